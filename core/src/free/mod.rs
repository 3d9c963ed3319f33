//! The free body: the centre of mass and the attitude under declared forces.
//!
//! A scene over the engine, in one place:
//! - [`FreeScene`] holds the forces and torques as data (uniform gravity, body- and
//!   space-fixed forces at body points, body- and space-fixed torques, linear drag on the
//!   centre of mass and on the rotation, user functions, an [`AppliedWrench`] whose frame its
//!   constructor names) and [`FreeScene::derive`] derives the
//!   right-hand side, the wrench, the energy, its power balance and the momenta symbolically,
//!   so only what is declared appears; a [`Rotor`] makes the body a gyrostat; [`cm_frame`] decides the principal frame about the
//!   centre of mass.
//! - [`FreeState`] is the state with its frames in its names; [`layout`] places it in the
//!   array of [`STATE_LEN`] numbers the steppers integrate.
//! - [`FreeDynamics`] is the trait `#[free(...)]` implements; [`FreeSystem`] and
//!   [`FreeLie`] run a derived body with the adaptive pairs, RK4 and RKMK4, and
//!   [`FreeFlight`] integrates it with the quaternion projected after every step.
//! - [`FreeExact`] is the exact motion under uniform gravity alone (parabola and torque-free
//!   attitude); [`FreeModel`] a derivation interpreted at run time.
//! - [`FreeQuantities`] gives a run's trajectory the energy, power and the sizes of the
//!   momenta per sample, named as a top's and a mechanism's.

mod checks;
mod derivation;
mod dynamics;
mod error;
mod frame;
mod interpreted;
mod quantities;
mod rotor;
mod run;
mod scene;
mod state;
mod system;
mod theory;
mod wrench;

pub use crate::rigid::{DrivenRotor, Rotor};
pub use checks::attitude_of;
pub use derivation::FreeDerivation;
pub use dynamics::{FreeDynamics, Wrench};
pub use error::FreeError;
pub use frame::{CmFrame, cm_frame};
pub use interpreted::FreeModel;
pub use quantities::{FreeQuantities, STATE_NAMES};
pub use run::{Flight, FreeFlight, Projection};
pub use scene::{AppliedForce, ForcePoint, FreeScene};
pub use state::{FreeState, STATE_LEN, layout};
pub use system::{FreeLie, FreeSystem};
pub use theory::FreeExact;
pub use wrench::{AppliedWrench, WrenchInputs};
