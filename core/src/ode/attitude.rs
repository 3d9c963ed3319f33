//! Attitude states on the unit quaternions, the exponential map that advances them, and the
//! models (torques, forces) that drive them.
//!
//! Convention: q maps body to space, q̇ = ½ q ⊗ (0, ω) with ω the body angular velocity, so a
//! body rotation by the vector φ is q ← q ⊗ exp(φ/2). The exponential keeps |q| = 1 to
//! round-off; one renormalisation per update stops round-off from accumulating.

use nalgebra::{Quaternion, UnitQuaternion, Vector3};

use super::error::{OdeError, check_finite, check_inertia};

/// Unit quaternion exp(φ/2) of a rotation vector φ (angle |φ| about φ/|φ|).
///
/// ```
/// use nalgebra::Vector3;
/// let q = precess_core::ode::attitude::exp_rotation(&Vector3::new(0.0, 0.0, std::f64::consts::PI));
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
/// use precess_core::ode::attitude::rotate_body;
/// let mut q = UnitQuaternion::identity();
/// for _ in 0..1000 {
///     q = rotate_body(&q, &Vector3::new(0.3, -0.2, 0.7));
/// }
/// approx::assert_relative_eq!(q.quaternion().norm(), 1.0, epsilon = 1e-15);
/// ```
pub fn rotate_body(q: &UnitQuaternion<f64>, phi: &Vector3<f64>) -> UnitQuaternion<f64> {
    UnitQuaternion::new_normalize(q.quaternion() * exp_rotation(phi))
}

/// Attitude and body angular velocity of a rigid body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Attitude {
    /// Body-to-space rotation.
    pub q: UnitQuaternion<f64>,
    /// Body angular velocity ω (principal axes).
    pub omega: Vector3<f64>,
}

/// The whole state of a free rigid body: centre of mass, its velocity, attitude and ω.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidState {
    /// Centre-of-mass position (space).
    pub x: Vector3<f64>,
    /// Centre-of-mass velocity (space).
    pub v: Vector3<f64>,
    /// Body-to-space rotation.
    pub q: UnitQuaternion<f64>,
    /// Body angular velocity ω (principal axes).
    pub omega: Vector3<f64>,
}

/// A body in principal axes under a body-frame torque G(t, state):
/// I ω̇ = (I ω) × ω + G.
pub trait AttitudeModel {
    /// Principal moments (I₁, I₂, I₃).
    fn inertia(&self) -> [f64; 3];
    /// Torque in body axes (default: none).
    fn torque(&self, _t: f64, _s: &Attitude) -> Vector3<f64> {
        Vector3::zeros()
    }
}

/// A free rigid body under a space-frame force F and a body-frame torque G:
/// M ẍ = F beside I ω̇ = (I ω) × ω + G.
pub trait RigidBodyModel {
    /// Mass M.
    fn mass(&self) -> f64;
    /// Principal moments (I₁, I₂, I₃) about the centre of mass.
    fn inertia(&self) -> [f64; 3];
    /// Force on the centre of mass, space axes (default: none).
    fn force(&self, _t: f64, _s: &RigidState) -> Vector3<f64> {
        Vector3::zeros()
    }
    /// Torque about the centre of mass, body axes (default: none).
    fn torque(&self, _t: f64, _s: &RigidState) -> Vector3<f64> {
        Vector3::zeros()
    }
}

/// Euler's equations: ω̇ = I⁻¹((I ω) × ω + G).
///
/// ```
/// use nalgebra::Vector3;
/// let w = Vector3::new(1.0, 0.0, 0.9);
/// let d = precess_core::ode::attitude::euler_rates([0.5, 2.0, 3.0], &w, &Vector3::zeros());
/// approx::assert_relative_eq!(d.y, (3.0 - 0.5) / 2.0 * 0.9 * 1.0);
/// ```
pub fn euler_rates(i: [f64; 3], w: &Vector3<f64>, g: &Vector3<f64>) -> Vector3<f64> {
    let l = Vector3::new(i[0] * w.x, i[1] * w.y, i[2] * w.z);
    let r = l.cross(w) + g;
    Vector3::new(r.x / i[0], r.y / i[1], r.z / i[2])
}

/// Checks the initial data of an attitude state.
///
/// # Errors
/// [`OdeError::NonFiniteInitialState`] for NaN or ∞ in q or ω.
pub fn check_attitude(s: &Attitude) -> Result<(), OdeError> {
    check_finite(s.q.quaternion().coords.as_slice())?;
    check_finite(s.omega.as_slice())
}

/// Checks the initial data of a rigid state.
///
/// # Errors
/// [`OdeError::NonFiniteInitialState`] for NaN or ∞ in any component.
pub fn check_rigid(s: &RigidState) -> Result<(), OdeError> {
    check_finite(s.x.as_slice())?;
    check_finite(s.v.as_slice())?;
    check_attitude(&Attitude {
        q: s.q,
        omega: s.omega,
    })
}

/// Checks a model's moments (mass 1 stands in where only inertia matters).
///
/// # Errors
/// [`OdeError::InvalidInertia`].
pub fn check_model_inertia(mass: f64, inertia: [f64; 3]) -> Result<(), OdeError> {
    check_inertia(mass, inertia)
}
