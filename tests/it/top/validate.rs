//! Field values of `#[top(...)]` meet the rules literals meet at compile time: a gravity
//! written with its sign (−9.81), a negative damping, a NaN or infinite setting are refused
//! by name at every checked entry point instead of running with the wrong physics.

use precess::prelude::*;
use precess::top::{TopError, TopParameters};

/// A heavy top whose gravity, damping and a body torque component come from fields.
#[derive(RigidBody)]
#[rigid(
    disk(mass = m, radius = 0.04, at = [0.0, 0.0, 0.05]),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = g, damping = k, body_torque = [0.0, 0.0, tau])]
struct Spinner {
    m: f64,
    g: f64,
    k: f64,
    tau: f64,
}

const SPINNER: Spinner = Spinner {
    m: 0.3,
    g: 9.81,
    k: 0.002,
    tau: 0.0,
};

/// A top whose gravity is arithmetic on a field: the value judged is the computed one.
#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1, at = [0.0, 0.0, 0.2]), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 2.0 * half_g, space_torque = [s, 0.0, 0.0])]
struct Scaled {
    half_g: f64,
    s: f64,
}

/// A tilted, spinning state away from the ZXZ chart's gimbal lock.
const Q: [f64; 3] = [0.1, 0.8, -0.3];
const Q_DOT: [f64; 3] = [0.4, 0.0, 30.0];

/// Every checked entry point of `top` gives `expected`.
fn refused_everywhere(top: &Spinner, expected: &TopError) {
    assert_eq!(top.check_parameters().as_ref(), Err(expected));
    assert_eq!(top.accelerations(0.0, &Q, &Q_DOT).as_ref(), Err(expected));
    assert_eq!(top.validate_top().as_ref(), Err(expected));
    let [zxz, zyx] = TopChart::both(top);
    let charted = ChartedTop::new(
        [&zxz, &zyx],
        0.0,
        &Matrix3::identity(),
        &Vector3::new(0.0, 0.0, 30.0),
        ChartConfig::default(),
    );
    match charted {
        Err(e) if &e == expected => {}
        Err(e) => panic!("expected {expected:?}, got {e:?}"),
        Ok(_) => panic!("expected {expected:?}, the charted top started"),
    }
}

#[test]
fn a_gravity_written_with_its_sign_is_refused() {
    let top = Spinner {
        g: -9.81,
        ..SPINNER
    };
    refused_everywhere(&top, &TopError::NegativeGravity { value: -9.81 });
    let message = top.check_parameters().map_err(|e| e.to_string());
    assert!(
        matches!(&message, Err(m) if m.contains("`gravity` is -9.81") && m.contains("not −9.81")),
        "{message:?}"
    );
}

#[test]
fn a_negative_damping_is_refused() {
    let top = Spinner {
        k: -0.002,
        ..SPINNER
    };
    refused_everywhere(&top, &TopError::NegativeDamping { value: -0.002 });
}

#[test]
fn nan_and_infinite_settings_are_refused_by_name() {
    let nan = Spinner {
        g: f64::NAN,
        ..SPINNER
    };
    match nan.accelerations(0.0, &Q, &Q_DOT) {
        Err(TopError::NonFiniteParameter {
            parameter: "gravity",
            value,
        }) => assert!(value.is_nan()),
        other => panic!("expected a NaN gravity, got {other:?}"),
    }
    let inf = Spinner {
        k: f64::INFINITY,
        ..SPINNER
    };
    refused_everywhere(
        &inf,
        &TopError::NonFiniteParameter {
            parameter: "damping",
            value: f64::INFINITY,
        },
    );
    let torque = Spinner {
        tau: f64::NEG_INFINITY,
        ..SPINNER
    };
    refused_everywhere(
        &torque,
        &TopError::NonFiniteParameter {
            parameter: "body_torque",
            value: f64::NEG_INFINITY,
        },
    );
}

#[test]
fn the_value_judged_is_the_one_the_equations_read() {
    let up = Scaled {
        half_g: -4.9,
        s: 0.0,
    };
    assert_eq!(
        up.check_parameters(),
        Err(TopError::NegativeGravity { value: -9.8 })
    );
    let spun = Scaled {
        half_g: 4.9,
        s: f64::NAN,
    };
    assert!(matches!(
        spun.check_parameters(),
        Err(TopError::NonFiniteParameter { parameter: "space_torque", value }) if value.is_nan()
    ));
    let good = Scaled {
        half_g: 4.9,
        s: 0.5,
    };
    assert_eq!(
        good.top_parameters(),
        TopParameters {
            gravity: Some(9.8),
            space_torque: Some(Vector3::new(0.5, 0.0, 0.0)),
            ..TopParameters::default()
        }
    );
}

#[test]
fn settings_in_range_pass_and_zero_is_in_range() {
    assert_eq!(
        SPINNER.top_parameters(),
        TopParameters {
            gravity: Some(9.81),
            damping: Some(0.002),
            body_torque: Some(Vector3::zeros()),
            space_torque: None,
        }
    );
    assert_eq!(SPINNER.validate_top(), Ok(()));
    assert!(SPINNER.accelerations(0.0, &Q, &Q_DOT).is_ok());
    // No gravity and no damping are physics (a top in free fall, an undamped one).
    let free = Spinner {
        g: 0.0,
        k: 0.0,
        ..SPINNER
    };
    assert_eq!(free.check_parameters(), Ok(()));
    assert!(free.validated_top().is_ok());
}

#[test]
fn the_body_of_a_top_is_checked_with_it() {
    let massless = Spinner { m: -0.3, ..SPINNER };
    assert!(matches!(
        massless.validate_top(),
        Err(TopError::Body(BodyError::NonPositiveMass { value, .. })) if value == -0.3
    ));
    // The settings alone are in range: the body is what is wrong.
    assert_eq!(massless.check_parameters(), Ok(()));
}

/// Literal settings are checked at compile time (tests/ui: top_negative_gravity,
/// top_negative_damping), so a top of literals passes at run time.
#[test]
fn literal_settings_were_checked_while_expanding() {
    #[derive(RigidBody)]
    #[rigid(sphere(mass = 1.0, radius = 0.1, at = [0.0, 0.0, 0.2]), pivot = [0.0, 0.0, 0.0])]
    #[top(gravity = 0.0, damping = 0.1)]
    struct Literal;
    assert_eq!(
        Literal.top_parameters(),
        TopParameters {
            gravity: Some(0.0),
            damping: Some(0.1),
            ..TopParameters::default()
        }
    );
    assert_eq!(Literal.check_parameters(), Ok(()));
}
