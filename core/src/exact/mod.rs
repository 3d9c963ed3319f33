//! Exact solutions: Jacobi elliptic functions and Carlson integrals from the complementary
//! parameter, the torque-free rigid body's angular momentum and attitude in closed form,
//! and the exact free-body flow as a splitting step.

pub mod attitude;
pub mod carlson;
pub mod dd;
pub mod elliptic;
pub mod error;
pub mod free_body;

pub use attitude::{FreeBodyAttitude, free_body_flow_attitude};
pub use elliptic::{Jacobi, ellip_k, sncndn};
pub use error::ExactError;
pub use free_body::{FreeBodyExact, Regime, free_body_flow};
