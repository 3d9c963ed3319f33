//! precess: rigid-body dynamics derived symbolically at compile time.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub use precess_core as core_api;
