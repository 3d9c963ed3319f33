//! Rotations as the tests convert them, optimised: nalgebra's `UnitQuaternion::from_matrix`
//! iterates from the identity (Müller's method), and unoptimised in a test crate that was
//! 95 % of a test drawing 10⁴ attitudes.
#![warn(missing_docs)]

use precess::nalgebra::{Matrix3, UnitQuaternion};

/// The unit quaternion of the rotation matrix `r` (body to space), by nalgebra's
/// `UnitQuaternion::from_matrix`: the nearest rotation's, to rounding for an orthonormal `r`.
pub fn quaternion_of(r: &Matrix3<f64>) -> UnitQuaternion<f64> {
    UnitQuaternion::from_matrix(r)
}
