//! Geometric splitting methods for rigid bodies: the free body as exact axis rotations, and
//! a body under a potential as free flow plus kicks; both run as fixed-step methods under
//! [`crate::ode::FixedStepper`], with trajectories and events.

mod free;
mod potential;
mod stepping;

pub use free::{FreeBodySplitting, SplittingOrder};
pub use potential::{ExactFreeFlow, FreeFlow, Gravity, Potential, PotentialSplitting};
