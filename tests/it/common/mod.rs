//! Helpers shared by the integration tests.

pub mod body;
pub mod eulerian;
pub mod free_bodies;
pub mod free_body;
pub mod latex;
pub mod mechanism;
pub mod rng;
pub mod tops;
pub mod tree;
