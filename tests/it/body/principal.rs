//! Principal frames: Rᵀ I R diagonal, right-handed, closest to the description axes, and
//! deterministic for degenerate and nearly degenerate moments.

use crate::common;

use common::rng::Rng;
use nalgebra::{Matrix3, Rotation3, Vector3};
use precess::body::principal_frame;

fn off_diagonal(i: &Matrix3<f64>, r: &Matrix3<f64>) -> f64 {
    let d = r.transpose() * i * r;
    let scale = d.diagonal().abs().max();
    let mut off = 0.0f64;
    for (a, b) in [(0, 1), (0, 2), (1, 2)] {
        off = off.max(d[(a, b)].abs()).max(d[(b, a)].abs());
    }
    off / scale
}

fn check_frame(i: &Matrix3<f64>) -> (Vector3<f64>, Matrix3<f64>) {
    let p = principal_frame(i);
    let r = *p.rotation.matrix();
    let off = off_diagonal(i, &r);
    assert!(off <= 1e-14, "Rᵀ I R off-diagonal {off:e}");
    assert!(
        (r.determinant() - 1.0).abs() < 1e-14,
        "det {}",
        r.determinant()
    );
    assert!((r.transpose() * r - Matrix3::identity()).abs().max() < 1e-14);
    let d = r.transpose() * i * r;
    for k in 0..3 {
        assert!((d[(k, k)] - p.moments[k]).abs() <= 1e-14 * p.moments.abs().max());
    }
    (p.moments, r)
}

#[test]
fn random_tensors_are_diagonalised_to_rounding() {
    let mut rng = Rng::new(11);
    let mut worst = 0.0f64;
    for _ in 0..2000 {
        let axis = rng.vector(-1.0, 1.0);
        let r0 = Rotation3::new(axis * rng.uniform(0.0, 3.0));
        let m = Vector3::new(
            rng.uniform(0.5, 2.0),
            rng.uniform(0.5, 2.0),
            rng.uniform(0.5, 2.0),
        );
        let i = r0.matrix() * Matrix3::from_diagonal(&m) * r0.matrix().transpose();
        let p = principal_frame(&i);
        worst = worst.max(off_diagonal(&i, p.rotation.matrix()));
        check_frame(&i);
    }
    println!("worst relative off-diagonal of Rᵀ I R: {worst:.1e}");
}

#[test]
fn diagonal_tensor_keeps_the_description_axes_unsorted() {
    let i = Matrix3::from_diagonal(&Vector3::new(3.0, 1.0, 2.0));
    let (m, r) = check_frame(&i);
    assert_eq!(m, Vector3::new(3.0, 1.0, 2.0));
    assert_eq!(r, Matrix3::identity());
}

#[test]
fn closest_to_the_axes() {
    // Eigenvectors rotated by 30° about z: the frame is that rotation, not a permutation.
    let r0 = Rotation3::from_axis_angle(&Vector3::z_axis(), 30f64.to_radians());
    let i = r0.matrix()
        * Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0))
        * r0.matrix().transpose();
    let (m, r) = check_frame(&i);
    assert!((m - Vector3::new(1.0, 2.0, 3.0)).abs().max() < 1e-15);
    assert!((r - r0.matrix()).abs().max() < 1e-15);
    // At 60° the closest frame is the −30° rotation with moments 1 and 2 swapped.
    let r0 = Rotation3::from_axis_angle(&Vector3::z_axis(), 60f64.to_radians());
    let i = r0.matrix()
        * Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0))
        * r0.matrix().transpose();
    let (m, r) = check_frame(&i);
    assert!((m - Vector3::new(2.0, 1.0, 3.0)).abs().max() < 1e-15);
    let expect = Rotation3::from_axis_angle(&Vector3::z_axis(), -30f64.to_radians());
    assert!((r - expect.matrix()).abs().max() < 1e-15);
}

