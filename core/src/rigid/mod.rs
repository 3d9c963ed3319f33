//! Rigid-body motion shared by the scenes: Euler-angle sequences, their rotation and rate
//! matrices, and the angles of a numeric attitude.

mod angles;

pub use angles::{AngleSequence, angles_from_rotation, elementary};
