//! The ways of writing a part's rotation (axis–angle, matrix, elementary turns, nalgebra's
//! rotations and quaternions) against nalgebra's own rotations, and the typed errors for
//! rotations that are not.

use crate::common;

use std::f64::consts::PI;

use common::body::*;
use common::rng::Rng;
use nalgebra::{Matrix3, Rotation3, Unit, UnitQuaternion, Vector3};
use precess::body::{Axis, BodyBuilder, BodyError, Orientation, RigidBody, Shape};

/// nalgebra's turn by `angle` about `axis`: an implementation independent of precess's.
fn reference(axis: [f64; 3], angle: f64) -> Matrix3<f64> {
    *Rotation3::from_axis_angle(&Unit::new_normalize(Vector3::from(axis)), angle).matrix()
}

#[test]
fn the_ways_of_writing_a_rotation_agree_with_nalgebra() {
    let mut rng = Rng::new(5);
    let close = |a: &Matrix3<f64>, b: &Matrix3<f64>| (a - b).abs().max() < 1e-15;
    for _ in 0..100 {
        let (a, b, c) = (
            rng.uniform(-PI, PI),
            rng.uniform(-PI, PI),
            rng.uniform(-PI, PI),
        );
        let axis = rng.vector(-2.0, 2.0);
        let turn = |o: Orientation<f64>| o.to_matrix().expect("a rotation");
        let angle_axis = turn(Orientation::axis_angle(axis, a));
        assert!(close(&angle_axis, &reference(axis.into(), a)));
        // Elementary turns are axis–angle turns about coordinate axes.
        for (ax, e) in [
            (Axis::X, [1.0, 0.0, 0.0]),
            (Axis::Y, [0.0, 1.0, 0.0]),
            (Axis::Z, [0.0, 0.0, 1.0]),
        ] {
            assert!(close(
                &turn(Orientation::sequence([(ax, b)])),
                &reference(e, b)
            ));
        }
        // zyx(yaw, pitch, roll) is nalgebra's from_euler_angles(roll, pitch, yaw).
        let zyx = turn(Orientation::sequence([
            (Axis::Z, a),
            (Axis::Y, b),
            (Axis::X, c),
        ]));
        assert!(close(&zyx, Rotation3::from_euler_angles(c, b, a).matrix()));
        // zxz(φ, θ, ψ) is the tops' R = Rz(φ) Rx(θ) Rz(ψ).
        let zxz = turn(Orientation::sequence([
            (Axis::Z, a),
            (Axis::X, b),
            (Axis::Z, c),
        ]));
        let want = reference([0.0, 0.0, 1.0], a)
            * reference([1.0, 0.0, 0.0], b)
            * reference([0.0, 0.0, 1.0], c);
        assert!(close(&zxz, &want));
        // A matrix, a Rotation3 and a UnitQuaternion are taken as they are.
        let q = UnitQuaternion::from_euler_angles(a, b, c);
        assert!(close(&turn(q.into()), q.to_rotation_matrix().matrix()));
        assert_eq!(turn(zyx.into()), zyx);
    }
    assert_eq!(
        Orientation::sequence([]).to_matrix(),
        Some(Matrix3::identity())
    );
}

#[test]
fn bad_rotations_are_typed_errors() {
    let cylinder = Shape::Cylinder {
        mass: 1.0,
        radius: 0.1,
        length: 0.5,
        axis: Axis::Z,
    };
    let ball = Shape::Sphere {
        mass: 1.0,
        radius: 0.1,
    };
    let build = |o: Orientation<f64>| {
        BodyBuilder::new()
            .part(ball.clone(), [0.0; 3])
            .rotated_part(cylinder.clone(), [0.0, 0.0, 0.5], o)
            .build()
            .map(|b| b.inertia())
    };
    let zero = build(Orientation::axis_angle([0.0; 3], 0.5)).unwrap_err();
    assert_eq!(
        zero,
        BodyError::ZeroRotationAxis {
            part: 1,
            kind: "cylinder",
            axis: [0.0; 3]
        }
    );
    assert!(
        zero.to_string()
            .contains("rotation axis [0.0, 0.0, 0.0] has no direction"),
        "{zero}"
    );
    // An axis so short or so long that |k|² leaves f64's normal range cannot be normalised.
    for axis in [[1e-160, 0.0, 0.0], [1e160, 1.0, 0.0]] {
        let e = build(Orientation::axis_angle(axis, 0.5)).unwrap_err();
        assert!(matches!(e, BodyError::ZeroRotationAxis { .. }), "{e}");
    }
    // Only the direction of an axis matters.
    let short = build(Orientation::axis_angle([0.0, 1e-100, 0.0], 0.5)).expect("valid");
    let unit = build(Orientation::axis_angle([0.0, 1.0, 0.0], 0.5)).expect("valid");
    assert!(rel_err(&short, &unit) < 1e-16);

    let stretched = build([[2.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]].into()).unwrap_err();
    assert_eq!(
        stretched,
        BodyError::NotOrthonormal {
            part: 1,
            kind: "cylinder",
            deviation: 3.0
        }
    );
    assert!(
        stretched.to_string().contains("not a rotation"),
        "{stretched}"
    );
    // Entries so large that RᵀR is ∞ − ∞ are not let through as NaN.
    let huge = [[1e200, 1e200, 0.0], [-1e200, 1e200, 0.0], [0.0, 0.0, 1.0]];
    let e = build(huge.into()).unwrap_err();
    assert!(
        matches!(e, BodyError::NotOrthonormal { deviation, .. } if deviation.is_nan()),
        "{e}"
    );
    let mirror = build([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, -1.0]].into()).unwrap_err();
    assert_eq!(
        mirror,
        BodyError::ImproperRotation {
            part: 1,
            kind: "cylinder",
            determinant: -1.0
        }
    );
    assert!(mirror.to_string().contains("reflection"), "{mirror}");
    let nan = build(Orientation::axis_angle([0.0, 0.0, 1.0], f64::NAN)).unwrap_err();
    assert!(
        matches!(
            nan,
            BodyError::NonFinite {
                part: 1,
                key: "rotate",
                ..
            }
        ),
        "{nan}"
    );

    // Orthonormal to 1e-9: a rotation written with ten digits passes, one with eight fails.
    let r = reference([1.0, 1.0, 0.0], 0.5);
    let rounded = |digits: i32| {
        let s = 10f64.powi(digits);
        Orientation::from(r.map(|x| (x * s).round() / s))
    };
    let ten = build(rounded(10)).expect("orthonormal to 1e-10");
    assert!(rel_err(&ten, &build(r.into()).expect("valid")) < 1e-9);
    assert!(matches!(
        build(rounded(8)).unwrap_err(),
        BodyError::NotOrthonormal { .. }
    ));
}
