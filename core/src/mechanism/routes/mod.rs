//! The derivation routes, one algorithm per file (as Pinocchio keeps its algorithms):
//!
//! - [`lagrangian`]: T, V and Q, the Euler–Lagrange equations `M q̈ = f`, and the block
//!   adjugate solve for few coordinates ([`Route::Symbolic`]).
//! - [`factored`]: the unexpanded LDLᵀ of M and its two triangular solves
//!   ([`Route::Factored`]).
//! - [`kane`]: M and f by Kane's method, from the kinematics without differentiating T twice
//!   (the rolling derivation's route).
//! - [`recursive`]: the articulated-body algorithm written symbolically, O(n) operations
//!   ([`Route::Recursive`]).
//! - [`aba`]: the same algorithm numerically ([`MechanismAba`]), the generic reference the
//!   generated code is tested and benchmarked against.
//!
//! [`Route::Symbolic`]: crate::mechanism::Route::Symbolic
//! [`Route::Factored`]: crate::mechanism::Route::Factored
//! [`Route::Recursive`]: crate::mechanism::Route::Recursive
//! [`MechanismAba`]: crate::mechanism::MechanismAba

pub(crate) mod aba;
pub(crate) mod factored;
pub(crate) mod kane;
pub(crate) mod lagrangian;
pub mod recursive;
