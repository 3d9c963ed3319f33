//! The Euler–Lagrange engine: from a symbolic Lagrangian and generalised forces to
//! `M(q) q̈ = f(q, q̇)` and its solution. Nothing here knows which scene it serves; the
//! scenes (the top in [`crate::top`]) build a Lagrangian and call in.
//!
//! - [`EquationsOfMotion::derive`] forms the mass matrix, the forcing and the residuals, all
//!   in trig-canonical form so structural zeros are exact.
//! - [`EquationsOfMotion::solve`] solves block by block with adjugates, sharing f, the
//!   adjugate entries and one division per block, and keeps the cheapest of three equal
//!   forms.
//! - [`Constraints`] holds velocity constraints `A(q, t) q̇ + b(q, t) = 0` (nonholonomic
//!   rows, or holonomic loops φ(q, t) = 0 differentiated); [`EquationsOfMotion::constrain`]
//!   eliminates the dependent speeds (Maggi's equations) and derives the multipliers;
//!   [`ConstrainedModel`] runs the result and closes loops by coordinate partitioning.
//!   `docs/constraints.md` says why this form.
//! - [`Partition`] is the same projection in floating point, for constraint blocks whose
//!   symbolic elimination swells (the Whipple bicycle's rolling wheels).

mod augmented;
mod block_solve;
mod constraints;
mod eliminate;
mod equations;
mod error;
mod model;
mod partition;
mod projection;

pub use augmented::op_count;
pub use block_solve::{Accelerations, MAX_BLOCK};
pub use constraints::Constraints;
pub use eliminate::ConstrainedEquations;
pub use equations::{Coordinates, EquationsOfMotion};
pub use error::LagrangeError;
pub use model::{ConstrainedModel, ConstrainedSystem};
pub use partition::{MAX_NEWTON, SINGULAR_BLOCK, START_RESIDUAL};
pub(crate) use projection::{Inverted, solve};
pub use projection::{Partition, Projected};
