//! The rolling disk's closed forms against the Newton–Euler formulation of `newton_euler`:
//! the accelerations at a state, the steady circles, the upright disk's threshold (by its
//! linearisation and by simulation) and Euler's disk's steady motion and collapse.

use nalgebra::{Matrix3, Vector3};
use precess::contact::theory::{DiskState, EulerDisk, RollingDisk};

use precess_testkit::newton_euler::{Body, Rolling, Shape};

/// A thin disk and a thick one (a coin-shaped cylinder of height equal to its radius), so a
/// formula that holds only for A = C/2 fails.
fn disks() -> [RollingDisk; 2] {
    let (r, m, h) = (0.1, 0.7, 0.1);
    [
        RollingDisk::thin(r, m, 9.81),
        RollingDisk {
            radius: r,
            mass: m,
            transverse: m * (3.0 * r * r + h * h) / 12.0,
            axial: m * r * r / 2.0,
            gravity: 9.81,
        },
    ]
}

fn body(d: &RollingDisk) -> Body {
    Body {
        mass: d.mass,
        inertia: Matrix3::from_diagonal(&Vector3::new(d.transverse, d.transverse, d.axial)),
        shape: Shape::Rim { radius: d.radius },
        gravity: d.gravity,
    }
}

/// The body state of a disk state at yaw ψ: body axes (u, t, n) at the start of the spin.
fn rolling(s: &DiskState, yaw: f64) -> Rolling {
    let [t, u, n] = s.axes(yaw);
    Rolling {
        rot: Matrix3::from_columns(&[u, t, n]),
        omega: s.angular_velocity(yaw),
    }
}

fn states() -> Vec<DiskState> {
    let mut out = Vec::new();
    for &lean in &[0.0, 0.3, -0.7, 1.2] {
        for &(lean_rate, yaw_rate, spin) in &[(0.4, -1.3, 7.0), (-2.0, 3.1, -4.5), (0.0, 0.0, 12.0)]
        {
            out.push(DiskState {
                lean,
                lean_rate,
                yaw_rate,
                spin,
            });
        }
    }
    out
}

/// θ̈, ψ̈ and ω̇₃ give the space ω̇ of the disk: d/dt of ψ̇ cos θ u − θ̇ t + ω₃ n in the frame
/// turning at Ω_f = ψ̇ ẑ − θ̇ t. Compared with the Newton–Euler ω̇ at 18 states of two disks.
#[test]
fn accelerations_match_newton_euler() {
    for d in disks() {
        let b = body(&d);
        for s in states() {
            let yaw = 0.8;
            let acc = d.accelerations(&s);
            let [t, u, n] = s.axes(yaw);
            let (sn, cs) = s.lean.sin_cos();
            let (p, q, sf) = (s.yaw_rate * cs, -s.lean_rate, -s.yaw_rate * sn);
            let theory = u * (acc.yaw * cs - s.yaw_rate * s.lean_rate * sn + q * (s.spin - sf))
                + t * (-acc.lean + p * (sf - s.spin))
                + n * acc.spin;
            let ne = b.rolling_acceleration(&rolling(&s, yaw), &Vector3::zeros());
            let err = (theory - ne).norm() / ne.norm().max(1.0);
            assert!(
                err < 1e-12,
                "state {s:?}: closed form {theory} vs Newton–Euler {ne}, {err:e}"
            );
        }
    }
}

