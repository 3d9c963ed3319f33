//! The state of a free body: the centre of mass and its velocity in space axes, the attitude
//! as a unit quaternion from principal to space axes, and ω in principal axes; as a struct
//! with the frames in its names and as the array the steppers integrate.

use nalgebra::{Quaternion, UnitQuaternion, Vector3};

use super::checks::{attitude_of, finite};
use super::error::FreeError;
use crate::body::Principal;
use crate::rigid::{BodyMomentum, RigidState};

/// The length of the state array: position (3), velocity (3), quaternion (4), ω (3).
pub const STATE_LEN: usize = 13;

/// Where each part sits in the state array `[x, y, z, vx, vy, vz, q_w, q_x, q_y, q_z, ω₁, ω₂, ω₃]`.
pub mod layout {
    /// The centre of mass, space axes: `y[POSITION..POSITION + 3]`.
    pub const POSITION: usize = 0;
    /// Its velocity, space axes.
    pub const VELOCITY: usize = 3;
    /// The attitude quaternion `[w, x, y, z]`, principal to space.
    pub const QUATERNION: usize = 6;
    /// The body angular velocity, principal axes.
    pub const OMEGA: usize = 10;
}

/// A free body's state.
///
/// Frames: `position` and `velocity` are the centre of mass in space axes; `attitude` turns
/// principal axes (of the inertia about the centre of mass) into space axes; `omega_principal`
/// is the body angular velocity in principal axes. The description frame is one constant
/// rotation away ([`Principal::rotation`], principal → description): see
/// [`FreeState::attitude_description`] and [`FreeState::from_description`].
///
/// ```
/// use approx::assert_relative_eq;
/// use nalgebra::{UnitQuaternion, Vector3};
/// use precess_core::free::FreeState;
///
/// let s = FreeState {
///     position: Vector3::new(1.0, 2.0, 3.0),
///     velocity: Vector3::new(0.0, 0.0, 5.0),
///     attitude: UnitQuaternion::from_euler_angles(0.1, 0.2, 0.3),
///     omega_principal: Vector3::new(0.0, 7.0, 0.1),
/// };
/// let back = FreeState::from_array(&s.to_array())?;
/// assert_relative_eq!(back.attitude, s.attitude, epsilon = 1e-15);
/// // A zero quaternion names no attitude.
/// let mut y = s.to_array();
/// y[6..10].copy_from_slice(&[0.0; 4]);
/// assert!(FreeState::from_array(&y).is_err());
/// # Ok::<(), precess_core::free::FreeError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FreeState {
    /// Centre of mass, space axes.
    pub position: Vector3<f64>,
    /// Velocity of the centre of mass, space axes.
    pub velocity: Vector3<f64>,
    /// Principal axes to space axes.
    pub attitude: UnitQuaternion<f64>,
    /// Body angular velocity, principal axes.
    pub omega_principal: Vector3<f64>,
}

impl FreeState {
    /// At rest at the origin, principal axes along the space axes.
    pub fn at_rest() -> FreeState {
        FreeState {
            position: Vector3::zeros(),
            velocity: Vector3::zeros(),
            attitude: UnitQuaternion::identity(),
            omega_principal: Vector3::zeros(),
        }
    }

    /// The state array the steppers integrate.
    pub fn to_array(&self) -> [f64; STATE_LEN] {
        let (x, v, q, w) = (
            self.position,
            self.velocity,
            self.attitude.quaternion(),
            self.omega_principal,
        );
        [
            x.x, x.y, x.z, v.x, v.y, v.z, q.w, q.i, q.j, q.k, w.x, w.y, w.z,
        ]
    }

    /// The state of an array, its quaternion normalised (a quaternion of any non-zero size
    /// names its attitude).
    ///
    /// # Errors
    /// [`FreeError::NonFinite`] naming the part that holds NaN or ±∞,
    /// [`FreeError::ZeroQuaternion`] for a zero quaternion.
    pub fn from_array(y: &[f64; STATE_LEN]) -> Result<FreeState, FreeError> {
        let part = |at: usize| Vector3::new(y[at], y[at + 1], y[at + 2]);
        let parts = [
            ("position", part(layout::POSITION)),
            ("velocity", part(layout::VELOCITY)),
            ("body angular velocity ω", part(layout::OMEGA)),
        ];
        for (quantity, v) in parts {
            finite(quantity, v.as_slice())?;
        }
        Ok(FreeState {
            position: parts[0].1,
            velocity: parts[1].1,
            attitude: attitude_of(y)?,
            omega_principal: parts[2].1,
        })
    }

