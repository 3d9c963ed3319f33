//! Validation of run-time bodies: one test per rule, the error carrying the numbers.

use precess::body::{About, Axis, BodyBuilder, BodyError, Shape};

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
    use precess::body::RigidBody;
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

#[test]
fn overflow_of_f64_is_named_not_taken_for_a_zero_moment() {
    // Finite values whose moment of inertia passes the largest f64: 2/5 M R² = 4e309.
    let e = one(Shape::Sphere {
        mass: 1e296,
        radius: 1e7,
    })
    .unwrap_err();
    assert_eq!(
        e,
        BodyError::Overflow {
            quantity: "inertia tensor about the centre of mass",
            value: f64::INFINITY
        }
    );
    assert!(e.to_string().contains("overflows f64"), "{e}");
    // Two finite masses whose sum does not fit.
    let heavy = Shape::Sphere {
        mass: 1e308,
        radius: 1e-200,
    };
    let e = BodyBuilder::new()
        .part(heavy.clone(), [0.0; 3])
        .part(heavy, [0.0; 3])
        .build()
        .unwrap_err();
    assert!(
        matches!(
            e,
            BodyError::Overflow {
                quantity: "total mass",
                ..
            }
        ),
        "{e}"
    );
}

#[test]
fn underflow_of_f64_is_named_not_taken_for_a_zero_moment() {
    // 2/5 M R² = 4e-321, subnormal: the digits are gone and 1/I overflows.
    let e = one(Shape::Sphere {
        mass: 1e-300,
        radius: 1e-10,
    })
    .unwrap_err();
    assert!(
        matches!(e, BodyError::Underflow { moments } if moments[2] == 4e-321),
        "{e}"
    );
    assert!(e.to_string().contains("underflow f64"), "{e}");
    // A point mass at the pivot has truly zero moments: that stays a zero moment.
    let e = BodyBuilder::new()
        .part(Shape::Particle { mass: 1e-300 }, [0.0; 3])
        .pivot([0.0; 3])
        .build()
        .unwrap_err();
    assert_eq!(e, BodyError::ZeroPrincipalMoment { moments: [0.0; 3] });
    // Light but not too light: the smallest normal range still works.
    assert!(
        one(Shape::Sphere {
            mass: 1e-290,
            radius: 1e-5
        })
        .is_ok()
    );
}

#[test]
fn a_parametric_zero_moment_names_its_axis() {
    use precess::body::{Description, Part, SymbolicBody};
    use precess::sym::Arena;
    let mut a = Arena::new();
    let (mass, length) = (a.parameter("m"), a.parameter("l"));
    let z = a.zero();
    let rod = Shape::Rod {
        mass,
        length,
        axis: Axis::X,
    };
    let d = Description {
        parts: vec![Part::new(rod, [z, z, z])],
        pivot: None,
    };
    let e = SymbolicBody::new(&mut a, &d).unwrap_err();
    assert_eq!(e, BodyError::IdenticallyZeroMoment { axis: "x" });
    assert!(!e.to_string().contains("NaN"), "{e}");
}