#[test]
fn degenerate_pair_keeps_the_description_axes() {
    let i = Matrix3::from_diagonal(&Vector3::new(2.0, 2.0, 1.0));
    let (m, r) = check_frame(&i);
    assert_eq!(m, Vector3::new(2.0, 2.0, 1.0));
    assert_eq!(r, Matrix3::identity());
    // A symmetric tensor whose axis is tilted in the x–z plane: axis 3 follows the tilt, and
    // axis 2 stays the description y (it lies in the degenerate plane).
    let tilt = Rotation3::from_axis_angle(&Vector3::y_axis(), 0.3);
    let i = tilt.matrix()
        * Matrix3::from_diagonal(&Vector3::new(2.0, 2.0, 1.0))
        * tilt.matrix().transpose();
    let (m, r) = check_frame(&i);
    // The pair's moments are made exactly equal, so (I1 − I2)/I3 is exactly zero.
    assert_eq!(m[0], m[1]);
    assert!((r.column(1) - Vector3::y()).norm() < 1e-15);
    assert!((r - tilt.matrix()).abs().max() < 1e-15);
    // All three equal: the identity.
    let (_, r) = check_frame(&(Matrix3::identity() * 0.7));
    assert_eq!(r, Matrix3::identity());
}

#[test]
fn near_degenerate_pair_is_deterministic() {
    let i1 = 1.25;
    let i = Matrix3::from_diagonal(&Vector3::new(i1, i1 * (1.0 + 1e-12), 2.0));
    let (m, r) = check_frame(&i);
    assert_eq!(r, Matrix3::identity());
    assert_eq!(m, i.diagonal());
    // Rotated about the 3-axis: diagonal to rounding, the same answer every time, and the
    // symmetric-axis column exact to rounding.
    let r0 = Rotation3::from_axis_angle(&Vector3::z_axis(), 0.4);
    let i = r0.matrix()
        * Matrix3::from_diagonal(&Vector3::new(i1, i1 * (1.0 + 1e-12), 2.0))
        * r0.matrix().transpose();
    let (m, r) = check_frame(&i);
    let again = principal_frame(&i);
    assert_eq!(again.rotation.matrix(), &r);
    assert_eq!(again.moments, m);
    assert!((r.column(2) - Vector3::z()).norm() < 1e-15);
    assert!((m[2] - 2.0).abs() < 1e-15);
    // Exactly degenerate and rotated: the description axes are kept.
    let i =
        r0.matrix() * Matrix3::from_diagonal(&Vector3::new(i1, i1, 2.0)) * r0.matrix().transpose();
    let (_, r) = check_frame(&i);
    assert!((r - Matrix3::identity()).abs().max() < 1e-15, "{r}");
}

#[test]
fn sorted_view_is_ascending_and_right_handed() {
    let r0 = Rotation3::new(Vector3::new(0.3, -0.2, 0.5));
    let i = r0.matrix()
        * Matrix3::from_diagonal(&Vector3::new(3.0, 1.0, 2.0))
        * r0.matrix().transpose();
    let s = principal_frame(&i).sorted();
    assert!(s.moments[0] <= s.moments[1] && s.moments[1] <= s.moments[2]);
    assert!((s.rotation.matrix().determinant() - 1.0).abs() < 1e-14);
    assert!(off_diagonal(&i, s.rotation.matrix()) < 1e-14);
}

#[test]
fn random_near_degenerate_and_degenerate_tensors() {
    // Random orientations of (a, a (1 + ε), b) for ε = 1e-12 and 0: always diagonal to
    // rounding, right-handed, and the same bits when asked twice.
    let mut rng = Rng::new(13);
    for eps in [1e-12, 0.0] {
        for _ in 0..500 {
            let r0 = Rotation3::new(rng.vector(-1.0, 1.0) * 3.0);
            let a = rng.uniform(0.5, 2.0);
            let b = rng.uniform(0.5, 2.0);
            let i = r0.matrix()
                * Matrix3::from_diagonal(&Vector3::new(a, a * (1.0 + eps), b))
                * r0.matrix().transpose();
            let (m, r) = check_frame(&i);
            let again = principal_frame(&i);
            assert_eq!(again.moments, m);
            assert_eq!(again.rotation.matrix(), &r);
        }
    }
}
