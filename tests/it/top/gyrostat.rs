//! Issue 26 item 4: tops carrying rotors (gyrostats about a pivot). A wheel spun at the
//! constant rate Ω relative to the body about its axis â, with axial moment J, carries
//! h = J Ω â, constant in the body; the Lagrangian gains ω·h and Euler's equations become
//! I ω̇ = τ − ω × (I ω + h). Checked against what is known independently of the code: the
//! Eulerian form written here with nalgebra, the steady precession of the symmetric heavy
//! gyrostat (derived below), the two integrals (the energy ½ ωᵀ I ω + V and the vertical
//! angular momentum (R (I ω + h))·ẑ), and the top whose wheel is stopped.
//!
//! Steady precession with the wheel on the symmetry axis: with ω₃ = ψ̇ + φ̇ cos θ,
//! L = ½ I₁ (θ̇² + φ̇² sin² θ) + ½ I₃ ω₃² + h ω₃ − M g l cos θ, so
//! I₁ θ̈ = ∂L/∂θ = I₁ φ̇² sin θ cos θ − (I₃ ω₃ + h) φ̇ sin θ + M g l sin θ.
//! θ̈ = 0 at θ̇ = 0, φ̇ = Ω_p, sin θ ≠ 0 when M g l = Ω_p (I₃ ω₃ + h) − I₁ Ω_p² cos θ: the
//! spin momentum I₃ ω₃ of the top without a wheel becomes I₃ ω₃ + h.

use approx::assert_relative_eq;
use nalgebra::{Matrix3, Vector3};
use precess::ode::{AdaptiveConfig, Dop853, OdeError};
use precess::prelude::*;
use precess::top::{EulerianTop, TheoryError, TopChart, TopError, angle_state};

use crate::common::rng::Rng;

/// An asymmetric top with its centre off every axis, under gravity, carrying two wheels: a
/// literal one along (1, 2, −2) with J Ω = 0.6, so h₁ = (0.2, 0.4, −0.4), and one along z
/// with its moment and rate read from fields.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.3, at = [0.04, -0.03, 0.25], inertia = [[0.9, 0.05, -0.02], [0.05, 0.7, 0.03], [-0.02, 0.03, 0.4]]),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81, rotor(axis = [1, 2, -2], inertia = 0.02, rate = 30), rotor(axis = [0, 0, 1], inertia = j, rate = spin))]
struct Gyro {
    j: f64,
    spin: f64,
}

const GYRO: Gyro = Gyro {
    j: 0.01,
    spin: -50.0,
};

/// `GYRO`'s h, written out.
fn gyro_h() -> Vector3<f64> {
    Vector3::new(0.2, 0.4, -0.4) + Vector3::new(0.0, 0.0, 0.01 * -50.0)
}

/// The symmetric heavy top (I₁ = 1, I₃ = ½ about the pivot, M g l = 1) with a wheel on its
/// symmetry axis of h = J Ω = 0.2 · 10 = 2.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 1.0, rotor(axis = [0, 0, 1], inertia = 0.2, rate = 10))]
struct Gyrotop;

/// A top with damping and a wheel stopped (rate 0) …
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.3, at = [0.04, -0.03, 0.25], inertia = diag(0.9, 0.7, 0.4)),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81, damping = 0.01, rotor(axis = [1, 1, 0], inertia = 0.01, rate = 0))]
struct Stopped;

/// … and the same top without the wheel.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.3, at = [0.04, -0.03, 0.25], inertia = diag(0.9, 0.7, 0.4)),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81, damping = 0.01)]
struct Wheelless;

/// Goldstein's ZXZ body rates ω = B q̇, written out.
pub(super) fn b_zxz(q: &[f64; 3]) -> Matrix3<f64> {
    let (st, ct) = q[1].sin_cos();
    let (sp, cp) = q[2].sin_cos();
    Matrix3::new(st * sp, cp, 0.0, st * cp, -sp, 0.0, ct, 0.0, 1.0)
}

