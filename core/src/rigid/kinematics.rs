//! Attitude kinematics on the unit quaternions: the exponential map that turns a body by a
//! rotation vector, and the inverse of its derivative that the Lie-group stepper needs.
//!
//! Convention: q maps body to space, q̇ = ½ q ⊗ (0, ω) with ω the body angular velocity, so a
//! body rotation by the vector φ is q ← q ⊗ exp(φ/2). The exponential keeps |q| = 1 to
//! round-off; one renormalisation per update stops round-off from accumulating.

use nalgebra::{Quaternion, UnitQuaternion, Vector3};

/// Unit quaternion exp(φ/2) of a rotation vector φ (angle |φ| about φ/|φ|).
///
/// ```
/// use nalgebra::Vector3;
/// let q = precess_core::rigid::exp_rotation(&Vector3::new(0.0, 0.0, std::f64::consts::PI));
/// approx::assert_relative_eq!(q.w, 0.0, epsilon = 1e-16);
/// approx::assert_relative_eq!(q.k, 1.0);
/// ```
pub fn exp_rotation(phi: &Vector3<f64>) -> Quaternion<f64> {
    let theta = phi.norm();
    let half = 0.5 * theta;
    // sin(θ/2)/θ by its series below 1e-4 to avoid 0/0 and cancellation.
    let sinc = if theta < 1e-4 {
        0.5 - theta * theta / 48.0
    } else {
        half.sin() / theta
    };
    Quaternion::new(half.cos(), sinc * phi.x, sinc * phi.y, sinc * phi.z)
}

/// q ⊗ exp(φ/2): rotates the body by φ (body axes), renormalised once.
///
/// ```
/// use nalgebra::{UnitQuaternion, Vector3};
/// use precess_core::rigid::rotate_body;
/// let mut q = UnitQuaternion::identity();
/// for _ in 0..1000 {
///     q = rotate_body(&q, &Vector3::new(0.3, -0.2, 0.7));
/// }
/// approx::assert_relative_eq!(q.quaternion().norm(), 1.0, epsilon = 1e-15);
/// ```
pub fn rotate_body(q: &UnitQuaternion<f64>, phi: &Vector3<f64>) -> UnitQuaternion<f64> {
    UnitQuaternion::new_normalize(q.quaternion() * exp_rotation(phi))
}

/// dexp⁻¹₋ᵤ(v) on so(3) ≅ ℝ³: v + ½ u × v + c(θ) u × (u × v),
/// c(θ) = (1 − (θ/2) cot(θ/2))/θ², θ = |u|.
///
/// ```
/// use nalgebra::Vector3;
/// use precess_core::rigid::dexpinv_right;
/// // Along u itself the map is the identity; at u = 0 it is the identity everywhere.
/// let u = Vector3::new(0.3, -0.2, 0.5);
/// approx::assert_relative_eq!(dexpinv_right(&u, &(2.0 * u)), 2.0 * u, epsilon = 1e-15);
/// let v = Vector3::new(1.0, 2.0, 3.0);
/// approx::assert_relative_eq!(dexpinv_right(&Vector3::zeros(), &v), v);
/// ```
pub fn dexpinv_right(u: &Vector3<f64>, v: &Vector3<f64>) -> Vector3<f64> {
    let th2 = u.norm_squared();
    let c = if th2 < 1e-6 {
        1.0 / 12.0 + th2 / 720.0
    } else {
        let th = th2.sqrt();
        (1.0 - 0.5 * th / (0.5 * th).tan()) / th2
    };
    let uv = u.cross(v);
    v + 0.5 * uv + c * u.cross(&uv)
}
