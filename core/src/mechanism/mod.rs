//! Mechanisms: trees of rigid bodies joined by revolute, prismatic, universal and spherical
//! joints, derived to `M(q) q̈ = f(q, q̇, t)` and solved by the cheapest exact route.
//!
//! - [`MechanismScene`] describes the tree and its loads (see `scene.rs` for the frames);
//!   [`MechanismScene::validate`] checks it and orders it parents first.
//! - [`MechanismScene::kinematics`] gives every body's attitude, origin, centre of mass,
//!   angular velocity and centre velocity as expressions in q and q̇.
//! - [`MechanismScene::derive`] forms T and V, the generalised forces of dampers, efforts
//!   and torques, the Euler–Lagrange equations, and solves them by a [`Route`]: the symbolic
//!   adjugate for few coordinates, an unexpanded LDLᵀ otherwise, whichever lowers to fewer
//!   operations.
//! - [`MechanismModel`] lowers a derivation and interprets it at run time, with typed
//!   [`MechanismError`]s for singular mass matrices and bad states, and an ODE adapter.
//! - [`recursive_accelerations`] is the recursive route (the articulated-body algorithm,
//!   symbolic, O(n) operations), [`MechanismAba`] the same algorithm numerically, the
//!   generic O(n) reference the benchmarks compare against.
//! - [`charts`]: spherical joints through gimbal lock, [`ChartedMechanism`] switching each
//!   joint between its declared sequence and the partner (ZXZ ↔ ZYX).
//! - [`MechanismQuantities`] gives a run's trajectory the energy, its kinetic and potential
//!   parts, the power and every generalised momentum per sample, named as a top's.
//! - [`rolling`]: bodies whose wheels roll without slip on a floor (nonholonomic rows, the
//!   Whipple bicycle), [`MechanismScene::derive_rolling`] and [`rolling::RollingDynamics`].
//! - [`MechanismDerivation::taylor_tape`] gives the Taylor recurrences of `(q, q̇)' = (q̇, q̈)`
//!   for [`crate::taylor`]'s integrator (`taylor = K` on `#[mechanism]` generates them).

pub mod charts;
mod checks;
mod derivation;
mod dynamics;
mod error;
mod interpreted;
mod kinematics;
mod quantities;
pub mod rolling;
mod routes;
mod rules;
mod scene;
mod system;
mod taylor;
mod validate;

pub use charts::{ChartSet, ChartedDynamics, ChartedMechanism, MechanismCharts};
pub use derivation::{MAX_LAGRANGIAN, MAX_SYMBOLIC, MechanismDerivation, Route};
pub use dynamics::{MechanismDynamics, split_state};
pub use error::MechanismError;
pub use interpreted::MechanismModel;
pub use kinematics::BodyKinematics;
pub use quantities::MechanismQuantities;
pub use routes::aba::MechanismAba;
pub use routes::recursive;
pub use routes::recursive::{
    RecursiveForm, coordinate_forces, derive_recursive, recursive_accelerations,
};
pub use rules::{PARALLEL_SINE, check_axis, check_universal_axes};
pub use scene::{CoordinateLoad, Joint, JointKind, MechanismBody, MechanismScene, Parent, Spring};
pub use system::MechanismSystem;
pub use taylor::MechanismTaylorError;
