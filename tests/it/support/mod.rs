//! Helpers shared by the integration tests.
#![allow(dead_code)]

pub mod body;
pub mod eulerian;
pub mod free_body;
pub mod latex;
pub mod rng;
pub mod tops;
pub mod tree;
