//! Tops derived by `#[top(...)]`: the generated angle form against the generated Eulerian
//! form, against the run-time derivation, and against the published heavy-top values.

use crate::common;

use approx::assert_relative_eq;
use common::rng::Rng;
use common::tops::ReferenceTop;
use precess::prelude::*;
use precess_core::ode::{AdaptiveConfig, Dop853};

/// An asymmetric top with its centre of mass off the axis and parameters from fields, under
/// every declared torque.
#[derive(RigidBody)]
#[rigid(
    cuboid(mass = m, size = [a, b, c], at = [0.01, -0.02, h]),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(
    gravity = 9.81,
    body_torque = [0.01, 0.0, tau],
    space_torque = [0.0, 0.02, 0.0],
    damping = k,
    torque = push,
    angles = zxz,
)]
struct Brick {
    m: f64,
    a: f64,
    b: f64,
    c: f64,
    h: f64,
    tau: f64,
    k: f64,
}

/// A user torque: a small spin-up about the body z axis that fades with time.
fn push(_: &Brick, t: f64, _r: &Matrix3<f64>, _w: &Vector3<f64>) -> Vector3<f64> {
    Vector3::new(0.0, 0.0, 0.05 * (-t).exp())
}

fn brick() -> Brick {
    Brick {
        m: 0.7,
        a: 0.05,
        b: 0.08,
        c: 0.12,
        h: 0.09,
        tau: 0.003,
        k: 0.001,
    }
}

/// ω̇ = B q̈ + Ḃ q̇ from the generated angle form. Ḃ q̇ is the derivative of B along q̇,
/// taken from the generated B by central differences with Richardson extrapolation
/// (truncation O(h⁴) ≈ 1e-13 at h = 1e-3, rounding ≈ 1e-13).
fn omega_dot_from_angles<T: TopDynamics>(
    top: &T,
    t: f64,
    q: [f64; 3],
    qd: [f64; 3],
) -> Vector3<f64> {
    let qdd = top.accelerations_unchecked(t, &q, &qd);
    let b = |h: f64| {
        let q: [f64; 3] = std::array::from_fn(|i| q[i] + h * qd[i]);
        top.rate_matrix_in(T::SEQUENCE, &q)
    };
    let central = |h: f64| (b(h) - b(-h)) / (2.0 * h);
    let h = 1e-3;
    let bdot = (central(h / 2.0) * 4.0 - central(h)) / 3.0;
    b(0.0) * Vector3::from(qdd) + bdot * Vector3::from(qd)
}

#[test]
fn generated_angle_and_eulerian_forms_agree() {
    let mut rng = Rng::new(5);
    let brick = brick();
    let reference = ReferenceTop;
    let mut worst: f64 = 0.0;
    for _ in 0..10_000 {
        let q = [
            rng.uniform(-3.0, 3.0),
            rng.uniform(0.3, 2.8),
            rng.uniform(-3.0, 3.0),
        ];
        let qd = [
            rng.uniform(-3.0, 3.0),
            rng.uniform(-3.0, 3.0),
            rng.uniform(-10.0, 10.0),
        ];
        let t = rng.uniform(0.0, 2.0);
        for (lag, eul, w) in [
            {
                let r = brick.rotation_in(AngleSequence::Zxz, &q);
                let w = brick.omega_from_rates(&q, &qd);
                let att = precess_testkit::rotations::quaternion_of(&r);
                (
                    omega_dot_from_angles(&brick, t, q, qd),
                    brick.eulerian_rhs(t, &att, &w),
                    w,
                )
            },
            {
                let r = reference.rotation_in(AngleSequence::Zxz, &q);
                let w = reference.omega_from_rates(&q, &qd);
                let att = precess_testkit::rotations::quaternion_of(&r);
                (
                    omega_dot_from_angles(&reference, t, q, qd),
                    reference.eulerian_rhs(t, &att, &w),
                    w,
                )
            },
        ] {
            let scale = 1.0 + w.norm_squared() + eul.norm();
            worst = worst.max((lag - eul).norm() / scale);
        }
    }
    eprintln!("generated angle vs Eulerian: worst relative difference {worst:.1e}");
    assert!(
        worst < 1e-10,
        "generated angle and Eulerian forms differ by {worst:e}"
    );
}

