//! A spinning top derived by the macro, simulated, and measured against theory.
//!
//! The top is a brass disk on a steel stem, its tip on a fixed pivot. `#[derive(RigidBody)]`
//! computes its inertia about the pivot at compile time and `#[top(gravity = 9.81)]` emits its
//! Euler-angle equations of motion. Released at rest 20° from the vertical while spinning at
//! 150 rad/s, it nutates and precesses; the exact nutation of the symmetric heavy top (the
//! cubic in u = cos θ, Jacobi's sn) gives the amplitude, the period and the mean precession
//! rate to compare with. Three integrators run the same top: DOP853 on the generated angle
//! equations, DOP853 on the generated Eulerian form, and a splitting with the exact
//! free-body flow and gravity kicks, whose step the fast spin does not limit.
//!
//! Run with `cargo run --release --example heavy_top`.

use std::time::Instant;

use precess::exact::{ellip_k, sncndn};
use precess::ode::{AdaptiveConfig, Dop853};
use precess::prelude::*;
use precess::rigid::{BodyMomentum, ExactFreeFlow, Gravity, PotentialSplitting};

/// A disk (brass, 40 mm radius) 50 mm up a stem (steel, 80 mm), turning on the stem's tip.
#[derive(RigidBody)]
#[rigid(
    disk(mass = 0.2, radius = 0.04, at = [0.0, 0.0, 0.05]),
    cylinder(mass = 0.01, radius = 0.003, length = 0.08, at = [0.0, 0.0, 0.04]),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81)]
struct SpinningTop;

/// The exact nutation of a symmetric heavy top released at rest from θ0 spinning at ω3:
/// u = cos θ runs between the roots u1 < u2 = cos θ0 of
/// u̇² = (α − βu)(1 − u²) − (b − au)² as u(t) = u1 + (u2 − u1) sn²(Ωt + K | m), which
/// from the top turning point is u1 + (u2 − u1) (cn/dn)²(Ωt | m).
struct Nutation {
    theta_min: f64,
    theta_max: f64,
    period: f64,
    mean_precession: f64,
}

fn exact_nutation(
    i1: f64,
    i3: f64,
    mgl: f64,
    theta0: f64,
    w3: f64,
) -> Result<Nutation, Box<dyn std::error::Error>> {
    let u0 = theta0.cos();
    let (beta, a) = (2.0 * mgl / i1, i3 * w3 / i1);
    let b = a * u0; // p_φ = I3 ω3 cos θ0 at rest
    let alpha = beta * u0; // E = ½ I3 ω3² + M g l u0
    // f(u) = β u³ + c2 u² + c1 u + c0 has the root u0; divide it out: β u² + d1 u + d0.
    let (c2, c1) = (-alpha - a * a, -beta + 2.0 * a * b);
    let d1 = c2 + beta * u0;
    let d0 = c1 + u0 * d1;
    let disc = (d1 * d1 - 4.0 * beta * d0).sqrt();
    // The cancellation-free pair of quadratic roots.
    let q = -0.5 * (d1 + d1.signum() * disc);
    let (r1, r2) = (q / beta, d0 / q);
    let (u1, u3) = (r1.min(r2), r1.max(r2));
    let omega = (mgl * (u3 - u1) / (2.0 * i1)).sqrt();
    let m = (u0 - u1) / (u3 - u1);
    let k = ellip_k(1.0 - m)?;
    let period = 2.0 * k / omega;
    // Mean of φ̇ = (b − a u)/(1 − u²) over a period: the trapezoid rule converges
    // geometrically for a smooth periodic integrand.
    let n = 4000;
    let mut sum = 0.0;
    for j in 0..n {
        let t = period * j as f64 / n as f64;
        let (_, cn, dn) = sncndn(omega * t, 1.0 - m)?;
        let u = u1 + (u0 - u1) * (cn / dn).powi(2);
        sum += (b - a * u) / (1.0 - u * u);
    }
    Ok(Nutation {
        theta_min: theta0,
        theta_max: u1.acos(),
        period,
        mean_precession: sum / n as f64,
    })
}

