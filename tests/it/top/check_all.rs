//! One checked entry for a top, `check_all`, checks everything its field values decide —
//! the body by the rules of its description and the torque settings — and every checked
//! path goes through it: `accelerations`, `accelerations_in`, `ChartedTop::new` over the
//! derived charts, `validate_top`. A body that `validate()` refuses (an inertia that is not
//! positive definite, moments against the triangle inequality, a negative disk mass or
//! radius) was accepted by `accelerations` and `ChartedTop::new`, which checked the
//! settings alone.

use precess::prelude::*;
use precess::top::TopError;

/// A top whose moments about the pivot are fields.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(i1, i2, i3), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = g)]
struct Moments {
    i1: f64,
    i2: f64,
    i3: f64,
    g: f64,
}

/// A disk on a pivot whose mass and radius are fields.
#[derive(RigidBody)]
#[rigid(disk(mass = m, radius = r, at = [0.0, 0.0, 0.05]), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81)]
struct Disk {
    m: f64,
    r: f64,
}

/// A tilted, spinning state away from the ZXZ chart's gimbal lock.
const Q: [f64; 3] = [0.1, 0.8, -0.3];
const Q_DOT: [f64; 3] = [0.4, 0.0, 30.0];

/// Every checked path of `top` refuses it with `expected`; `validate()` agrees on the body.
fn refused_everywhere<T: TopDynamics>(top: &T, expected: &TopError) {
    assert_eq!(top.check_all().as_ref(), Err(expected));
    assert_eq!(top.validate_top().as_ref(), Err(expected));
    assert_eq!(top.accelerations(0.0, &Q, &Q_DOT).as_ref(), Err(expected));
    let state = [Q[0], Q[1], Q[2], Q_DOT[0], Q_DOT[1], Q_DOT[2]];
    for seq in [AngleSequence::Zxz, AngleSequence::Zyx] {
        assert_eq!(
            top.accelerations_in(seq, 0.0, &state).as_ref(),
            Err(expected)
        );
    }
    let [zxz, zyx] = TopChart::both(top);
    let charted = ChartedTop::new(
        [zxz, zyx],
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
    if let TopError::Body(body) = expected {
        assert_eq!(top.validate().as_ref(), Err(body));
    }
}

/// The body's error that `validate()` gives, wrapped as the top's.
fn body_error<T: TopDynamics>(top: &T) -> TopError {
    match top.validate() {
        Err(e) => TopError::Body(e),
        Ok(()) => panic!("validate() accepted the body"),
    }
}

const GOOD: Moments = Moments {
    i1: 1.0,
    i2: 1.0,
    i3: 0.5,
    g: 1.0,
};

#[test]
fn a_top_in_range_passes_every_path() {
    assert_eq!(GOOD.check_all(), Ok(()));
    assert!(GOOD.accelerations(0.0, &Q, &Q_DOT).is_ok());
    let disk = Disk { m: 0.3, r: 0.04 };
    assert_eq!(disk.check_all(), Ok(()));
    assert!(disk.accelerations(0.0, &Q, &Q_DOT).is_ok());
}

#[test]
fn an_inertia_that_is_not_positive_definite_is_refused() {
    let top = Moments { i1: -1.0, ..GOOD };
    let e = body_error(&top);
    assert!(
        matches!(e, TopError::Body(BodyError::NotPositiveDefinite { .. })),
        "{e:?}"
    );
    refused_everywhere(&top, &e);
}

#[test]
fn moments_against_the_triangle_inequality_are_refused() {
    // 1 + 1 < 3: no mass distribution has these moments.
    let top = Moments {
        i1: 1.0,
        i2: 1.0,
        i3: 3.0,
        ..GOOD
    };
    let e = body_error(&top);
    assert!(
        matches!(e, TopError::Body(BodyError::TriangleInequality { .. })),
        "{e:?}"
    );
    refused_everywhere(&top, &e);
}

#[test]
fn a_negative_disk_mass_or_radius_is_refused() {
    let light = Disk { m: -0.3, r: 0.04 };
    let e = body_error(&light);
    assert!(
        matches!(e, TopError::Body(BodyError::NonPositiveMass { value, .. }) if value == -0.3),
        "{e:?}"
    );
    refused_everywhere(&light, &e);
    let inside_out = Disk { m: 0.3, r: -0.04 };
    let e = body_error(&inside_out);
    assert!(
        matches!(e, TopError::Body(BodyError::NonPositiveDimension { value, .. }) if value == -0.04),
        "{e:?}"
    );
    refused_everywhere(&inside_out, &e);
}

#[test]
fn validate_checks_the_body_and_check_all_the_top() {
    // A gravity written with its sign: the body is fine, the top is not.
    let top = Moments { g: -9.81, ..GOOD };
    assert_eq!(top.validate(), Ok(()));
    refused_everywhere(&top, &TopError::NegativeGravity { value: -9.81 });
    // The body is checked first: with both wrong, the body's error is the one named.
    let both = Moments {
        i1: -1.0,
        g: -9.81,
        ..GOOD
    };
    refused_everywhere(&both, &body_error(&both));
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]

    /// Any moments and gravity: the checked paths accept exactly the tops that the body's
    /// rules and the settings' rules both accept, and refuse the others with one error.
    #[test]
    fn the_checked_paths_agree_with_the_rules(
        i1 in -2.0f64..4.0,
        i2 in -2.0f64..4.0,
        i3 in -2.0f64..4.0,
        g in -5.0f64..10.0,
    ) {
        let top = Moments { i1, i2, i3, g };
        let expected = top
            .validate()
            .map_err(TopError::Body)
            .and_then(|()| top.check_parameters());
        proptest::prop_assert_eq!(top.check_all(), expected.clone());
        let accel = top.accelerations(0.0, &Q, &Q_DOT).map(|_| ());
        match &expected {
            Ok(()) => proptest::prop_assert!(accel.is_ok(), "{accel:?}"),
            Err(e) => proptest::prop_assert_eq!(accel, Err(e.clone())),
        }
    }
}
