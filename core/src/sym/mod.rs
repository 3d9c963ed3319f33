//! The symbolic engine: an arena of hash-consed expressions in a canonical form.
//!
//! - [`Arena`] holds every node once; an [`ExprId`] is a handle, and equal canonical
//!   expressions have equal ids.
//! - Constants are exact [`Rational`]s: a decimal literal such as `0.03` is 3/100.
//! - Sums and products are n-ary, flat and sorted, with like terms and like factors collected
//!   and constants folded; `sin² u` is rewritten `1 − cos² u`, so polynomials in the sines and
//!   cosines of the angles have one expanded form ([`Arena::expand`]) and zero-equivalence of
//!   such polynomials is exact.
//! - Partial derivatives ([`Arena::diff`]) are memoised per node; [`Arena::dt`] is the total
//!   time derivative over coordinates and their rates.
//! - [`mat3`] holds the small matrix algebra (products, cross and dot, determinants) that
//!   kinematics is written in.
//! - Every walk is iterative over [`Arena::post_order`] (children through
//!   [`Node::children`]), so no depth of nesting overflows the stack.
//! - [`Arena::abbreviate`] names a large time-independent expression (an inertia entry) so
//!   that derivations over it stay small; [`Arena::is_zero`] sees through the names.
//!
//! See `docs/symbolic.md` for the canonical form in full.

mod abbreviate;
mod arena;
mod build;
mod cancel;
mod diff;
mod display;
mod error;
mod eval;
mod expand;
mod func;
pub mod functions;
mod hash;
mod literal;
pub mod mat3;
mod memo;
mod monomial;
mod node;
mod rational;
pub(crate) mod series;
mod substitute;
mod walk;
mod zero;

pub use arena::{Arena, ExprId, Symbol, SymbolId, SymbolKind};
pub use cancel::MAX_DIVIDED_DEGREE;
pub use error::SymError;
pub use expand::MAX_EXPANDED_TERMS;
pub use functions::Func;
pub use hash::{IdHasher, IdMap};
pub use literal::parse_decimal;
pub use node::Node;
pub use rational::Rational;
