//! Closed kinematic loops of a mechanism: a four-bar linkage, a slider-crank.
//!
//! - [`LoopClosure`] joins a point of one body to a point of another body (or of the
//!   ground): the tree's coordinates are then tied by φ(q) = P_a(q) − P_b(q) = 0, three rows
//!   in ground axes, the identically zero ones left out (a planar loop keeps two).
//! - [`MechanismScene::derive_loops`](crate::mechanism::MechanismScene::derive_loops)
//!   derives M(q) and f(q, q̇) of the tree (Kane's method), the closure rows with the
//!   engine's [`Constraints::holonomic`](crate::lagrange::Constraints::holonomic) (φ, its
//!   Jacobian A = ∂φ/∂q) and Ȧq̇, and each planar loop's sides for the closure rule
//!   [`check_loop_sides`].
//! - [`LoopDynamics`] finishes the projection in floating point with the engine's
//!   [`Partition`](crate::lagrange::Partition): the dependent coordinates are chosen at each
//!   configuration by pivoting on A (so a crank at a dead point hands the motion to the
//!   rocker instead of stopping), the multipliers are the closing joints' reactions, and
//!   [`LoopDynamics::close_loop`] pulls a state back onto φ = 0 and A q̇ = 0. The derive
//!   implements it with straight-line code for `closes = ..` bodies.
//! - [`LoopDynamics::closed_run`] runs it in the one run loop, which projects after every
//!   step and halts with a [`LoopHalt`] where the loop cannot be closed.

mod derivation;
mod dynamics;
mod run;
mod scene;

pub use derivation::LoopDerivation;
pub use dynamics::{LOOP_TOLERANCE, LoopDynamics, LoopSystem, MassForcing, best_partition};
pub use run::{LoopHalt, LoopRun};
pub use scene::{LoopClosure, LoopSide, check_loop_sides};
