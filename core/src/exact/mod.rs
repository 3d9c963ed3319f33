//! Exact solutions: Jacobi elliptic functions and Carlson integrals from the complementary
//! parameter, the torque-free rigid body's angular momentum and attitude in closed form,
//! and the exact free-body flow as a splitting step.
//!
//! Carlson's symmetric integrals and the Legendre integrals built on them form the namespace
//! [`carlson`]; everything else is re-exported here.

mod attitude;
pub mod carlson;
mod dd_functions;
mod double_double;
mod elliptic;
mod error;
mod free_body;
mod scaling;

pub use attitude::{FreeBodyAttitude, free_body_flow_attitude};
pub(crate) use dd_functions::rational;
pub use double_double::Dd;
pub use elliptic::{Jacobi, MAX_ARGUMENT, ellip_k, sncndn};
pub use error::ExactError;
pub(crate) use free_body::array;
pub use free_body::{FreeBodyExact, Regime, free_body_flow};
