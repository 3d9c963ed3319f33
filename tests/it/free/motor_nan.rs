//! Issue 37: a free body's driven rotor whose motor returns NaN or ±∞ is reported naming the
//! motor function, its rotor, the time and the value, by DOP853 and RK4 and by
//! `FreeDynamics::check_motors`, not as a generic non-finite state. The motors fail from
//! t = 0.5 on, so the time reported must be at least that.

use precess::free::{FreeDynamics, FreeError, FreeState, FreeSystem};
use precess::ode::{AdaptiveConfig, Dop853, FixedStepConfig, OdeError, Rk4};
use precess::prelude::*;

/// The instant the motors stop returning a finite torque.
const FAIL: f64 = 0.5;

/// A body with a constant-rate wheel (rotor_0) and two driven ones: rotor_1's motor gives NaN
/// from [`FAIL`] on, rotor_2's (the same inertia rule met) stays finite.
#[derive(RigidBody)]
#[rigid(body(mass = 1.0, inertia = [[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 3.0]], about = center))]
#[free(
    gravity = 9.81,
    rotor(axis = [1, 0, 0], inertia = 0.1, rate = 3),
    rotor(axis = [0, 0, 1], inertia = 0.5, torque = nan_after),
    rotor(axis = [0, 1, 0], inertia = 0.2, torque = steady),
)]
struct Craft;

fn nan_after(_: &Craft, t: f64, _y: &[f64]) -> f64 {
    if t < FAIL { 0.2 } else { f64::NAN }
}

fn steady(_: &Craft, _t: f64, _y: &[f64]) -> f64 {
    -0.1
}

/// A body whose one driven wheel's motor gives −∞ from [`FAIL`] on.
#[derive(RigidBody)]
#[rigid(body(mass = 2.0, inertia = [[2.0, 0.0, 0.0], [0.0, 3.0, 0.0], [0.0, 0.0, 4.0]], about = center))]
#[free(rotor(axis = [1, 2, 2], inertia = 0.05, torque = Probe::motor))]
struct Probe;

impl Probe {
    fn motor(&self, t: f64, _y: &[f64]) -> f64 {
        if t < FAIL { 0.1 } else { f64::NEG_INFINITY }
    }
}

/// A tumbling state with the wheels at rest relative to the body.
fn start<const N: usize>() -> [f64; N] {
    let s = FreeState {
        omega_principal: Vector3::new(0.1, 0.5, 0.2),
        ..FreeState::at_rest()
    }
    .to_array();
    std::array::from_fn(|k| s.get(k).copied().unwrap_or(0.0))
}

/// `e` names the motor `motor` of `rotor` and carries a time in [`FAIL`, 1] and the value
/// returned (`None`: NaN).
fn assert_motor(e: &OdeError, motor: &str, rotor: &str, value: Option<f64>) {
    let shown = e.to_string();
    assert!(
        shown.contains(&format!("`{motor}`")) && shown.contains(rotor),
        "the error does not name the motor `{motor}` of {rotor}: {shown}"
    );
    let OdeError::NonFiniteInput { t, value: got, .. } = *e else {
        panic!("not a non-finite input: {e:?}");
    };
    assert!((FAIL..=1.0).contains(&t), "t = {t}");
    match value {
        Some(v) => assert_eq!(got, v),
        None => assert!(got.is_nan(), "value = {got}"),
    }
}

#[test]
fn dop853_and_rk4_name_a_nan_motor() {
    let sys = FreeSystem(&Craft);
    let mut ode = Dop853::new(sys, 0.0, start::<15>(), AdaptiveConfig::default()).unwrap();
    assert_motor(
        &ode.advance_to(1.0).unwrap_err(),
        "nan_after",
        "rotor_1",
        None,
    );
    assert!(ode.y().iter().all(|v| v.is_finite()));
    let mut rk = Rk4::new(sys, 0.0, start::<15>(), FixedStepConfig::with_step(0.01)).unwrap();
    assert_motor(
        &rk.advance_to(1.0).unwrap_err(),
        "nan_after",
        "rotor_1",
        None,
    );
    assert!(rk.t() < FAIL, "t = {}", rk.t());
}

#[test]
fn dop853_and_rk4_name_an_infinite_motor() {
    let sys = FreeSystem(&Probe);
    let mut ode = Dop853::new(sys, 0.0, start::<14>(), AdaptiveConfig::default()).unwrap();
    let inf = Some(f64::NEG_INFINITY);
    assert_motor(
        &ode.advance_to(1.0).unwrap_err(),
        "Probe::motor",
        "rotor_0",
        inf,
    );
    let mut rk = Rk4::new(sys, 0.0, start::<14>(), FixedStepConfig::with_step(0.01)).unwrap();
    assert_motor(
        &rk.advance_to(1.0).unwrap_err(),
        "Probe::motor",
        "rotor_0",
        inf,
    );
}

#[test]
fn check_motors_names_the_motor() {
    assert_eq!(Craft::MOTORS, ["nan_after", "steady"]);
    assert_eq!(Craft.check_motors(0.2, &start::<15>()), Ok(()));
    let e = Craft.check_motors(0.6, &start::<15>()).unwrap_err();
    assert!(e.to_string().contains("`nan_after` of rotor_1"), "{e}");
    assert!(
        matches!(e, FreeError::NonFiniteMotor { rotor: "rotor_1", motor: "nan_after", t, value } if t == 0.6 && value.is_nan()),
        "{e:?}"
    );
    // The run reports it as the integrators do.
    assert!(matches!(e.into_ode_error(), OdeError::NonFiniteInput { t, .. } if t == 0.6));
}