/// In a steady circle the disk's ω turns about the vertical at Ω: ω̇ = Ω ẑ × ω; the
/// Newton–Euler ω̇ at the closed form's state must be that. And the thin disk's special case
/// Ω² = g tan θ / (3R/2 − 5 r sin θ / 4).
#[test]
fn steady_circles_are_steady() {
    for d in disks() {
        let b = body(&d);
        for &(lean, path) in &[(0.2, 0.5), (0.6, 0.3), (-0.4, -0.8), (1.0, 0.15)] {
            let c = d.steady_circle(lean, path).expect("a steady circle");
            let s = DiskState {
                lean,
                lean_rate: 0.0,
                yaw_rate: c.precession,
                spin: c.spin,
            };
            let x = rolling(&s, 0.0);
            let ne = b.rolling_acceleration(&x, &Vector3::zeros());
            let steady = Vector3::z().cross(&x.omega) * c.precession;
            let err = (ne - steady).norm() / x.omega.norm().powi(2);
            assert!(err < 1e-13, "θ = {lean}, R = {path}: residual {err:e}");
            // The centre moves on its circle: speed Ω ρ.
            let v = b.rolling_velocity(&x).norm();
            assert!((v - (c.precession * c.centre_radius).abs()).abs() < 1e-14);
        }
    }
    let d = disks()[0];
    let (lean, path) = (0.5_f64, 0.4);
    let thin = d.gravity * lean.tan() / (1.5 * path - 1.25 * d.radius * lean.sin());
    let c = d.steady_circle(lean, path).expect("a steady circle");
    assert!((c.precession.powi(2) - thin).abs() < 1e-13 * thin);
    // No steady circle leans away from its centre at this radius.
    assert!(d.steady_circle(0.5, -0.4).is_none());
}

/// The thin disk's threshold is ω₀² = g/(3r); the general form's linearisation matches the
/// Newton–Euler θ̈ near upright (ψ̇ = C ω₀ θ / A), to O(θ²).
#[test]
fn upright_threshold_and_linearisation() {
    let d = disks()[0];
    let thin = (d.gravity / (3.0 * d.radius)).sqrt();
    assert!((d.critical_spin() - thin).abs() < 1e-14 * thin);
    for d in disks() {
        assert!(d.upright_frequency_squared(d.critical_spin()).abs() < 1e-12);
        let b = body(&d);
        for &w0 in &[0.5 * d.critical_spin(), 1.5 * d.critical_spin(), 20.0] {
            let eps = 1e-6;
            let s = DiskState {
                lean: eps,
                lean_rate: 0.0,
                yaw_rate: d.axial * w0 * eps / d.transverse,
                spin: w0,
            };
            let x = rolling(&s, 0.0);
            let ne = b.rolling_acceleration(&x, &Vector3::zeros());
            // ω̇·t = −θ̈ + p (s − ω₃), p = ψ̇ cos θ, s = −ψ̇ sin θ (the turning frame's term).
            let [t, _, _] = s.axes(0.0);
            let (p, sf) = (s.yaw_rate * eps.cos(), -s.yaw_rate * eps.sin());
            let lean_acc = -ne.dot(&t) + p * (sf - w0);
            let lin = -d.upright_frequency_squared(w0) * eps;
            assert!(
                (lean_acc - lin).abs() < 1e-9 * (lin.abs() + eps),
                "ω₀ = {w0}: Newton–Euler θ̈ {lean_acc:e} vs linear {lin:e}"
            );
        }
    }
}

/// The largest |lean| over `time` from upright with a lean rate of 1e-3 rad/s, rolling at
/// spin ω₀ (ψ̇ = C ω₀ θ / A holds at the start, so no steady turn is excited).
fn max_lean(d: &RollingDisk, w0: f64, time: f64) -> f64 {
    let b = body(d);
    let s = DiskState {
        lean: 0.0,
        lean_rate: 1e-3,
        yaw_rate: 0.0,
        spin: w0,
    };
    let mut x = rolling(&s, 0.0);
    let h = 1e-3;
    let mut worst = 0.0_f64;
    for _ in 0..(time / h) as usize {
        x = b.rolling_step(&x, h, &|_| Vector3::zeros());
        let n = x.rot.column(2);
        worst = worst.max(n.z.abs().asin());
        if worst > 1.0 {
            break;
        }
    }
    worst
}