/// ω̇ = B q̈ + Ḃ q̇ for ZXZ, differentiated by hand.
pub(super) fn omega_dot_zxz(q: &[f64; 3], qd: &[f64; 3], qdd: &[f64; 3]) -> Vector3<f64> {
    let (st, ct) = q[1].sin_cos();
    let (sp, cp) = q[2].sin_cos();
    let [phd, thd, psd] = *qd;
    let b_dot_qd = Vector3::new(
        phd * thd * ct * sp + phd * psd * st * cp - thd * psd * sp,
        phd * thd * ct * cp - phd * psd * st * sp - thd * psd * cp,
        -phd * thd * st,
    );
    b_zxz(q) * Vector3::from(*qdd) + b_dot_qd
}

/// The Volterra–Zhukovsky equations under gravity, independently of the derive:
/// I ω̇ = c × (Rᵀ(−M g ẑ)) − ω × (I ω + h).
fn volterra(
    top: &impl RigidBody,
    g: f64,
    h: &Vector3<f64>,
    r: &Matrix3<f64>,
    w: &Vector3<f64>,
) -> Vector3<f64> {
    let i = top.inertia();
    let c = top.center_of_mass() - top.reference_point();
    let weight = r.transpose() * Vector3::new(0.0, 0.0, -top.mass() * g);
    let tau = c.cross(&weight);
    i.try_inverse().unwrap() * (tau - w.cross(&(i * w + h)))
}

/// A state of the ZXZ chart away from its lock (|sin θ| ≥ 0.2).
pub(super) fn random_state(rng: &mut Rng) -> ([f64; 3], [f64; 3]) {
    let q = [
        rng.uniform(-3.0, 3.0),
        rng.uniform(0.2, 2.9),
        rng.uniform(-3.0, 3.0),
    ];
    let qd = [
        rng.uniform(-5.0, 5.0),
        rng.uniform(-5.0, 5.0),
        rng.uniform(-5.0, 5.0),
    ];
    (q, qd)
}

/// The Euler-angle Lagrangian equations (ω̇ from q̈) and the generated Eulerian form both
/// equal the Volterra–Zhukovsky equations written here, at random states, to 1e-12 of the
/// size of ω̇.
#[test]
fn lagrangian_and_eulerian_forms_agree_with_rotors() {
    let mut rng = Rng::new(264);
    let h = gyro_h();
    assert_relative_eq!(GYRO.rotor_momentum(), h, epsilon = 1e-15);
    let mut worst = (0.0f64, 0.0f64);
    for _ in 0..2000 {
        let (q, qd) = random_state(&mut rng);
        let b = GYRO.rate_matrix_in(AngleSequence::Zxz, &q);
        assert_relative_eq!(b, b_zxz(&q), epsilon = 1e-15);
        let w = b * Vector3::from(qd);
        let r = GYRO.rotation_in(AngleSequence::Zxz, &q);
        let expected = volterra(&GYRO, 9.81, &h, &r, &w);
        let qdd = GYRO.accelerations(0.0, &q, &qd).unwrap();
        let from_angles = omega_dot_zxz(&q, &qd, &qdd);
        let attitude = precess_testkit::rotations::quaternion_of(&r);
        let eulerian = GYRO.eulerian_rhs(0.0, &attitude, &w);
        let scale = expected.norm().max(1.0);
        worst.0 = worst.0.max((from_angles - expected).norm() / scale);
        worst.1 = worst.1.max((eulerian - expected).norm() / scale);
    }
    assert!(worst.0 < 1e-12, "Lagrangian form off by {:e}", worst.0);
    assert!(worst.1 < 1e-12, "Eulerian form off by {:e}", worst.1);
}

/// The slow root of I₁ cos θ Ω² − (I₃ ω₃ + h) Ω + M g l = 0 for `Gyrotop` at θ = 60°,
/// ω₃ = 10: ½ Ω² − 7 Ω + 1 = 0, Ω = 7 − √47 (without the wheel it would be 5 − √23).
fn gyrotop_precession() -> (f64, f64, f64) {
    (std::f64::consts::FRAC_PI_3, 10.0, 7.0 - 47f64.sqrt())
}

