//! The `RigidBody` derive of precess.
#![forbid(unsafe_code)]
#![warn(missing_docs)]
