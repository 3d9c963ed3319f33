//! Validation of run-time bodies: one test per rule, the error carrying the numbers.

use precess::core_api::body::{About, Axis, BodyBuilder, BodyError, Shape};

fn one(shape: Shape<f64>) -> Result<(), BodyError> {
    BodyBuilder::new().part(shape, [0.0; 3]).build().map(|_| ())
}

#[test]
fn mass_must_be_positive() {
    let e = one(Shape::Sphere {
        mass: 0.0,
        radius: 1.0,
    })
    .unwrap_err();
    assert_eq!(
        e,
        BodyError::NonPositiveMass {
            part: 0,
            kind: "sphere",
            value: 0.0
        }
    );
    assert!(e.to_string().contains("mass must be positive"));
}

#[test]
fn dimensions_must_be_positive() {
    let e = one(Shape::Cylinder {
        mass: 1.0,
        radius: 0.1,
        length: -2.0,
        axis: Axis::Z,
    })
    .unwrap_err();
    assert_eq!(
        e,
        BodyError::NonPositiveDimension {
            part: 0,
            kind: "cylinder",
            key: "length",
            value: -2.0
        }
    );
}

#[test]
fn values_must_be_finite() {
    let e = one(Shape::Sphere {
        mass: 1.0,
        radius: f64::INFINITY,
    })
    .unwrap_err();
    assert!(matches!(e, BodyError::NonFinite { key: "radius", .. }));
    let e = BodyBuilder::new()
        .part(
            Shape::Sphere {
                mass: 1.0,
                radius: 1.0,
            },
            [0.0; 3],
        )
        .pivot([f64::NAN, 0.0, 0.0])
        .build()
        .unwrap_err();
    assert!(matches!(e, BodyError::NonFinitePivot { .. }));
}

#[test]
fn tube_radii_must_nest() {
    let e = one(Shape::Tube {
        mass: 1.0,
        inner: 0.3,
        outer: 0.2,
        length: 1.0,
        axis: Axis::Z,
    })
    .unwrap_err();
    assert_eq!(
        e,
        BodyError::TubeRadii {
            part: 0,
            inner: 0.3,
            outer: 0.2
        }
    );
}

#[test]
fn explicit_tensor_must_be_symmetric() {
    let t = [[1.0, 0.1, 0.0], [0.2, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let e = one(Shape::Explicit {
        mass: 1.0,
        inertia: t,
        about: About::Center,
    })
    .unwrap_err();
    assert_eq!(
        e,
        BodyError::NotSymmetric {
            part: 0,
            row: 0,
            col: 1,
            upper: 0.1,
            lower: 0.2
        }
    );
}

#[test]
fn explicit_tensor_must_be_positive_definite() {
    let t = [[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0]];
    let e = one(Shape::Explicit {
        mass: 1.0,
        inertia: t,
        about: About::Center,
    })
    .unwrap_err();
    assert!(matches!(e, BodyError::NotPositiveDefinite { moments, .. } if moments[0] == -1.0));
}

#[test]
fn explicit_tensor_must_obey_the_triangle_inequality() {
    let t = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 3.0]];
    let e = one(Shape::Explicit {
        mass: 1.0,
        inertia: t,
        about: About::Center,
    })
    .unwrap_err();
    assert_eq!(
        e,
        BodyError::TriangleInequality {
            part: 0,
            moments: [1.0, 1.0, 3.0]
        }
    );
    // A lamina sits exactly on the boundary, I1 + I2 = I3, and is fine.
    let t = [[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 3.0]];
    assert!(
        one(Shape::Explicit {
            mass: 1.0,
            inertia: t,
            about: About::Center
        })
        .is_ok()
    );
}

#[test]
fn about_pivot_needs_a_pivot() {
    let t = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let e = one(Shape::Explicit {
        mass: 1.0,
        inertia: t,
        about: About::Pivot,
    })
    .unwrap_err();
    assert_eq!(e, BodyError::PivotRequired { part: 0 });
}

#[test]
fn explicit_tensor_about_the_pivot_is_moved_to_the_centre() {
    // A unit sphere-like tensor given about a pivot one metre below its centre.
    let (m, i0) = (2.0, 0.4);
    let about_pivot = [[i0 + m, 0.0, 0.0], [0.0, i0 + m, 0.0], [0.0, 0.0, i0]];
    let b = BodyBuilder::new()
        .part(
            Shape::Explicit {
                mass: m,
                inertia: about_pivot,
                about: About::Pivot,
            },
            [0.0, 0.0, 1.0],
        )
        .pivot([0.0; 3])
        .build()
        .expect("a valid body");
    use precess::core_api::body::RigidBody;
    assert!(
        (b.inertia_cm() - nalgebra::Matrix3::identity() * i0)
            .abs()
            .max()
            < 1e-15
    );
    assert!((b.inertia()[(0, 0)] - (i0 + m)).abs() < 1e-15);
}

#[test]
fn mass_on_a_line_has_a_zero_moment() {
    let e = one(Shape::Rod {
        mass: 1.0,
        length: 1.0,
        axis: Axis::X,
    })
    .unwrap_err();
    assert!(matches!(e, BodyError::ZeroPrincipalMoment { moments } if moments[0] == 0.0));
    let e = BodyBuilder::new()
        .part(Shape::Particle { mass: 1.0 }, [0.0, 0.0, 1.0])
        .pivot([0.0; 3])
        .build()
        .unwrap_err();
    assert!(matches!(e, BodyError::ZeroPrincipalMoment { .. }));
}

#[test]
fn empty_body() {
    assert_eq!(BodyBuilder::new().build().unwrap_err(), BodyError::NoParts);
}
