//! The states of a rigid body (attitude and angular velocity; the whole free body; attitude
//! and angular momentum for the splittings) and the models (torques, forces) that drive them.

use nalgebra::{UnitQuaternion, Vector3};

use crate::ode::{OdeError, check_finite};

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

/// A rigid body's state in the splitting methods: attitude and body angular momentum m = I ω.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyMomentum {
    /// Body-to-space rotation.
    pub q: UnitQuaternion<f64>,
    /// Body angular momentum (principal axes).
    pub m: Vector3<f64>,
}

/// How far |q| may be from 1 in a state handed to a stepper (a `UnitQuaternion` built
/// unchecked from data): beyond this it is no rotation, and is refused rather than
/// normalised silently.
pub(crate) const UNIT_NORM_TOLERANCE: f64 = 1e-6;

/// Checks that a finite attitude quaternion has unit norm.
///
/// # Errors
/// [`OdeError::NotUnitQuaternion`].
pub(crate) fn check_unit(q: &UnitQuaternion<f64>) -> Result<(), OdeError> {
    let norm = q.quaternion().norm();
    if (norm - 1.0).abs() <= UNIT_NORM_TOLERANCE {
        Ok(())
    } else {
        Err(OdeError::NotUnitQuaternion { norm })
    }
}

/// Checks the initial data of an attitude state.
///
/// # Errors
/// [`OdeError::NonFiniteInitialState`] for NaN or ∞ in q or ω,
/// [`OdeError::NotUnitQuaternion`].
pub(crate) fn check_attitude(s: &Attitude) -> Result<(), OdeError> {
    check_finite(s.q.quaternion().coords.as_slice())?;
    check_finite(s.omega.as_slice())?;
    check_unit(&s.q)
}

/// Checks the initial data of a rigid state.
///
/// # Errors
/// [`OdeError::NonFiniteInitialState`] for NaN or ∞ in any component,
/// [`OdeError::NotUnitQuaternion`].
pub(crate) fn check_rigid(s: &RigidState) -> Result<(), OdeError> {
    check_finite(s.x.as_slice())?;
    check_finite(s.v.as_slice())?;
    check_attitude(&Attitude {
        q: s.q,
        omega: s.omega,
    })
}

/// Checks the state of the splittings.
///
/// # Errors
/// [`OdeError::NonFiniteInitialState`] for NaN or ∞ in q or m,
/// [`OdeError::NotUnitQuaternion`].
pub(crate) fn check_momentum(y: &BodyMomentum) -> Result<(), OdeError> {
    check_finite(y.q.quaternion().coords.as_slice())?;
    check_finite(y.m.as_slice())?;
    check_unit(&y.q)
}

/// `true` when q and m are finite (the per-step check of the splittings; |q| = 1 holds by
/// construction there).
pub(crate) fn momentum_is_finite(y: &BodyMomentum) -> bool {
    y.q.coords.iter().chain(y.m.iter()).all(|v| v.is_finite())
}
