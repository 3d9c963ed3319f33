//! Closed forms of the symmetric top: the heavy top's conserved quantities, nutation,
//! precession and sleeping threshold, and the torque-free body's cones.
//!
//! These sit beside the scene they describe and check it: `tests/top_theory.rs` holds them
//! against DOP853 runs of a derived top. The derivations are in `docs/theory.md`.

mod cubic;
mod derived;
mod error;
mod heavy;
mod motion;
mod torque_free;

pub(crate) use derived::derived_theory;
pub use error::TheoryError;
pub use heavy::{
    HeavyTopTheory, STEADY_TOLERANCE, SYMMETRY_TOLERANCE, SleepingTop, SteadyPrecession,
};
pub use motion::HeavyTopMotion;
pub use torque_free::TorqueFreeSymmetric;
