//! Issue 37: a driven rotor's motor that returns NaN or ±∞ is reported naming the motor
//! function, its rotor, the time and the value — by the checked accelerations and by the
//! steppers of a run (DOP853, RK4, the chart-switching run) — not as a generic non-finite
//! state. The motors below fail from t = 0.5 on, so the time reported must be at least that.

use precess::ode::{AdaptiveConfig, Dop853, FixedStepConfig, OdeError, Rk4};
use precess::prelude::*;
use precess::top::{TopChart, TopError};

/// The instant the motors stop returning a finite torque.
const FAIL: f64 = 0.5;

/// A top hanging below its pivot with one driven wheel on its figure axis, whose motor gives
/// NaN from [`FAIL`] on.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, -0.1], inertia = diag(0.05, 0.05, 0.02), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81, angles = zyx, rotor(axis = [0, 0, 1], inertia = 0.005, torque = nan_after))]
struct NanTop;

fn nan_after(_: &NanTop, t: f64, _y: &[f64]) -> f64 {
    if t < FAIL { 0.01 } else { f64::NAN }
}

/// The same top with a constant-rate wheel declared first (rotor_0) and a driven wheel on a
/// transverse axis (rotor_1) whose motor gives +∞ from [`FAIL`] on.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, -0.1], inertia = diag(0.05, 0.05, 0.02), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(
    gravity = 9.81,
    angles = zyx,
    rotor(axis = [0, 0, 1], inertia = 0.001, rate = 5),
    rotor(axis = [1, 0, 0], inertia = 0.01, torque = InfTop::motor),
)]
struct InfTop;

impl InfTop {
    fn motor(&self, t: f64, _y: &[f64]) -> f64 {
        if t < FAIL { 0.01 } else { f64::INFINITY }
    }
}

/// Swinging gently, the wheel at rest relative to the body.
const START: [f64; 7] = [0.0, 0.1, 0.0, 0.3, 0.2, 0.0, 0.0];

/// `e` is the run's error for the motor `motor` of `rotor`: it names both, and carries a
/// time at or after [`FAIL`] (and before the run's end, 1) and the value `nan` or `inf`
/// returned.
fn assert_motor(e: &OdeError, motor: &str, rotor: &str, infinite: bool) {
    let shown = e.to_string();
    assert!(
        shown.contains(&format!("`{motor}`")) && shown.contains(rotor),
        "the error does not name the motor `{motor}` of {rotor}: {shown}"
    );
    let OdeError::NonFiniteInput { t, value, .. } = *e else {
        panic!("not a non-finite input: {e:?}");
    };
    assert!((FAIL..=1.0).contains(&t), "t = {t}");
    if infinite {
        assert_eq!(value, f64::INFINITY);
    } else {
        assert!(value.is_nan(), "value = {value}");
    }
}

#[test]
fn dop853_names_a_nan_motor() {
    let chart = TopChart::declared(&NanTop);
    let mut ode = Dop853::new(&chart, 0.0, START, AdaptiveConfig::default()).unwrap();
    let e = ode.advance_to(1.0).unwrap_err();
    assert_motor(&e, "nan_after", "rotor_0", false);
    // The state before the failed step is kept: before the motor failed.
    assert!(ode.t() < FAIL + 0.5 && ode.y().iter().all(|v| v.is_finite()));
}

#[test]
fn rk4_names_a_nan_motor() {
    let chart = TopChart::declared(&NanTop);
    let mut rk = Rk4::new(&chart, 0.0, START, FixedStepConfig::with_step(0.01)).unwrap();
    let e = rk.advance_to(1.0).unwrap_err();
    assert_motor(&e, "nan_after", "rotor_0", false);
    assert!(
        rk.t() < FAIL && rk.y().iter().all(|v| v.is_finite()),
        "t = {}",
        rk.t()
    );
}

#[test]
fn dop853_and_rk4_name_an_infinite_motor_by_its_rotor_among_all() {
    let chart = TopChart::declared(&InfTop);
    let mut ode = Dop853::new(&chart, 0.0, START, AdaptiveConfig::default()).unwrap();
    assert_motor(
        &ode.advance_to(1.0).unwrap_err(),
        "InfTop::motor",
        "rotor_1",
        true,
    );
    let mut rk = Rk4::new(&chart, 0.0, START, FixedStepConfig::with_step(0.01)).unwrap();
    assert_motor(
        &rk.advance_to(1.0).unwrap_err(),
        "InfTop::motor",
        "rotor_1",
        true,
    );
}

#[test]
fn the_chart_switching_run_names_the_motor() {
    let [zyx, zxz] = TopChart::both(&NanTop);
    let (r0, w0) = (
        nalgebra::Matrix3::identity(),
        nalgebra::Vector3::new(0.3, 0.2, 0.0),
    );
    let mut top =
        ChartedTop::with_rotor_rates([zyx, zxz], 0.0, &r0, &w0, &[0.0], ChartConfig::default())
            .unwrap();
    match top.advance_to(1.0).unwrap_err() {
        TopError::Ode(e) => assert_motor(&e, "nan_after", "rotor_0", false),
        other => panic!("not the run's error: {other:?}"),
    }
}

#[test]
fn checked_accelerations_name_the_motor() {
    use precess::rigid::AngleSequence;
    let ok = NanTop.accelerations_in(AngleSequence::Zyx, 0.2, &START);
    assert!(ok.is_ok(), "{ok:?}");
    let e = NanTop
        .accelerations_in(AngleSequence::Zyx, 0.7, &START)
        .unwrap_err();
    assert!(e.to_string().contains("`nan_after`"), "{e}");
    assert!(
        matches!(e, TopError::NonFiniteMotor { rotor: "rotor_0", motor: "nan_after", t, value } if t == 0.7 && value.is_nan()),
        "{e:?}"
    );
    let e = InfTop
        .accelerations_in(
            AngleSequence::Zxz,
            0.9,
            &[0.0, 1.0, 0.0, 0.3, 0.2, 0.0, 0.0],
        )
        .unwrap_err();
    assert_eq!(
        e,
        TopError::NonFiniteMotor {
            rotor: "rotor_1",
            motor: "InfTop::motor",
            t: 0.9,
            value: f64::INFINITY
        }
    );
}
