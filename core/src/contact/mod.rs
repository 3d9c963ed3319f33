//! A body on a table: rolling and sliding contact with a horizontal plane.
//!
//! A scene over the engine, in one place:
//! - [`ContactScene`] holds the body's mass properties, the convex [`Surface`] it touches the
//!   table with and the [`ContactLaw`] (rolling, sliding under a [`Friction`], stick–slip);
//!   [`ContactScene::derive`] derives each phase's equations by Kane's method with ω as the
//!   generalised speeds ([`ContactDerivation`]).
//! - [`Surface::support`] gives the contact point as a closed-form function of the attitude.
//! - [`STATE_LEN`] and [`layout`] place the state in the array the steppers integrate, one
//!   layout for every law.
//! - [`ContactDynamics`] is the trait a derived body implements (the interpreted
//!   [`ContactModel`], and `#[contact(...)]`); [`ContactSystem`] is one phase as an ODE and
//!   [`ContactRun`] a run that switches stick↔slip at events and stops at lift-off.
//! - [`ContactQuantities`] gives a run's trajectory the energy, N, the slip, Jellett's λ and
//!   the angular momentum about the contact point; [`ContactError`] is the scene's one error.
//!
//! The files, with the roles every scene gives them: `scene.rs` (the description, with the
//! [`Phase`]s, the [`LawKind`] and the [`ContactTorques`]), `derivation.rs` with
//! `torques.rs` (the torques beyond the law's friction), `interpreted.rs` (the model),
//! `dynamics.rs` (the trait), `error.rs`; then `system.rs` (the ODE adapter), `phases.rs`
//! (the run loop's hooks) with `pivot.rs` (pivoting friction: the spin stopping, held, breaking
//! loose), `run.rs` (the run driver) with `outcome.rs` (what a run reports),
//! `checks.rs` (the run-time checks) and `theory/` (closed forms to measure runs against).

mod checks;
mod derivation;
mod dynamics;
mod error;
mod interpreted;
mod outcome;
mod phases;
mod pivot;
mod quantities;
mod run;
mod scene;
mod state;
/// The surfaces moved down to `rigid` (shared with a mechanism's wheels); the scene's files
/// still name them through `super::surface`.
use crate::rigid as surface;
mod system;
pub mod theory;
mod torques;

/// The surfaces and their support maps, shared with a mechanism's wheels: they live in
/// [`crate::rigid`].
pub use crate::rigid::{Surface, SurfaceKind};
pub use checks::{ContactValues, MIN_TILT, QUATERNION_TOLERANCE, ROLLING_TOLERANCE};
pub use derivation::{ContactDerivation, ContactEquations};
pub use dynamics::{ContactDynamics, ContactMomenta, ContactPoint, Reaction};
pub use error::ContactError;
pub use interpreted::ContactModel;
pub use outcome::{ContactOutcome, Switch};
pub use phases::{STICK_FRACTION, normal_denominator};
pub use pivot::{HeldSpin, held_spin};
pub use quantities::ContactQuantities;
pub use run::{ContactRun, SEED_SLIP};
pub use scene::{
    ContactLaw, ContactMode, ContactScene, ContactTorques, Friction, LawKind, Phase, coefficients,
};
pub use state::{STATE_LEN, attitude_of, layout};
pub use system::ContactSystem;