#[test]
fn literal_top_reproduces_steady_precession_and_nutation() {
    let top = ReferenceTop;
    let theta = std::f64::consts::FRAC_PI_3;
    for omega_p in [0.204168476687, 9.795831523313] {
        let q = [0.0, theta, 0.0];
        let qd = [omega_p, 0.0, 10.0 - omega_p * theta.cos()];
        assert!(top.accelerations_unchecked(0.0, &q, &qd)[1].abs() < 1e-10);
    }
    // Fast top released at rest, ω3 = 20: nutation amplitude 1.7580e-2 rad.
    let chart = TopChart::declared(&top);
    let mut ode = Dop853::new(
        &chart,
        0.0,
        [0.0, theta, 0.0, 0.0, 0.0, 20.0],
        AdaptiveConfig::with_tol(1e-12, 1e-12),
    )
    .unwrap();
    let mut max_theta: f64 = 0.0;
    for k in 1..=800 {
        ode.advance_to(k as f64 * 0.634549 / 400.0).unwrap();
        max_theta = max_theta.max(ode.y()[1]);
    }
    assert_relative_eq!(max_theta - theta, 1.7580e-2, max_relative = 2e-4);
    // Conserved: p_φ and p_ψ for the symmetric top, not p_θ.
    let m = top.conserved_momenta(&[0.1, 0.7, 0.2], &[0.3, 0.1, 5.0]);
    assert!(m[0].is_some() && m[1].is_none() && m[2].is_some());
    // p_ψ = I3 ω3 in closed form.
    assert_relative_eq!(
        m[2].unwrap(),
        0.5 * (5.0 + 0.3 * 0.7f64.cos()),
        max_relative = 1e-14
    );
}

#[test]
fn generated_jacobian_matches_differences() {
    let brick = brick();
    let (q, qd) = ([0.3, 1.1, -0.4], [0.5, -0.7, 6.0]);
    let jac = brick.angle_jacobian(0.5, &q, &qd);
    let h = 1e-6;
    for j in 0..6 {
        let mut s: [f64; 6] = [q[0], q[1], q[2], qd[0], qd[1], qd[2]];
        s[j] += h;
        let ap = brick.accelerations_unchecked_in(AngleSequence::Zxz, 0.5, &s);
        s[j] -= 2.0 * h;
        let am = brick.accelerations_unchecked_in(AngleSequence::Zxz, 0.5, &s);
        for i in 0..3 {
            let fd = (ap[i] - am[i]) / (2.0 * h);
            assert!(
                (jac[i][j] - fd).abs() < 1e-6 * (1.0 + fd.abs()),
                "∂q̈{i}/∂x{j}: {} vs {fd}",
                jac[i][j]
            );
        }
    }
}

#[test]
fn rates_and_omega_round_trip_and_gimbal_lock_is_an_error() {
    let top = ReferenceTop;
    let q = [0.2, 0.9, -1.0];
    let w = top.omega_from_rates(&q, &[0.3, -0.2, 4.0]);
    let back = top.rates_from_omega(&q, &w).unwrap();
    assert_relative_eq!(back[0], 0.3, max_relative = 1e-14);
    assert_relative_eq!(back[2], 4.0, max_relative = 1e-14);
    let err = top.rates_from_omega(&[0.0, 0.0, 0.0], &w).unwrap_err();
    assert!(matches!(
        err,
        TopError::Chart(ChartError::SingularChart {
            sequence: AngleSequence::Zxz,
            ..
        })
    ));
    assert!(matches!(
        top.rates_from_omega(&[f64::NAN, 0.0, 0.0], &w),
        Err(TopError::Chart(ChartError::NonFinite { .. }))
    ));
}

