//! The state array of a body on a table, one layout for every contact law, so a stick–slip
//! run switches law without changing its state.
//!
//! The height of the centre of mass and its vertical velocity are not states: contact fixes
//! them as functions of the attitude and ω (a holonomic constraint and its derivative).

use nalgebra::{Quaternion, UnitQuaternion};

/// The length of the state array: horizontal position (2), horizontal velocity (2),
/// quaternion (4), ω (3).
pub const STATE_LEN: usize = 11;

/// Where each part sits in the state array `[x, y, vx, vy, q_w, q_x, q_y, q_z, ω₁, ω₂, ω₃]`.
pub mod layout {
    /// The horizontal position of the centre of mass, space axes: `y[POSITION..POSITION + 2]`.
    pub const POSITION: usize = 0;
    /// Its horizontal velocity, space axes. Under rolling it follows from ω and the attitude
    /// (it is integrated all the same, so the laws share one layout).
    pub const VELOCITY: usize = 2;
    /// The attitude quaternion `[w, x, y, z]`, description to space axes.
    pub const QUATERNION: usize = 4;
    /// The body angular velocity, description axes.
    pub const OMEGA: usize = 8;
}

/// The attitude of a state array, its quaternion normalised.
pub fn attitude_of(y: &[f64; STATE_LEN]) -> UnitQuaternion<f64> {
    let at = layout::QUATERNION;
    UnitQuaternion::new_normalize(Quaternion::new(y[at], y[at + 1], y[at + 2], y[at + 3]))
}
