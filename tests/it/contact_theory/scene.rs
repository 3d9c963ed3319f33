//! The derived contact scene (`ContactModel`) against the closed forms of `contact::theory`:
//! the rolling disk's accelerations and steady circles, Routh's three integrals and the
//! contact point at rest over a long run, and the tippe top's inverted state.

use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};
use precess::contact::theory::{DiskState, RollingDisk, SphereBody, TippeTop};
use precess::contact::{
    ContactDynamics, ContactLaw, ContactModel, ContactRun, ContactScene, Friction, Phase,
    STATE_LEN, Surface, attitude_of,
};
use precess::ode::AdaptiveConfig;
use precess::sym::{Arena, ExprId};

const ROLLING: ContactLaw = ContactLaw::Rolling {
    rolling_resistance: None,
    spin_resistance: None,
};

/// A model of a body with diagonal moments `i` about its centre of mass at the origin.
fn model(
    i: [f64; 3],
    mass: f64,
    surface: impl FnOnce(&mut Arena, &mut Vec<(&'static str, f64)>) -> Surface,
    law: impl FnOnce(&mut Arena, &mut Vec<(&'static str, f64)>) -> ContactLaw,
) -> ContactModel {
    let mut a = Arena::new();
    let mut values = vec![
        ("m", mass),
        ("g", 9.81),
        ("i1", i[0]),
        ("i2", i[1]),
        ("i3", i[2]),
    ];
    let z = a.zero();
    let p: Vec<ExprId> = ["m", "g", "i1", "i2", "i3"]
        .iter()
        .map(|n| a.parameter(n))
        .collect();
    let surface = surface(&mut a, &mut values);
    let law = law(&mut a, &mut values);
    let scene = ContactScene {
        mass: p[0],
        center: [z; 3],
        inertia: [[p[2], z, z], [z, p[3], z], [z, z, p[4]]],
        surface,
        law,
        gravity: p[1],
    };
    let d = scene.derive(&mut a).expect("derives");
    ContactModel::new(&mut a, &d, &values).expect("binds")
}

fn disk_model(d: &RollingDisk) -> ContactModel {
    let r = d.radius;
    model(
        [d.transverse, d.transverse, d.axial],
        d.mass,
        |a, v| {
            v.push(("r", r));
            Surface::DiskRim {
                center: [a.zero(); 3],
                radius: a.parameter("r"),
            }
        },
        |_, _| ROLLING,
    )
}

/// The model's state at a theory disk state, yaw 0: body axes (u, t, n).
fn disk_state(m: &ContactModel, s: &DiskState) -> [f64; STATE_LEN] {
    let [t, u, n] = s.axes(0.0);
    let rot = Rotation3::from_matrix_unchecked(Matrix3::from_columns(&[u, t, n]));
    let q = UnitQuaternion::from_rotation_matrix(&rot);
    m.rolling_state([0.0, 0.0], &q, &(q.inverse() * s.angular_velocity(0.0)))
        .unwrap()
}

/// The derived rolling disk's ω̇ at 12 states against the closed-form θ̈, ψ̈, ω̇₃ (turned into
/// the space ω̇ in the frame turning at ψ̇ ẑ − θ̇ t), ≤ 1e-12 relative.
#[test]
fn derived_disk_matches_the_closed_form_accelerations() {
    let d = RollingDisk {
        radius: 0.1,
        mass: 0.7,
        transverse: 0.7 * (3.0 * 0.01 + 0.01) / 12.0,
        axial: 0.7 * 0.01 / 2.0,
        gravity: 9.81,
    };
    let m = disk_model(&d);
    for &lean in &[0.2, -0.6, 1.1] {
        for &(lean_rate, yaw_rate, spin) in &[
            (0.4, -1.3, 7.0),
            (-2.0, 3.1, -4.5),
            (0.0, 0.5, 12.0),
            (1.0, 0.0, 0.0),
        ] {
            let s = DiskState {
                lean,
                lean_rate,
                yaw_rate,
                spin,
            };
            let y = disk_state(&m, &s);
            let dy = m.accelerations(Phase::Rolling, 0.0, &y).expect("rhs");
            let derived = attitude_of(&y) * Vector3::new(dy[8], dy[9], dy[10]);
            let acc = d.accelerations(&s);
            let [t, u, n] = s.axes(0.0);
            let (sn, cs) = lean.sin_cos();
            let (p, q, sf) = (yaw_rate * cs, -lean_rate, -yaw_rate * sn);
            let closed = u * (acc.yaw * cs - yaw_rate * lean_rate * sn + q * (spin - sf))
                + t * (-acc.lean + p * (sf - spin))
                + n * acc.spin;
            let err = (derived - closed).norm() / closed.norm().max(1.0);
            assert!(
                err < 1e-12,
                "{s:?}: derived {derived} vs closed form {closed}, {err:e}"
            );
        }
    }
}

/// The derived disk started on a theory steady circle keeps its lean and its centre's circle
/// to 1e-11 over 20 s.
#[test]
fn derived_disk_keeps_a_steady_circle() {
    let d = RollingDisk::thin(0.1, 0.5, 9.81);
    let m = disk_model(&d);
    let c = d.steady_circle(0.3, 0.5).expect("steady");
    let s = DiskState {
        lean: 0.3,
        lean_rate: 0.0,
        yaw_rate: c.precession,
        spin: c.spin,
    };
    let mut run = ContactRun::new(
        &m,
        Phase::Rolling,
        0.0,
        disk_state(&m, &s),
        AdaptiveConfig::with_tol(1e-12, 1e-12),
    )
    .expect("run");
    let centre = Vector3::new(0.0, c.centre_radius, 0.0);
    for k in 1..=200 {
        run.advance_to(0.1 * k as f64).expect("advance");
        let y = run.y();
        let n = attitude_of(y) * Vector3::z();
        assert!((-n.z.asin() - 0.3).abs() < 1e-11, "lean at {}", run.t());
        let rho = (Vector3::new(y[0], y[1], 0.0) - centre).norm();
        assert!(
            (rho - c.centre_radius).abs() < 1e-11,
            "ρ at {}: {rho}",
            run.t()
        );
    }
}

/// Routh's sphere rolled 200 s by the derived model: E, λ and Q_R (closed forms evaluated on
/// the run's states) within 1e-12 relative; the contact point at rest to 1e-12 m/s.
#[test]
fn derived_routh_sphere_keeps_its_integrals() {
    let b = SphereBody {
        radius: 0.1,
        centre: Vector3::new(0.0, 0.0, 0.03),
        mass: 1.0,
        inertia: Matrix3::from_diagonal(&Vector3::new(0.004, 0.004, 0.0055)),
        gravity: 9.81,
    };
    let m = model(
        [0.004, 0.004, 0.0055],
        1.0,
        |a, v| {
            v.push(("rho", 0.1));
            v.push(("d", 0.03));
            let z = a.zero();
            Surface::Sphere {
                center: [z, z, a.parameter("d")],
                radius: a.parameter("rho"),
            }
        },
        |_, _| ROLLING,
    );
    let q0 = UnitQuaternion::from_euler_angles(0.4, -0.2, 0.3);
    let y0 = m
        .rolling_state([0.0, 0.0], &q0, &Vector3::new(1.0, -0.5, 15.0))
        .unwrap();
    let integrals = |y: &[f64; STATE_LEN]| {
        let q = attitude_of(y);
        let w = Vector3::new(y[8], y[9], y[10]);
        let v = b.rolling_velocity(&q, &w);
        [b.energy(&q, &w, &v), b.jellett(&q, &w), b.routh(&q, &w)]
    };
    let start = integrals(&y0);
    let times: Vec<f64> = (1..=2000).map(|k| 0.1 * k as f64).collect();
    let config = AdaptiveConfig::with_tol(1e-13, 1e-13);
    let states =
        precess_testkit::contact::states(&m, Phase::Rolling, y0, config, &times).expect("runs");
    let mut worst = [0.0_f64; 3];
    let mut slip = 0.0_f64;
    for y in &states {
        let now = integrals(y);
        for j in 0..3 {
            worst[j] = worst[j].max((now[j] - start[j]).abs() / start[j].abs());
        }
        slip = slip.max(m.contact(y).velocity.norm());
    }
    assert!(
        worst.iter().all(|&w| w < 1e-12),
        "drifts over 200 s: {worst:?}"
    );
    assert!(slip < 1e-12, "contact point speed {slip:e}");
}

/// The derived tippe top (viscous sliding) inverts; λ within 1e-12; the final spin and energy
/// those Jellett's closed form gives, within 1e-5 after 20 s (the nutation left).
#[test]
fn derived_tippe_top_inverts_to_jelletts_state() {
    let (mm, r) = (0.02, 0.02);
    let t = TippeTop {
        radius: r,
        alpha: 0.3,
        mass: mm,
        i1: 0.35 * mm * r * r,
        i3: 0.4 * mm * r * r,
        gravity: 9.81,
    };
    let m = model(
        [t.i1, t.i1, t.i3],
        mm,
        |a, v| {
            v.push(("rho", r));
            v.push(("d", t.alpha * r));
            let z = a.zero();
            Surface::Sphere {
                center: [z, z, a.parameter("d")],
                radius: a.parameter("rho"),
            }
        },
        |a, v| {
            v.push(("c", 5.0 * mm));
            ContactLaw::Sliding(Friction::Viscous(a.parameter("c")))
        },
    );
    let q = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), 0.1);
    let mut y0 = [0.0; STATE_LEN];
    y0[4..8].copy_from_slice(&[q.w, q.i, q.j, q.k]);
    y0[10] = 140.0;
    let lambda = m.jellett(&y0);
    let mut run = ContactRun::new(
        &m,
        Phase::Sliding,
        0.0,
        y0,
        AdaptiveConfig::with_tol(1e-12, 1e-12),
    )
    .expect("run");
    let mut worst = 0.0_f64;
    for k in 1..=400 {
        run.advance_to(0.05 * k as f64).expect("advance");
        worst = worst.max((m.jellett(run.y()) - lambda).abs() / lambda);
    }
    let y = *run.y();
    let spin = (attitude_of(&y) * Vector3::new(y[8], y[9], y[10])).z;
    let e = m.energy(Phase::Sliding, &y);
    assert!(worst < 1e-12, "λ drifts {worst:e}");
    assert!((attitude_of(&y) * Vector3::z()).z < -0.9999, "not inverted");
    assert!((spin - t.inverted_spin(lambda)).abs() < 1e-5 * spin);
    assert!((e - t.inverted_energy(lambda)).abs() < 1e-5 * e);
}

/// Kane & Levinson's rattleback, derived and rolled by `ContactRun`, against the Newton–Euler
/// formulation of `newton_euler` (the ellipsoid's support map and its derivative written out
/// there): ω in space agrees to 1e-7 at 1 and 2 s (RK4 at h = 1.25e-4 limits it; the
/// rattling amplifies every error, to 1e-6 by 3 s), and so does the first time the heading
/// of the long axis turns back (the spin reversal the example reports).
#[test]
fn derived_rattleback_matches_newton_euler() {
    use precess_testkit::newton_euler::{Body, Rolling, Shape};
    let inertia = Matrix3::new(2e-4, -2e-5, 0.0, -2e-5, 1.6e-3, 0.0, 0.0, 0.0, 1.7e-3);
    let mut a = Arena::new();
    let z = a.zero();
    let names = ["M", "a", "b", "c", "h", "A", "B", "C", "D", "g"];
    let values = [
        1.0, 0.2, 0.03, 0.02, 0.01, 2e-4, 1.6e-3, 1.7e-3, -2e-5, 9.81,
    ];
    let p: Vec<ExprId> = names.iter().map(|n| a.parameter(n)).collect();
    let scene = ContactScene {
        mass: p[0],
        center: [z; 3],
        inertia: [[p[5], p[8], z], [p[8], p[6], z], [z, z, p[7]]],
        surface: Surface::Ellipsoid {
            center: [z, z, p[4]],
            semi_axes: [p[1], p[2], p[3]],
        },
        law: ROLLING,
        gravity: p[9],
    };
    let d = scene.derive(&mut a).expect("derives");
    let pairs: Vec<(&str, f64)> = names.iter().copied().zip(values).collect();
    let m = ContactModel::new(&mut a, &d, &pairs).expect("binds");
    let tilt = 0.5_f64.to_radians();
    let q = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), tilt)
        * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), tilt);
    let w0 = Vector3::new(0.0, 0.0, -5.0);

    // The heading rate of the long axis, x = R e₁, ẋ = ω × x.
    let heading = |rot: &Matrix3<f64>, w: &Vector3<f64>| {
        let x = rot * Vector3::x();
        let xd = w.cross(&x);
        (x.x * xd.y - x.y * xd.x) / (x.x * x.x + x.y * x.y)
    };
    let h = 1.25e-4;
    let first_turn = |samples: &[(f64, f64)]| {
        samples
            .windows(2)
            .find(|w| w[0].0 > 1.0 && w[0].1 * w[1].1 < 0.0)
            .map(|w| w[0].0 - w[0].1 * (w[1].0 - w[0].0) / (w[1].1 - w[0].1))
    };

    let ne = Body {
        mass: 1.0,
        inertia,
        shape: Shape::Ellipsoid {
            centre: Vector3::new(0.0, 0.0, 0.01),
            semi: Vector3::new(0.2, 0.03, 0.02),
        },
        gravity: 9.81,
    };
    let rot0 = *q.to_rotation_matrix().matrix();
    let mut x = Rolling {
        rot: rot0,
        omega: rot0 * w0,
    };
    let steps = (4.0 / h) as usize;
    let times: Vec<f64> = (1..=steps).map(|k| k as f64 * h).collect();
    let y0 = m.rolling_state([0.0, 0.0], &q, &w0).unwrap();
    let config = AdaptiveConfig::with_tol(1e-13, 1e-13);
    let states =
        precess_testkit::contact::states(&m, Phase::Rolling, y0, config, &times).expect("runs");
    let (mut derived, mut reference) = (Vec::new(), Vec::new());
    for (k, (&t, y)) in (1..).zip(times.iter().zip(&states)) {
        x = ne.rolling_step(&x, h, &|_| Vector3::zeros());
        let qy = attitude_of(y);
        let w = qy * Vector3::new(y[8], y[9], y[10]);
        derived.push((t, heading(qy.to_rotation_matrix().matrix(), &w)));
        reference.push((t, heading(&x.rot, &x.omega)));
        if k % (1.0 / h) as usize == 0 && t <= 2.0 {
            let gap = (w - x.omega).norm() / x.omega.norm();
            assert!(
                gap < 1e-7,
                "ω at t = {t}: derived {w} vs Newton–Euler {}, {gap:e}",
                x.omega
            );
        }
    }
    let (td, tr) = (
        first_turn(&derived).expect("derived turns"),
        first_turn(&reference).expect("reference turns"),
    );
    eprintln!("first reversal: derived {td} s, Newton–Euler {tr} s");
    assert!(
        (td - tr).abs() < 1e-6,
        "first reversal: derived {td} s, Newton–Euler {tr} s"
    );
    assert!((2.5..3.2).contains(&td), "first reversal at {td} s");
}