#[test]
fn derived_top_runs_through_the_vertical_with_both_charts() {
    let top = ReferenceTop;
    let charts = TopChart::both(&top);
    let r0 = top.rotation_in(AngleSequence::Zxz, &[0.0, 1.4, std::f64::consts::FRAC_PI_2]);
    let w0 = Vector3::new(0.0, 2.5, 0.0);
    let mut sim = ChartedTop::new(
        [&charts[0], &charts[1]],
        0.0,
        &r0,
        &w0,
        ChartConfig::default(),
    )
    .unwrap();
    let e0 = sim.energy();
    sim.advance_to(6.0).unwrap();
    assert!(sim.switches() >= 2);
    assert!((sim.energy() - e0).abs() < 1e-8);
}

/// The generated equations of the reference top against the exact nutation (published
/// closed form): released at rest from θ0 = 60° with ω3 = 20, u = cos θ follows
/// u1 + (u2 − u1) (cn/dn)²(Ωt | m) and φ̇ = (b − a u)/(1 − u²), at every sample.
#[test]
fn literal_top_follows_the_exact_nutation() {
    use precess_core::exact::sncndn;
    let top = ReferenceTop;
    let (i1, i3, mgl, theta0, w3): (f64, f64, f64, f64, f64) =
        (1.0, 0.5, 1.0, std::f64::consts::FRAC_PI_3, 20.0);
    let u2 = theta0.cos();
    let (beta, a) = (2.0 * mgl / i1, i3 * w3 / i1);
    let b = a * u2;
    // f(u) = β u³ − (β u2 + a²) u² + (2ab − β) u + (β u2 − b²) = (u − u2)(β u² + d1 u + d0).
    let d1 = -(beta * u2 + a * a) + beta * u2;
    let d0 = (2.0 * a * b - beta) + u2 * d1;
    let disc = (d1 * d1 - 4.0 * beta * d0).sqrt();
    let q = -0.5 * (d1 + d1.signum() * disc);
    let (u1, u3) = ((q / beta).min(d0 / q), (q / beta).max(d0 / q));
    let omega = (mgl * (u3 - u1) / (2.0 * i1)).sqrt();
    let mc = 1.0 - (u2 - u1) / (u3 - u1);
    let chart = TopChart::declared(&top);
    let mut ode = Dop853::new(
        &chart,
        0.0,
        [0.0, theta0, 0.0, 0.0, 0.0, w3],
        AdaptiveConfig::with_tol(1e-13, 1e-13),
    )
    .unwrap();
    let mut worst: f64 = 0.0;
    for k in 1..=300 {
        let t = 0.01 * k as f64;
        ode.advance_to(t).unwrap();
        let (_, cn, dn) = sncndn(omega * t, mc).unwrap();
        let u = u1 + (u2 - u1) * (cn / dn).powi(2);
        let y = ode.y();
        worst = worst
            .max((y[1].cos() - u).abs())
            .max(((b - a * u) / (1.0 - u * u) - y[3]).abs());
    }
    assert!(
        worst < 1e-10,
        "generated top departs from the exact nutation by {worst:e}"
    );
}

/// Any stepper runs a derived top: RK4 (fixed step) and DOPRI5 land where DOP853 does.
#[test]
fn any_stepper_runs_the_generated_top() {
    use precess_core::ode::{Dopri5, FixedStepConfig, Rk4};
    let top = brick();
    let chart = TopChart::declared(&top);
    let y0 = [0.1, 0.8, -0.3, 0.4, -0.2, 30.0];
    let mut reference =
        Dop853::new(&chart, 0.0, y0, AdaptiveConfig::with_tol(1e-12, 1e-12)).unwrap();
    reference.advance_to(1.0).unwrap();
    let mut dopri = Dopri5::new(&chart, 0.0, y0, AdaptiveConfig::with_tol(1e-10, 1e-10)).unwrap();
    dopri.advance_to(1.0).unwrap();
    let mut rk4 = Rk4::new(&chart, 0.0, y0, FixedStepConfig::with_step(1e-4)).unwrap();
    rk4.advance_to(1.0).unwrap();
    for k in 0..6 {
        let r = reference.y()[k];
        assert!(
            (dopri.y()[k] - r).abs() < 1e-7 * (1.0 + r.abs()),
            "DOPRI5 component {k}"
        );
        assert!(
            (rk4.y()[k] - r).abs() < 1e-7 * (1.0 + r.abs()),
            "RK4 component {k}"
        );
    }
}

