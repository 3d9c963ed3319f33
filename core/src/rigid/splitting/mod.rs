//! Geometric splitting methods for rigid bodies: the free body as exact axis rotations, and
//! a body under a potential as free flow plus kicks.

mod free;
mod potential;

pub use free::{FreeBodySplitting, SplittingOrder};
pub use potential::{ExactFreeFlow, FreeFlow, Gravity, Potential, PotentialSplitting};
