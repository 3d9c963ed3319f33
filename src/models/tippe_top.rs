//! The tippe top: an eccentric sphere spun with its stem up glides on the table, turns over
//! and ends spinning on its stem. Its closed forms (the inversion condition, Jellett's
//! integral, the inverted state) are [`crate::contact::theory::TippeTop`].

use crate::contact::STATE_LEN;
use crate::contact::theory;
use crate::nalgebra::{UnitQuaternion, Vector3};
use crate::prelude::RigidBody;

/// The sphere's radius R \[m\].
pub const RADIUS: f64 = 0.02;
/// The eccentricity α: the centre of mass is αR below the sphere's centre.
pub const ALPHA: f64 = 0.3;
/// The mass M \[kg\].
pub const MASS: f64 = 0.02;
/// Gravity g \[m/s²\].
pub const GRAVITY: f64 = 9.81;

/// The tippe top: mass M = 20 g with its centre of mass at the origin, I₁ = 0.35 M R² and
/// I₃ = 0.4 M R² about it (I₁/I₃ = 0.875, inside the inversion range
/// 1 − α < I₁/I₃ < 1 + α), a sphere of radius R = 2 cm centred αR = 6 mm above the centre of
/// mass, gliding with viscous friction F = −c u on the slip u of its contact point
/// (Cohen 1977, Or 1994); c = `viscous` \[kg/s\] is a run-time parameter.
///
/// # Examples
///
/// The body the derive read agrees with the closed forms' numbers:
///
/// ```
/// use approx::assert_relative_eq;
/// use precess::models::TippeTop;
/// use precess::prelude::RigidBody;
///
/// let top = TippeTop { viscous: 0.1 };
/// let theory = TippeTop::theory();
/// assert_relative_eq!(top.principal().moments[0], theory.i1, max_relative = 1e-14);
/// assert_relative_eq!(top.principal().moments[2], theory.i3, max_relative = 1e-14);
/// assert!(theory.inverts());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, RigidBody)]
#[rigid(body(
    mass = 0.02,
    inertia = diag(0.35 * 0.02 * 0.02 * 0.02, 0.35 * 0.02 * 0.02 * 0.02, 0.4 * 0.02 * 0.02 * 0.02),
))]
#[contact(
    surface = sphere(radius = 0.02, center = [0.0, 0.0, 0.3 * 0.02]),
    law = sliding(viscous = viscous),
    gravity = 9.81,
)]
pub struct TippeTop {
    /// The viscous friction coefficient c \[kg/s\].
    pub viscous: f64,
}

impl TippeTop {
    /// The closed forms of the same top, from the constants of this module (not from what
    /// the derive read, so that comparing the two checks the derive).
    pub fn theory() -> theory::TippeTop {
        let (m, r) = (MASS, RADIUS);
        theory::TippeTop {
            radius: r,
            alpha: ALPHA,
            mass: m,
            i1: 0.35 * m * r * r,
            i3: 0.4 * m * r * r,
            gravity: GRAVITY,
        }
    }

    /// A start: the stem up, the symmetry axis `tilt` rad off the vertical (about space x),
    /// spinning at `spin` rad/s about it, the centre of mass at rest at the origin.
    pub fn start(tilt: f64, spin: f64) -> [f64; STATE_LEN] {
        let q = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), tilt);
        let q = q.quaternion();
        let mut y0 = [0.0; STATE_LEN];
        y0[4..8].copy_from_slice(&[q.w, q.i, q.j, q.k]);
        y0[8..11].copy_from_slice(&[0.0, 0.0, spin]);
        y0
    }

    /// cos θ of the symmetry axis with the vertical (γ₃): positive stem up, negative once
    /// the top has turned over.
    pub fn axis_up(y: &[f64; STATE_LEN]) -> f64 {
        (crate::contact::attitude_of(y) * Vector3::z()).z
    }
}