/// The steady precession of the closed form is an equilibrium of the angle equations and
/// stays steady over a run, in the angle chart and in the Eulerian form.
#[test]
fn steady_precession_of_the_symmetric_gyrostat() {
    let (theta, w3, omega_p) = gyrotop_precession();
    let q = [0.0, theta, 0.0];
    let qd = [omega_p, 0.0, w3 - omega_p * theta.cos()];
    let qdd = Gyrotop.accelerations(0.0, &q, &qd).unwrap();
    assert!(qdd.iter().all(|a| a.abs() < 1e-13), "q̈ = {qdd:?}");
    // The momentum conjugate to ψ is I₃ ω₃ + h.
    assert_relative_eq!(
        Gyrotop.conserved_momenta(&q, &qd)[2].unwrap(),
        0.5 * w3 + 2.0,
        epsilon = 1e-13
    );

    let tight = AdaptiveConfig::with_tol(1e-13, 1e-13);
    let t_end = 20.0;
    let mut angles = Dop853::new(
        TopChart::declared(&Gyrotop),
        0.0,
        angle_state(&q, &qd),
        tight,
    )
    .unwrap();
    angles.advance_to(t_end).unwrap();
    let y = angles.y();
    assert!(
        (y[1] - theta).abs() < 1e-10,
        "θ drifted by {:e}",
        y[1] - theta
    );
    assert!(
        (y[0] - omega_p * t_end).abs() < 1e-10,
        "φ off by {:e}",
        y[0] - omega_p * t_end
    );

    // The Eulerian form: the figure axis turns about the vertical at Ω_p, keeping its tilt.
    let q0 = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), theta);
    let w0 = Vector3::new(0.0, omega_p * theta.sin(), w3);
    let y0 = EulerianTop::<Gyrotop>::state(&q0, &w0);
    let mut euler = Dop853::new(EulerianTop(&Gyrotop), 0.0, y0, tight).unwrap();
    euler.advance_to(t_end).unwrap();
    let axis = EulerianTop::<Gyrotop>::attitude(euler.y()).unwrap() * Vector3::z();
    let phi = omega_p * t_end;
    let expected = Vector3::new(
        theta.sin() * phi.sin(),
        -theta.sin() * phi.cos(),
        theta.cos(),
    );
    assert!(
        (axis - expected).norm() < 1e-10,
        "axis off by {:e}",
        (axis - expected).norm()
    );
}

/// ½ ωᵀ I ω + M g (R c)·ẑ and (R (I ω + h))·ẑ, written here.
fn integrals(r: &Matrix3<f64>, w: &Vector3<f64>) -> (f64, f64) {
    let i = GYRO.inertia();
    let c = GYRO.center_of_mass() - GYRO.reference_point();
    let energy = 0.5 * w.dot(&(i * w)) + GYRO.mass() * 9.81 * (r * c).z;
    (energy, (r * (i * w + gyro_h())).z)
}

