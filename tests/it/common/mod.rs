//! Helpers shared by the integration tests.

pub mod body;
pub mod dips;
pub mod eulerian;
pub mod flow;
pub mod free_bodies;
pub mod latex;
pub mod mechanism;
pub mod tops;
pub mod tree;

/// The seeded generator, shared with the benches.
pub use precess_testkit::rng;