/// By simulation: 10 % above the threshold the lean stays below 1 mrad for 4 s (the linear
/// amplitude θ̇₀/ν is 0.25 mrad for the thin disk); 10 % below it grows past 0.3 rad.
#[test]
fn upright_threshold_by_simulation() {
    for d in disks() {
        let wc = d.critical_spin();
        let above = max_lean(&d, 1.1 * wc, 4.0);
        let below = max_lean(&d, 0.9 * wc, 4.0);
        assert!(above < 1e-3, "1.1 ω_c: max lean {above}");
        assert!(below > 0.3, "0.9 ω_c: max lean {below}");
    }
}

/// Euler's disk's steady motion is the steady circle with ρ = 0; its energy
/// (3/2) m g r sin α is the sum ½ ωᵀIω + m g z_C evaluated on that state.
#[test]
fn euler_disk_steady_motion() {
    for d in disks() {
        let e = EulerDisk {
            disk: d,
            kappa: 1e-4,
        };
        for &alpha in &[0.05_f64, 0.3, 1.0] {
            let lean = std::f64::consts::FRAC_PI_2 - alpha;
            let c = d
                .steady_circle(lean, d.radius * lean.sin())
                .expect("steady");
            assert!(c.spin.abs() < 1e-12 && c.centre_radius.abs() < 1e-15);
            let omega = e.precession(alpha);
            assert!((c.precession - omega).abs() < 1e-12 * omega);
            let s = DiskState {
                lean,
                lean_rate: 0.0,
                yaw_rate: omega,
                spin: 0.0,
            };
            let x = rolling(&s, 0.0);
            let i = x.rot * body(&d).inertia * x.rot.transpose();
            let direct =
                0.5 * x.omega.dot(&(i * x.omega)) + d.mass * d.gravity * d.radius * alpha.sin();
            assert!((direct - e.energy(alpha)).abs() < 1e-14 * direct);
        }
    }
}

/// sin α of the disk's plane to the table: its axis n has n_z = −cos α.
fn sin_alpha(x: &Rolling) -> f64 {
    (1.0 - x.rot.column(2).z.powi(2)).sqrt()
}

/// Euler's disk under the couple −κ ω / sin³ α, simulated with the Newton–Euler model from
/// α = 0.1 rad in its steady motion: the time for sin α to fall to a third of its start
/// against the adiabatic law sin³ α = 2κ (t₀ − t)/A, t = (1 − 1/27) t₀. The law neglects
/// the spin ω₃ that the falling lean feeds (ω̇₃ ∝ ψ̇ θ̇ cos θ), which moves the centre off
/// its point: 0.8 % late here (5 % from α = 0.25), hence the 2 % bound.
#[test]
fn euler_disk_collapse_follows_the_adiabatic_law() {
    let d = disks()[0];
    let e = EulerDisk {
        disk: d,
        kappa: 1e-7,
    };
    let alpha0 = 0.1_f64;
    let lean = std::f64::consts::FRAC_PI_2 - alpha0;
    let s = DiskState {
        lean,
        lean_rate: 0.0,
        yaw_rate: e.precession(alpha0),
        spin: 0.0,
    };
    let b = body(&d);
    let mut x = rolling(&s, 0.0);
    let couple = |x: &Rolling| {
        let sin_alpha = sin_alpha(x);
        -x.omega * (e.kappa / sin_alpha.powi(3))
    };
    let target = alpha0.sin() / 3.0;
    let mut t = 0.0;
    let h = 2e-4;
    while sin_alpha(&x) > target && t < 100.0 {
        x = b.rolling_step(&x, h, &couple);
        t += h;
    }
    let theory = e.collapse_time(alpha0) * (1.0 - 1.0 / 27.0);
    let rel = (t - theory).abs() / theory;
    assert!(
        rel < 0.02,
        "time to sin α₀/3: simulated {t}, adiabatic {theory}, {rel:e}"
    );
}
