//! Fast tops: a body about its pivot under gravity as a splitting of the exact free-body
//! flow and gravity kicks, in the principal frame of its inertia about the pivot.

use nalgebra::{Rotation3, UnitQuaternion, Vector3};

use super::dynamics::TopDynamics;
use super::error::TopError;
use crate::body::RigidBody;
use crate::ode::{OdeError, body_quantity, refused};
use crate::rigid::{BodyMomentum, ExactFreeFlow, FreeFlow, Gravity, PotentialSplitting};

/// A body about its pivot as a [`PotentialSplitting`]: the exact free-body flow with the
/// principal moments about the pivot, and gravity kicks with the centre of mass expressed in
/// the principal frame. The splitting's attitude maps principal axes to space; convert with
/// [`FastTop::to_principal`] and [`FastTop::to_description`].
///
/// A fast spin does not limit the step of the free flow; the step is set by the nutation.
///
/// # Examples
///
/// Steady precession of the symmetric heavy top (I1 = 1, I3 = ½ about the pivot,
/// M g l = 1) at θ = 60° with ω3 = 10: the figure axis turns about the vertical at
/// Ω = 0.204168476687 rad/s (the slow root of I1 cos θ Ω² − I3 ω3 Ω + M g l = 0); the
/// splitting follows it at second order with a step of 5 ms:
///
/// ```
/// use approx::assert_relative_eq;
/// use precess::prelude::*;
/// use precess::top::FastTop;
///
/// #[derive(RigidBody)]
/// #[rigid(
///     body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
///     pivot = [0.0, 0.0, 0.0],
/// )]
/// #[top(gravity = 1.0)]
/// struct Heavy;
///
/// let fast = FastTop::new(&Heavy, 1.0)?;
/// let (theta, omega_p) = (std::f64::consts::FRAC_PI_3, 0.204168476687);
/// let q0 = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), theta);
/// let w0 = Vector3::new(0.0, omega_p * theta.sin(), 10.0);
/// let mut y = fast.to_principal(&q0, &w0);
/// fast.splitting.run(&mut y, 0.005, 400)?;
/// let (q, _) = fast.to_description(&y);
/// let phi = omega_p * 2.0;
/// let expected = Vector3::new(theta.sin() * phi.sin(), -theta.sin() * phi.cos(), theta.cos());
/// assert_relative_eq!(q * Vector3::z(), expected, epsilon = 1e-5);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct FastTop {
    /// The splitting.
    pub splitting: PotentialSplitting<Gravity, ExactFreeFlow>,
    /// From principal to description axes.
    pub principal_to_description: Rotation3<f64>,
}

impl FastTop {
    /// The fast-top splitting of `body` (which should have a pivot: the reference point) under
    /// gravity `g` along −z.
    ///
    /// It reads the body alone: a derived top's rotors, damping and torques are not seen.
    /// [`FastTop::of_top`] takes a derived top and refuses what the splitting does not model.
    ///
    /// # Errors
    /// [`OdeError::InvalidSystemParameter`] for a body that breaks a rule of its description
    /// for its field values ([`RigidBody::validate`]: a negative mass, say, which would turn
    /// the weight upward while the moments stay positive); [`OdeError::InvalidInertia`] if
    /// the principal moments are not positive; [`OdeError::InvalidParameter`] for a
    /// non-finite or negative `g`.
    pub fn new(body: &impl RigidBody, g: f64) -> Result<FastTop, OdeError> {
        if !(g.is_finite() && g >= 0.0) {
            return Err(OdeError::InvalidParameter {
                name: "g",
                value: g,
            });
        }
        body.validate()
            .map_err(|e| refused(body_quantity(&e), &e))?;
        let principal = body.principal();
        let p = principal.rotation;
        let lever = body.center_of_mass() - body.reference_point();
        let m = principal.moments;
        Ok(FastTop {
            splitting: PotentialSplitting {
                free: ExactFreeFlow::new([m[0], m[1], m[2]])?,
                potential: Gravity {
                    weight: body.mass() * g,
                    c: p.inverse() * lever,
                },
            },
            principal_to_description: p,
        })
    }

    /// The fast-top splitting of a derived top under its declared gravity, its parameters
    /// checked first ([`TopDynamics::check_all`]).
    ///
    /// ```
    /// use precess::prelude::*;
    /// use precess::top::{FastTop, TopError};
    ///
    /// #[derive(RigidBody)]
    /// #[rigid(body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot), pivot = [0.0, 0.0, 0.0])]
    /// #[top(gravity = 1.0, rotor(axis = [0, 0, 1], inertia = 0.1, rate = 10))]
    /// struct Gyrotop;
    ///
    /// assert_eq!(
    ///     FastTop::of_top(&Gyrotop),
    ///     Err(TopError::FastTopBeyondGravity { declared: "a rotor" })
    /// );
    /// ```
    ///
    /// # Errors
    /// [`TopError::FastTopBeyondGravity`] for a top with a rotor or a torque other than
    /// gravity (the splitting models the weight alone); as [`TopDynamics::check_all`] and
    /// [`FastTop::new`] (in [`TopError::Ode`]).
    pub fn of_top<T: TopDynamics>(top: &T) -> Result<FastTop, TopError> {
        let declared = if T::ROTORS > 0 {
            Some("a rotor")
        } else {
            T::BEYOND_GRAVITY
        };
        if let Some(declared) = declared {
            return Err(TopError::FastTopBeyondGravity { declared });
        }
        top.check_all()?;
        Ok(FastTop::new(
            top,
            top.top_parameters().gravity.unwrap_or(0.0),
        )?)
    }

    /// The splitting's state for a description-frame attitude (body to space) and body ω
    /// (description axes): m = I ω in principal axes, attitude R P.
    pub fn to_principal(
        &self,
        attitude: &UnitQuaternion<f64>,
        omega: &Vector3<f64>,
    ) -> BodyMomentum {
        let p = UnitQuaternion::from_rotation_matrix(&self.principal_to_description);
        let w = p.inverse() * omega;
        let i = self.splitting.free.inertia();
        BodyMomentum {
            q: attitude * p,
            m: Vector3::new(i[0] * w.x, i[1] * w.y, i[2] * w.z),
        }
    }

    /// The description-frame attitude and body ω of a splitting state.
    pub fn to_description(&self, y: &BodyMomentum) -> (UnitQuaternion<f64>, Vector3<f64>) {
        let p = UnitQuaternion::from_rotation_matrix(&self.principal_to_description);
        let i = self.splitting.free.inertia();
        let w = Vector3::new(y.m.x / i[0], y.m.y / i[1], y.m.z / i[2]);
        (y.q * p.inverse(), p * w)
    }
}