/// A fast top whose principal axes are not the description axes (products of inertia),
/// with its centre off the axis.
#[derive(RigidBody)]
#[rigid(
    body(
        mass = 1.0,
        at = [0.02, 0.0, 0.3],
        inertia = [[0.05, 0.004, 0.0], [0.004, 0.045, 0.003], [0.0, 0.003, 0.02]],
    ),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81)]
struct Skewed;

/// The exact-free-flow splitting of a derived top converges at order 2 to the generated
/// Eulerian form integrated tightly, through the principal-frame conversion.
#[test]
fn fast_top_splitting_converges_to_the_eulerian_form() {
    use precess_core::top::FastTop;
    let top = Skewed;
    let fast = FastTop::new(&top, 9.81).unwrap();
    assert!(
        fast.principal_to_description.angle() > 1e-3,
        "the test needs a tilted principal frame"
    );
    let q0 = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), 0.4);
    let w0 = Vector3::new(0.3, -0.2, 80.0);
    let eul = EulerianTop(&top);
    let mut ode = Dop853::new(
        &eul,
        0.0,
        EulerianTop::<Skewed>::state(&q0, &w0),
        AdaptiveConfig::with_tol(1e-13, 1e-13),
    )
    .unwrap();
    let t_end = 0.5;
    ode.advance_to(t_end).unwrap();
    let truth = EulerianTop::<Skewed>::attitude(ode.y()).unwrap();
    let errors: Vec<f64> = [2e-3, 1e-3]
        .iter()
        .map(|&h| {
            let mut y = fast.to_principal(&q0, &w0);
            let n = (t_end / h).round() as u64;
            fast.splitting.run(&mut y, h, n).unwrap();
            let (q, _) = fast.to_description(&y);
            q.angle_to(&truth)
        })
        .collect();
    let order = (errors[0] / errors[1]).log2();
    eprintln!(
        "fast-top splitting: errors {:.2e} and {:.2e}, observed order {order:.2}",
        errors[0], errors[1]
    );
    assert!(errors[1] < 1e-4, "error {:e} at h = 1e-3", errors[1]);
    assert!(
        (order - 2.0).abs() < 0.2,
        "observed order {order} (errors {errors:?})"
    );
    // The round trip through the principal frame is exact.
    let (q, w) = fast.to_description(&fast.to_principal(&q0, &w0));
    assert!(q.angle_to(&q0) < 1e-15 && (w - w0).norm() < 1e-12);
}

/// A user's struct may be called `Top`, the name the docs use: the trait the derive
/// implements is `TopDynamics`, so the prelude's glob import keeps its methods in scope.
mod user_struct_named_top {
    use approx::assert_relative_eq;
    use precess::prelude::*;

    #[derive(RigidBody)]
    #[rigid(
        body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
        pivot = [0.0, 0.0, 0.0],
    )]
    #[top(gravity = 1.0)]
    struct Top;

    #[test]
    fn methods_resolve_through_the_prelude() {
        // Lying on its side at rest, θ̈ = M g l sin θ / I1 = 1 (ZXZ: q = [φ, θ, ψ]).
        let q_ddot =
            Top.accelerations_unchecked(0.0, &[0.0, std::f64::consts::FRAC_PI_2, 0.0], &[0.0; 3]);
        assert_relative_eq!(q_ddot[1], 1.0, max_relative = 1e-15);
        assert_eq!(<Top as TopDynamics>::SEQUENCE, AngleSequence::Zxz);
    }
}
