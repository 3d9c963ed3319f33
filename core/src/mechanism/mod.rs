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
//! - [`MechanismPoses`] (derived) gives each link's [`LinkPose`] at q and its declared parts,
//!   what `precess::animate::mechanism` draws.
//! - [`MechanismQuantities`] gives a run's trajectory the energy, its kinetic and potential
//!   parts, the power and every generalised momentum per sample, named as a top's.
//! - [`rolling`]: bodies whose wheels roll without slip on a floor (nonholonomic rows, the
//!   Whipple bicycle), [`MechanismScene::derive_rolling`] and [`rolling::RollingDynamics`].
//! - [`loops`]: closed kinematic loops (`closes = ..`: a four-bar, a slider-crank),
//!   [`MechanismScene::derive_loops`] and [`loops::LoopDynamics`], the dependent coordinates
//!   chosen at each configuration and the loop closed after every step.
//! - [`MechanismDerivation::taylor_tape`] gives the Taylor recurrences of `(q, q̇)' = (q̇, q̈)`
//!   for [`crate::taylor`]'s integrator (`taylor = K` on `#[mechanism]` generates them).
//!
//! The files, with the roles every scene gives them: `scene.rs`, `validate.rs` and
//! `rules.rs` (the description and its rules), `derivation.rs` (the route chosen) over
//! `routes/` (one algorithm per file: `lagrangian.rs`, `factored.rs`, `kane.rs`,
//! `recursive/`, and the numeric `aba.rs`), `interpreted.rs` (the model), `dynamics.rs` (the
//! trait), `error.rs`; then `system.rs` (the ODE adapter), `checks.rs` (the run-time checks of
//! values made of parameters), and the run drivers `charts/run.rs` (spherical joints through
//! gimbal lock) and `rolling/run.rs`. No `theory/`: the closed forms the mechanism tests hold
//! runs against live in the tests (pendulums), [`crate::exact`] (the free body) and the
//! contact scene's theory (the rolling disk), which a scene does not name.

pub mod charts;
mod checks;
mod derivation;
mod dynamics;
mod error;
mod interpreted;
mod kinematics;
pub mod loops;
mod poses;
mod quantities;
pub mod rolling;
mod routes;
mod rules;
mod scene;
mod system;
mod taylor;
mod validate;

pub use charts::{ChartSet, ChartedDynamics, ChartedMechanism, MechanismCharts};
pub use derivation::{MAX_SYMBOLIC, MechanismDerivation, Route};
pub use dynamics::{MechanismDynamics, effort_jacobian, split_state};
pub use error::MechanismError;
pub use interpreted::MechanismModel;
pub use kinematics::{BodyKinematics, MAX_LAGRANGIAN};
pub use poses::{LinkPose, MechanismPoses};
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
