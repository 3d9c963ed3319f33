//! A rotation matrix within the orthonormality tolerance (1e-9) is used as the rotation
//! nearest it, so a part's principal moments survive the turn to rounding. Used as given,
//! a matrix R₀(1 + δ) scaled the moments by (1 + δ)², 8e-10 at the tolerance's edge.
//! Checked against the closed-form moments of a cuboid, m(b² + c²)/12 and the others, and
//! against the same part turned by the exact rotation R₀, for the run-time builder, the
//! derive's literal matrices and its matrices of fields.

use crate::common::tops::ReferenceTop;
use nalgebra::{Matrix3, Rotation3, Vector3};
use precess::prelude::*;
use precess_core::body::{Axis, BodyBuilder, Orientation, Shape};
use proptest::prelude::*;

const SIZE: [f64; 3] = [0.2, 0.5, 0.9];

/// The cuboid's principal moments about its centre, ascending.
fn cuboid_moments() -> [f64; 3] {
    let [a, b, c] = SIZE;
    let mut m = [
        (b * b + c * c) / 12.0,
        (a * a + c * c) / 12.0,
        (a * a + b * b) / 12.0,
    ];
    m.sort_by(f64::total_cmp);
    m
}

/// The eigenvalues of a symmetric tensor, ascending.
fn eigenvalues(t: &Matrix3<f64>) -> [f64; 3] {
    let e = t.symmetric_eigen().eigenvalues;
    let mut v = [e[0], e[1], e[2]];
    v.sort_by(f64::total_cmp);
    v
}

/// The largest relative difference between two sets of moments.
fn rel_diff(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3)
        .map(|k| ((a[k] - b[k]) / b[k]).abs())
        .fold(0.0, f64::max)
}

/// A unit-mass cuboid at the origin turned by `rows`.
fn turned(rows: Matrix3<f64>) -> precess_core::body::Body {
    BodyBuilder::new()
        .rotated_part(
            Shape::Cuboid {
                mass: 1.0,
                size: SIZE,
            },
            [0.0; 3],
            rows,
        )
        .build()
        .expect("within the tolerance of a rotation")
}

#[test]
fn a_scaled_rotation_keeps_the_moments() {
    let r0 = Rotation3::from_axis_angle(
        &nalgebra::Unit::new_normalize(Vector3::new(1.0, 2.0, 2.0)),
        0.7,
    );
    // RᵀR − E = 8e-10 E, inside the tolerance.
    let r = r0.matrix() * (1.0 + 4e-10);
    let body = turned(r);
    let err = rel_diff(eigenvalues(&body.inertia()), cuboid_moments());
    assert!(err < 1e-14, "moments off by {err:e}");
    let exact = turned(*r0.matrix());
    let diff = (body.inertia() - exact.inertia()).abs().max() / exact.inertia().abs().max();
    assert!(diff < 1e-15, "tensor off the exact rotation's by {diff:e}");
    // The orientation itself reports the nearest rotation.
    let m = Orientation::from(r).to_matrix().unwrap();
    assert!((m - r0.matrix()).abs().max() < 1e-15);
}

/// A cuboid turned by a literal matrix 1 + 4e-10 times the identity.
#[derive(RigidBody)]
#[rigid(cuboid(
    mass = 1.0,
    size = [0.2, 0.5, 0.9],
    rotate = matrix([[1.0000000004, 0.0, 0.0], [0.0, 1.0000000004, 0.0], [0.0, 0.0, 1.0000000004]]),
))]
struct LiteralNearIdentity;

/// A cuboid turned by a literal matrix that is a rotation exactly in decimals (0.6² + 0.8²
/// = 1): it is kept as it is.
#[derive(RigidBody)]
#[rigid(cuboid(
    mass = 1.0,
    size = [0.2, 0.5, 0.9],
    rotate = matrix([[0.6, -0.8, 0.0], [0.8, 0.6, 0.0], [0.0, 0.0, 1.0]]),
))]
struct LiteralExact;