/// The energy and the vertical angular momentum stay constant over a tumbling run of the
/// Eulerian form; the derived energy and p_φ equal them at every state.
#[test]
fn energy_and_vertical_momentum_are_conserved() {
    let mut rng = Rng::new(2641);
    for _ in 0..50 {
        let (q, qd) = random_state(&mut rng);
        let r = GYRO.rotation_in(AngleSequence::Zxz, &q);
        let w = GYRO.omega_from_rates(&q, &qd);
        let (energy, lz) = integrals(&r, &w);
        assert_relative_eq!(
            GYRO.energy(&q, &qd),
            energy,
            max_relative = 1e-13,
            epsilon = 1e-13
        );
        assert_relative_eq!(
            GYRO.conserved_momenta(&q, &qd)[0].unwrap(),
            lz,
            max_relative = 1e-13,
            epsilon = 1e-13
        );
    }
    let r0 = GYRO.rotation_in(AngleSequence::Zxz, &[0.3, 1.1, -0.4]);
    let w0 = Vector3::new(2.0, -3.0, 4.0);
    let (e0, l0) = integrals(&r0, &w0);
    let y0 = EulerianTop::<Gyro>::state(&precess_testkit::rotations::quaternion_of(&r0), &w0);
    let mut run = Dop853::new(
        EulerianTop(&GYRO),
        0.0,
        y0,
        AdaptiveConfig::with_tol(1e-13, 1e-13),
    )
    .unwrap();
    run.advance_to(10.0).unwrap();
    let r = EulerianTop::<Gyro>::attitude(run.y())
        .unwrap()
        .to_rotation_matrix()
        .into_inner();
    let y = run.y();
    let (e, l) = integrals(&r, &Vector3::new(y[4], y[5], y[6]));
    assert!(
        (e - e0).abs() < 1e-10 * e0.abs(),
        "energy drifted by {:e}",
        e - e0
    );
    assert!(
        (l - l0).abs() < 1e-10 * l0.abs().max(1.0),
        "L_z drifted by {:e}",
        l - l0
    );
}

/// A wheel stopped contributes nothing: the top equals the one without it.
#[test]
fn rate_zero_equals_no_rotor() {
    assert_eq!(Stopped.rotor_momentum(), Vector3::zeros());
    let mut rng = Rng::new(2642);
    for _ in 0..200 {
        let (q, qd) = random_state(&mut rng);
        let (a, b) = (
            Stopped.accelerations(0.0, &q, &qd).unwrap(),
            Wheelless.accelerations(0.0, &q, &qd).unwrap(),
        );
        for k in 0..3 {
            assert_relative_eq!(a[k], b[k], max_relative = 1e-14, epsilon = 1e-14);
        }
        let r = Stopped.rotation_in(AngleSequence::Zxz, &q);
        let attitude = precess_testkit::rotations::quaternion_of(&r);
        let w = Vector3::from(qd);
        assert_relative_eq!(
            Stopped.eulerian_rhs(0.0, &attitude, &w),
            Wheelless.eulerian_rhs(0.0, &attitude, &w),
            max_relative = 1e-14,
            epsilon = 1e-14
        );
        assert_relative_eq!(
            Stopped.energy(&q, &qd),
            Wheelless.energy(&q, &qd),
            max_relative = 1e-14
        );
    }
}

/// The heavy-top closed forms assume no wheel: a gyrostat's theory is refused by name.
#[test]
fn theory_refuses_a_gyrostat() {
    assert_eq!(Gyrotop::ROTORS, 1);
    assert_eq!(Gyro::ROTORS, 2);
    assert!(matches!(
        Gyrotop.theory(),
        Err(TopError::Theory(TheoryError::Rotor { rotors: 1 }))
    ));
}

/// Field values of a wheel are judged when a run starts: a negative moment, a NaN rate.
#[test]
fn rotor_fields_are_checked() {
    assert!(GYRO.check_all().is_ok());
    let negative = Gyro {
        j: -0.01,
        spin: 5.0,
    };
    assert!(matches!(
        negative.check_all(),
        Err(TopError::InvalidRotor { rotor: 1, inertia, .. }) if inertia == -0.01
    ));
    let nan = Gyro {
        j: 0.01,
        spin: f64::NAN,
    };
    assert!(matches!(
        nan.check_all(),
        Err(TopError::NonFiniteParameter {
            parameter: "rotor rate",
            ..
        })
    ));
    let y0 = angle_state(&[0.0, 1.0, 0.0], &[0.0, 0.0, 1.0]);
    let refused = Dop853::new(
        TopChart::declared(&negative),
        0.0,
        y0,
        AdaptiveConfig::default(),
    );
    assert!(matches!(
        refused,
        Err(OdeError::InvalidSystemParameter { ref quantity, value, .. }) if quantity == "rotor inertia" && value == -0.01
    ));
}