/// The precession angle φ of the symmetry axis (ZXZ: axis = (sin φ sin θ, −cos φ sin θ,
/// cos θ)), followed continuously through ±π.
#[derive(Default)]
struct Unwrap {
    total: f64,
    last: f64,
}

impl Unwrap {
    fn phi(&mut self, axis: &Vector3<f64>) -> f64 {
        let phi = axis.x.atan2(-axis.y);
        let d = phi - self.last;
        self.total += d - (d / std::f64::consts::TAU).round() * std::f64::consts::TAU;
        self.last = phi;
        self.total
    }
}

/// What a simulation measured over `periods` nutation periods.
struct Measured {
    theta_max: f64,
    period: f64,
    mean_precession: f64,
    energy_drift: f64,
    steps: u64,
    seconds: f64,
}

fn measure(
    periods: f64,
    per_period: f64,
    nominal_period: f64,
    mut step_to: impl FnMut(f64) -> Result<(f64, f64, f64, u64), Box<dyn std::error::Error>>,
    e0: f64,
) -> Result<Measured, Box<dyn std::error::Error>> {
    // step_to(t) → (θ, φ, energy, steps). Sample densely enough to see the θ turning points.
    let started = Instant::now();
    let samples = (periods * per_period).round() as usize;
    let dt = periods * nominal_period / samples as f64;
    let mut theta_max = 0.0f64;
    let mut window = [f64::NAN; 3];
    let mut tops = Vec::new();
    let (mut phi_end, mut energy_end, mut steps) = (0.0, e0, 0);
    for j in 1..=samples {
        let t = j as f64 * dt;
        let (theta, phi, energy, n) = step_to(t)?;
        theta_max = theta_max.max(theta);
        window = [window[1], window[2], theta];
        // θ falls back to θ0 once a period: a local minimum of the samples, refined by the
        // parabola through the three around it.
        let [a, b, c] = window;
        if b < a && b <= c {
            let shift = 0.5 * (a - c) / (a - 2.0 * b + c);
            tops.push(t - dt + shift * dt);
        }
        (phi_end, energy_end, steps) = (phi, energy, n);
    }
    let period = match tops.as_slice() {
        [first, .., last] if tops.len() > 1 => (last - first) / (tops.len() - 1) as f64,
        _ => f64::NAN,
    };
    Ok(Measured {
        theta_max,
        period,
        mean_precession: phi_end / (samples as f64 * dt),
        energy_drift: (energy_end - e0).abs() / e0.abs(),
        steps,
        seconds: started.elapsed().as_secs_f64(),
    })
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let top = SpinningTop;
    let moments = top.principal().moments;
    let (i1, i3) = (moments[0], moments[2]);
    let mgl = top.mass() * 9.81 * top.center_of_mass().z;
    let (theta0, w3) = (20f64.to_radians(), 150.0);
    println!(
        "Spinning top: M = {:.3} kg, I1 = {i1:.4e}, I3 = {i3:.4e} kg m² about the tip, M g l = {mgl:.4e} N m",
        top.mass()
    );
    println!(
        "Released at rest from θ0 = 20° spinning at ω3 = {w3} rad/s (sleeping threshold {:.1} rad/s)\n",
        (4.0 * i1 * mgl).sqrt() / i3
    );
    let exact = exact_nutation(i1, i3, mgl, theta0, w3)?;
    let periods = 10.0;

    // 1. DOP853 on the generated angle equations.
    let chart = TopChart::declared(&top);
    let y0 = [0.0, theta0, 0.0, 0.0, 0.0, w3];
    let tol = AdaptiveConfig::with_tol(1e-11, 1e-11);
    let mut ode = Dop853::new(&chart, 0.0, y0, tol)?;
    let e0 = top.energy(&[0.0, theta0, 0.0], &[0.0, 0.0, w3]);
    let t_end = periods * exact.period;
    // Steps chosen by the controller alone; samples come from the dense output.
    let angles = measure(
        periods,
        400.0,
        exact.period,
        |t| {
            while ode.t() < t {
                ode.step(t_end)?;
            }
            let y = ode.dense_at(t)?;
            Ok((
                y[1],
                y[0],
                top.energy(&[y[0], y[1], y[2]], &[y[3], y[4], y[5]]),
                ode.stats().steps,
            ))
        },
        e0,
    )?;

    // 2. DOP853 on the generated Eulerian form (quaternion and ω).
    let r0 = top.rotation_in(AngleSequence::Zxz, &[0.0, theta0, 0.0]);
    let q0 = UnitQuaternion::from_matrix(&r0);
    let eul = EulerianTop(&top);
    let y0 = EulerianTop::<SpinningTop>::state(&q0, &Vector3::new(0.0, 0.0, w3));
    let mut ode = Dop853::new(&eul, 0.0, y0, tol)?;
    let inertia = top.inertia();
    let weight_lever = top.center_of_mass() * top.mass() * 9.81;
    let energy = |y: &[f64; 7]| {
        let q = EulerianTop::<SpinningTop>::attitude(y)?;
        let w = Vector3::new(y[4], y[5], y[6]);
        Ok::<f64, TopError>(0.5 * w.dot(&(inertia * w)) + (q * weight_lever).z)
    };
    let mut unwrap = Unwrap::default();
    let eulerian = measure(
        periods,
        400.0,
        exact.period,
        |t| {
            while ode.t() < t {
                ode.step(t_end)?;
            }
            let y = ode.dense_at(t)?;
            let axis = EulerianTop::<SpinningTop>::attitude(&y)? * Vector3::z();
            Ok((
                axis.z.acos(),
                unwrap.phi(&axis),
                energy(&y)?,
                ode.stats().steps,
            ))
        },
        energy(&y0)?,
    )?;

    // 3. Splitting: exact free-body flow plus gravity kicks, 100 steps per nutation period
    //    (each 0.3 spin revolutions long), sampled at every step.
    let split = PotentialSplitting {
        free: ExactFreeFlow::new([i1, moments[1], i3])?,
        potential: Gravity {
            weight: top.mass() * 9.81,
            c: top.center_of_mass(),
        },
    };
    let mut y = BodyMomentum {
        q: q0,
        m: Vector3::new(0.0, 0.0, i3 * w3),
    };
    let h = exact.period / 100.0;
    let (mut t_now, mut n_steps) = (0.0, 0u64);
    let mut unwrap = Unwrap::default();
    let split_e0 = split.energy(&y);
    let splitting = measure(
        periods,
        100.0,
        exact.period,
        |t| {
            while t_now < t - 1e-12 {
                split.step(&mut y, h)?;
                t_now += h;
                n_steps += 1;
            }
            let axis = y.q * Vector3::z();
            Ok((axis.z.acos(), unwrap.phi(&axis), split.energy(&y), n_steps))
        },
        split_e0,
    )?;

    println!(
        "{:<34} {:>14} {:>14} {:>16} {:>11} {:>7} {:>9}",
        "", "amplitude/rad", "period/s", "precession/rad/s", "energy err", "steps", "time/ms"
    );
    println!(
        "{:<34} {:>14.6e} {:>14.8} {:>16.8} {:>11} {:>7} {:>9}",
        "theory (exact nutation)",
        exact.theta_max - exact.theta_min,
        exact.period,
        exact.mean_precession,
        "",
        "",
        ""
    );
    println!(
        "{:<34} {:>14} {:>14} {:>16.8} {:>11} {:>7} {:>9}",
        "theory (fast-top Mgl/(I3 ω3))",
        "",
        "",
        mgl / (i3 * w3),
        "",
        "",
        ""
    );
    for (name, m) in [
        ("DOP853, generated angle form", &angles),
        ("DOP853, generated Eulerian form", &eulerian),
        ("splitting, exact free flow", &splitting),
    ] {
        println!(
            "{name:<34} {:>14.6e} {:>14.8} {:>16.8} {:>11.1e} {:>7} {:>9.3}",
            m.theta_max - theta0,
            m.period,
            m.mean_precession,
            m.energy_drift,
            m.steps,
            1e3 * m.seconds
        );
    }
    let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
    println!(
        "\nAngle form against theory: amplitude {:.1e}, period {:.1e}, precession {:.1e} (relative)",
        rel(angles.theta_max - theta0, exact.theta_max - exact.theta_min),
        rel(angles.period, exact.period),
        rel(angles.mean_precession, exact.mean_precession)
    );
    Ok(())
}