/// A cuboid turned about y by a matrix of fields, with a field k on the diagonal.
#[derive(RigidBody)]
#[rigid(cuboid(
    mass = 1.0,
    size = [0.2, 0.5, 0.9],
    rotate = matrix([[c, 0.0, s], [0.0, k, 0.0], [-s, 0.0, c]]),
))]
struct Fields {
    c: f64,
    s: f64,
    k: f64,
}

#[test]
fn the_derive_keeps_the_moments_of_literal_and_field_matrices() {
    let [a, b, c] = SIZE;
    let diag = [
        (b * b + c * c) / 12.0,
        (a * a + c * c) / 12.0,
        (a * a + b * b) / 12.0,
    ];
    let i = LiteralNearIdentity.inertia();
    for k in 0..3 {
        assert!(
            ((i[(k, k)] - diag[k]) / diag[k]).abs() < 1e-15,
            "I[{k}{k}] = {} for {}",
            i[(k, k)],
            diag[k]
        );
    }
    assert!(rel_diff(eigenvalues(&LiteralExact.inertia()), cuboid_moments()) < 1e-15);
    let exact = turned(Matrix3::new(0.6, -0.8, 0.0, 0.8, 0.6, 0.0, 0.0, 0.0, 1.0));
    assert!((LiteralExact.inertia() - exact.inertia()).abs().max() < 1e-16);

    let angle: f64 = 0.6;
    let fields = Fields {
        c: angle.cos(),
        s: angle.sin(),
        k: 1.0 + 4e-10,
    };
    fields.validate().expect("within the tolerance");
    let err = rel_diff(eigenvalues(&fields.inertia()), cuboid_moments());
    assert!(err < 1e-14, "moments off by {err:e}");
    let built = BodyBuilder::new()
        .rotated_part(
            Shape::Cuboid {
                mass: 1.0,
                size: SIZE,
            },
            [0.0; 3],
            Orientation::sequence([(Axis::Y, angle)]),
        )
        .build()
        .unwrap();
    let diff = (fields.inertia() - built.inertia()).abs().max() / built.inertia().abs().max();
    assert!(diff < 1e-15, "{diff:e}");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Any rotation R₀ stretched by E + S, S symmetric and small enough to pass the
    /// tolerance: the moments are the cuboid's to rounding.
    #[test]
    fn near_rotations_preserve_the_moments(
        axis in prop::array::uniform3(-1.0f64..1.0),
        angle in -3.2f64..3.2,
        s in prop::array::uniform6(-2.4e-10f64..2.4e-10),
    ) {
        let axis = Vector3::from(axis);
        prop_assume!(axis.norm() > 1e-3);
        let r0 = Rotation3::from_axis_angle(&nalgebra::Unit::new_normalize(axis), angle);
        let stretch = Matrix3::new(
            1.0 + s[0], s[3], s[4],
            s[3], 1.0 + s[1], s[5],
            s[4], s[5], 1.0 + s[2],
        );
        let r = r0.matrix() * stretch;
        let o = Orientation::from(r);
        prop_assume!(precess_core::body::check_orientation(0, "cuboid", &o).is_ok());
        let err = rel_diff(eigenvalues(&turned(r).inertia()), cuboid_moments());
        prop_assert!(err < 1e-14, "moments off by {err:e}");
    }
}

/// ChartedTop::new accepts an attitude within the same 1e-9; the angles it reads off are
/// ratios of R's entries (atan2), so a stretched R gives the angles of the rotation itself.
#[test]
fn a_charted_top_starts_from_the_nearest_rotation() {
    use precess::rigid::ChartConfig;
    use precess::top::{ChartedTop, TopChart};
    let r0 = Rotation3::from_euler_angles(0.3, 0.9, -0.4);
    // |RᵀR − E| = 6e-10 and det R − 1 = 9e-10, both inside the tolerance.
    let r = r0.matrix() * (1.0 + 3e-10);
    let [zxz, zyx] = TopChart::both(&ReferenceTop);
    let top = ChartedTop::new(
        [zxz, zyx],
        0.0,
        &r,
        &Vector3::new(0.1, 0.2, 5.0),
        ChartConfig::default(),
    )
    .unwrap();
    let off = (top.rotation() - r0.matrix()).abs().max();
    assert!(off < 1e-15, "the start is {off:e} off the rotation");
}
