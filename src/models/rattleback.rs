//! The rattleback of Kane & Levinson (Int. J. Non-Linear Mech. 17 (1982) 175): an ellipsoid
//! whose axes of inertia are turned against its axes of shape. Spun one way it rocks, stops
//! and spins back; rolling without slip and without dissipation, it keeps its energy.

use crate::nalgebra::{UnitQuaternion, Vector3};
use crate::prelude::{ContactDynamics, ContactError, RigidBody};

/// Kane & Levinson's rattleback: M = 1 kg with its centre of mass at the origin; moments
/// A = 2e-4, B = 1.6e-3, C = 1.7e-3 kg m² and the product D = −2e-5 kg m² in the (x, y)
/// entries (the misalignment of mass and shape); a contact surface of semi-axes a = 0.2,
/// b = 0.03, c = 0.02 m whose centre is h = 0.01 m above the centre of mass; rolling
/// without slip under g = 9.81 m/s².
///
/// # Examples
///
/// Upright, the centre of mass stands c − h = 0.01 m above the table; tilted by ε about
/// each horizontal axis it rises by (a²/c − (c − h)) ε²/2 + (b²/c − (c − h)) ε²/2 to
/// second order (a²/c and b²/c the radii of curvature at the bottom):
///
/// ```
/// use approx::assert_relative_eq;
/// use precess::contact::ContactDynamics;
/// use precess::models::Rattleback;
///
/// let tilt = 0.5_f64.to_radians();
/// let y0 = Rattleback.release(tilt, -5.0)?;
/// let (a, b, c, h) = (0.2, 0.03, 0.02, 0.01);
/// let rise = (a * a / c + b * b / c - 2.0 * (c - h)) * tilt * tilt / 2.0;
/// assert_relative_eq!(Rattleback.contact(&y0).height, c - h + rise, max_relative = 1e-4);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, RigidBody)]
#[rigid(body(
    mass = 1.0,
    inertia = [[2e-4, -2e-5, 0.0], [-2e-5, 1.6e-3, 0.0], [0.0, 0.0, 1.7e-3]],
))]
#[contact(
    surface = ellipsoid(semi_axes = [0.2, 0.03, 0.02], center = [0.0, 0.0, 0.01]),
    law = rolling,
    gravity = 9.81,
)]
pub struct Rattleback;

impl Rattleback {
    /// Kane & Levinson's start: tilted `tilt` rad about space x and then about y, at rest
    /// on the table but for a spin `spin` rad/s about the body's short axis (their run:
    /// 0.5° and −5 rad/s).
    ///
    /// # Errors
    /// As [`ContactDynamics::rolling_state`] (a non-finite value).
    pub fn release(
        &self,
        tilt: f64,
        spin: f64,
    ) -> Result<[f64; crate::contact::STATE_LEN], ContactError> {
        let q = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), tilt)
            * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), tilt);
        self.rolling_state([0.0, 0.0], &q, &Vector3::new(0.0, 0.0, spin))
    }
}
