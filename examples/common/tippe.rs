//! The tippe top of `tippe_top` and `tippe_sweep`: declared once, so that the sweep runs the
//! same body the single run does. Included by path (`#[path = "common/tippe.rs"] mod tippe;`).

#![allow(dead_code)] // each example uses the part it needs

use precess::contact::STATE_LEN;
use precess::contact::theory::TippeTop;
use precess::nalgebra::{UnitQuaternion, Vector3};
use precess::prelude::RigidBody;

/// The sphere's radius R [m].
pub const RADIUS: f64 = 0.02;
/// The eccentricity α: the centre of mass is αR below the sphere's centre.
pub const ALPHA: f64 = 0.3;
/// The mass M [kg].
pub const MASS: f64 = 0.02;
/// Gravity g [m/s²].
pub const GRAVITY: f64 = 9.81;

/// The top: mass M = 20 g with its centre of mass at the origin, I₁ = 0.35 M R² and
/// I₃ = 0.4 M R² (R = 2 cm), a sphere of radius R centred αR = 6 mm above the centre of mass,
/// gliding with viscous friction F = −c u on the slip u of its contact point, c = `viscous`
/// [kg/s] (a run-time parameter: the sweep changes it).
#[derive(RigidBody)]
#[rigid(body(
    mass = 0.02,
    inertia = diag(0.35 * 0.02 * 0.02 * 0.02, 0.35 * 0.02 * 0.02 * 0.02, 0.4 * 0.02 * 0.02 * 0.02),
))]
#[contact(
    surface = sphere(radius = 0.02, center = [0.0, 0.0, 0.3 * 0.02]),
    law = sliding(viscous = viscous),
    gravity = 9.81,
)]
pub struct Top {
    /// The viscous friction coefficient c [kg/s].
    pub viscous: f64,
}

/// The closed forms of the same top (`contact::theory::TippeTop`), from the numbers as
/// written here, not as the derive read them.
pub fn theory() -> TippeTop {
    let (m, r) = (MASS, RADIUS);
    TippeTop {
        radius: r,
        alpha: ALPHA,
        mass: m,
        i1: 0.35 * m * r * r,
        i3: 0.4 * m * r * r,
        gravity: GRAVITY,
    }
}

/// The start: the stem up, the symmetry axis `tilt` rad off the vertical (about space x),
/// spinning at `spin` rad/s about it, the centre of mass at rest.
pub fn start(tilt: f64, spin: f64) -> [f64; STATE_LEN] {
    let q = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), tilt);
    let q = q.quaternion();
    let mut y0 = [0.0; STATE_LEN];
    y0[4..8].copy_from_slice(&[q.w, q.i, q.j, q.k]);
    y0[8..11].copy_from_slice(&[0.0, 0.0, spin]);
    y0
}

/// cos θ of the symmetry axis with the vertical (γ₃): positive stem up, negative once the
/// top has turned over.
pub fn axis_up(y: &[f64; STATE_LEN]) -> f64 {
    (precess::contact::attitude_of(y) * Vector3::z()).z
}
