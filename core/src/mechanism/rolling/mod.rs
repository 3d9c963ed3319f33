//! Wheels of a mechanism rolling without slip on a floor: the Whipple bicycle's knife-edge
//! wheels, a ball under a frame.
//!
//! - [`RollingScene`] names the rolling bodies ([`RollingWheel`], a disk rim or a sphere),
//!   the floor's upward axis, and the free speeds u (the state is `(q, u)`).
//! - [`MechanismScene::derive_rolling`](crate::mechanism::MechanismScene::derive_rolling)
//!   derives M(q), f(q, q̇), the rolling rows A(q) q̇ = 0 (two per wheel, plus the height
//!   row where the joints do not already hold the wheel on the floor) and Ȧq̇, all exactly.
//! - [`RollingDynamics`] finishes Maggi's equations numerically ([`Partition`]) at each
//!   evaluation, puts the wheels on the floor ([`RollingDynamics::close_contacts`]) and
//!   reports the multipliers (the contact forces). The derive implements it with
//!   straight-line code; [`RollingModel`] interprets a derivation.
//! - [`RollingDynamics::acceleration_jacobian`] gives ∂u̇/∂q and ∂u̇/∂u exactly, from the
//!   engine's derivatives of M, f, A and Ȧq̇ ([`RollingPartials`]) carried through the
//!   projection by the product rule: the derive's as straight-line code, a
//!   [`RollingModel`]'s lowered on its first call.
//!
//! Why numerically: the symbolic elimination of a five-row block with a square root in its
//! rows (the bicycle's) swelled past 8 GB; see docs/bicycle.md.
//!
//! [`Partition`]: crate::lagrange::Partition

mod derivation;
mod dynamics;
mod interpreted;
mod partials;
mod run;
mod scene;

pub use derivation::RollingDerivation;
pub use dynamics::{CONTACT_TOLERANCE, MIN_TILT, RollingDynamics, RollingSystem, split_rolling};
pub use interpreted::RollingModel;
pub use partials::RollingPartials;
pub use run::{FLAT_WITNESS, RollingHalt, RollingRun, rolling_run};
pub use scene::{RollingScene, RollingWheel, WheelSurface};