/// |L| of the quantities is |I ω + h|: a top at rest carries the wheels' momentum alone.
#[test]
fn quantities_count_the_wheels_momentum() {
    use precess::ode::Quantities;
    let mut quantities = precess::top::TopQuantities::new(&GYRO);
    let names = quantities.names();
    let at = names.iter().position(|n| n == "L").unwrap();
    let mut out = vec![0.0; names.len()];
    quantities.evaluate(0.0, &angle_state(&[0.1, 0.8, 0.2], &[0.0; 3]), &mut out);
    assert_relative_eq!(out[at], gyro_h().norm(), max_relative = 1e-14);
}

/// A scene built at run time with a rotor whose rate is a parameter, interpreted by
/// `TopModel`: the same steady precession is an equilibrium, and the rate changes it.
#[test]
fn run_time_scene_with_a_rotor() {
    use precess::rigid::Rotor;
    use precess::sym::Arena;
    use precess::top::{TopModel, TopScene};
    let mut a = Arena::new();
    let (one, half, z) = (
        a.one(),
        a.constant(precess::sym::Rational::new(1, 2).unwrap()),
        a.zero(),
    );
    let mut scene = TopScene::free(&mut a, [[one, z, z], [z, one, z], [z, z, half]]);
    scene.center = [z, z, one];
    scene.gravity = Some(one);
    let (j, rate) = (a.parameter("J"), a.parameter("Omega"));
    scene.rotors.push(Rotor {
        axis: [z, z, one],
        inertia: j,
        rate,
    });
    let derivation = scene.derive(&mut a).unwrap();
    let (theta, w3, omega_p) = gyrotop_precession();
    let state = [0.0, theta, 0.0, omega_p, 0.0, w3 - omega_p * theta.cos()];
    let mut model = TopModel::new(&mut a, &derivation, &[("J", 0.2), ("Omega", 10.0)]).unwrap();
    assert!(
        model
            .accelerations(&state)
            .unwrap()
            .iter()
            .all(|x| x.abs() < 1e-13)
    );
    assert_relative_eq!(model.momenta(&state)[2], 0.5 * w3 + 2.0, epsilon = 1e-13);
    // Without the wheel's momentum the same state is not steady: θ̈ = 1/4 (from the
    // equation in the header with h = 0: sin θ (½ Ω_p² − 5 Ω_p + 1)).
    model.set("Omega", 0.0).unwrap();
    let expected = theta.sin() * (omega_p * omega_p * theta.cos() - 5.0 * omega_p + 1.0);
    assert_relative_eq!(
        model.accelerations(&state).unwrap()[1],
        expected,
        epsilon = 1e-13
    );
}

/// The same body as [`Gyrotop`] without its wheel: a heavy top the splitting models.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 1.0)]
struct PlainHeavy;

/// `FastTop::new` reads the body only, so it cannot see a wheel; `FastTop::of_top` takes the
/// derived top and refuses a gyrostat (and a damped top) by name rather than integrate it as
/// if the wheel were not there. A top under gravity alone gets the splitting `new` builds,
/// with its declared g.
#[test]
fn the_fast_top_refuses_a_gyrostat() {
    use precess::top::FastTop;
    assert_eq!(
        FastTop::of_top(&Gyrotop),
        Err(TopError::FastTopBeyondGravity {
            declared: "a rotor"
        })
    );
    assert_eq!(
        FastTop::of_top(&Stopped),
        Err(TopError::FastTopBeyondGravity {
            declared: "a rotor"
        })
    );
    assert_eq!(
        FastTop::of_top(&Wheelless),
        Err(TopError::FastTopBeyondGravity {
            declared: "damping"
        })
    );
    let fast = FastTop::of_top(&PlainHeavy).unwrap();
    assert_eq!(fast, FastTop::new(&PlainHeavy, 1.0).unwrap());
    assert_eq!(fast.splitting.potential.weight, 1.0);
}