    /// The state of an array without checks, for generated code in a stepper's inner loop
    /// (a user force function's argument): the quaternion normalised, NaN if it is zero. The
    /// array may be longer (a body's driven rotors' rates follow the 13 slots); a slot a
    /// shorter one lacks reads NaN.
    pub fn from_array_unchecked<const N: usize>(y: &[f64; N]) -> FreeState {
        let at = |k: usize| y.get(k).copied().unwrap_or(f64::NAN);
        let part = |k: usize| Vector3::new(at(k), at(k + 1), at(k + 2));
        let q = layout::QUATERNION;
        FreeState {
            position: part(layout::POSITION),
            velocity: part(layout::VELOCITY),
            attitude: UnitQuaternion::new_normalize(Quaternion::new(
                at(q),
                at(q + 1),
                at(q + 2),
                at(q + 3),
            )),
            omega_principal: part(layout::OMEGA),
        }
    }

    /// The state of a body described in its description frame: the attitude of the
    /// description axes and ω in description axes, turned into principal axes with the
    /// body's principal frame (about its centre of mass).
    pub fn from_description(
        position: impl Into<Vector3<f64>>,
        velocity: impl Into<Vector3<f64>>,
        attitude_description: &UnitQuaternion<f64>,
        omega_description: impl Into<Vector3<f64>>,
        principal: &Principal,
    ) -> FreeState {
        let to_description = UnitQuaternion::from_rotation_matrix(&principal.rotation);
        FreeState {
            position: position.into(),
            velocity: velocity.into(),
            attitude: attitude_description * to_description,
            omega_principal: principal.rotation.inverse() * omega_description.into(),
        }
    }

    /// The attitude of the description axes (description → space): the principal attitude
    /// followed back through the constant principal frame.
    pub fn attitude_description(&self, principal: &Principal) -> UnitQuaternion<f64> {
        self.attitude * UnitQuaternion::from_rotation_matrix(&principal.rotation).inverse()
    }

    /// ω in description axes.
    pub fn omega_description(&self, principal: &Principal) -> Vector3<f64> {
        principal.rotation * self.omega_principal
    }

    /// ω in space axes.
    pub fn omega_space(&self) -> Vector3<f64> {
        self.attitude * self.omega_principal
    }

    /// The attitude and body angular momentum m = I ω (principal moments `moments`), the
    /// state of the splittings and of the exact free-body flow.
    pub fn body_momentum(&self, moments: &Vector3<f64>) -> BodyMomentum {
        BodyMomentum {
            q: self.attitude,
            m: moments.component_mul(&self.omega_principal),
        }
    }

    /// Checks that every part is finite and the quaternion a rotation (its norm within
    /// 1e-6 of 1, as the steppers require of a `UnitQuaternion`).
    ///
    /// # Errors
    /// [`FreeError::NonFinite`] naming the part, [`FreeError::Ode`] with
    /// [`crate::ode::OdeError::NotUnitQuaternion`] for a quaternion off the unit sphere.
    pub fn check(&self) -> Result<(), FreeError> {
        finite("position", self.position.as_slice())?;
        finite("velocity", self.velocity.as_slice())?;
        finite(
            "attitude quaternion",
            self.attitude.quaternion().coords.as_slice(),
        )?;
        finite("body angular velocity ω", self.omega_principal.as_slice())?;
        let norm = self.attitude.quaternion().norm();
        if (norm - 1.0).abs() > 1e-6 {
            return Err(crate::ode::OdeError::NotUnitQuaternion { norm }.into());
        }
        Ok(())
    }
}

impl From<FreeState> for RigidState {
    fn from(s: FreeState) -> RigidState {
        RigidState {
            x: s.position,
            v: s.velocity,
            q: s.attitude,
            omega: s.omega_principal,
        }
    }
}

impl From<RigidState> for FreeState {
    fn from(s: RigidState) -> FreeState {
        FreeState {
            position: s.x,
            velocity: s.v,
            attitude: s.q,
            omega_principal: s.omega,
        }
    }
}
