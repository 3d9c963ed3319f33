//! The Euler–Lagrange engine: from a symbolic Lagrangian and generalised forces to
//! `M(q) q̈ = f(q, q̇)` and its solution. Nothing here knows which scene it serves; the
//! scenes (the top in [`crate::top`]) build a Lagrangian and call in.
//!
//! - [`EquationsOfMotion::derive`] forms the mass matrix, the forcing and the residuals, all
//!   in trig-canonical form so structural zeros are exact.
//! - [`EquationsOfMotion::solve`] solves block by block with adjugates, sharing f, the
//!   adjugate entries and one division per block, and keeps the cheapest of three equal
//!   forms.

mod block_solve;
mod equations;
mod error;

pub use block_solve::{Accelerations, MAX_BLOCK};
pub use equations::{Coordinates, EquationsOfMotion};
pub use error::LagrangeError;
