//! The top: one rigid body turning about a fixed pivot, under the torques its scene declares.
//!
//! A scene over the engine, in one place:
//! - [`TopScene`] builds the Lagrangian in Euler angles and the declared torques as
//!   generalised forces, and [`TopScene::derive`] hands them to the Euler–Lagrange engine
//!   ([`crate::lagrange`]), giving a [`TopDerivation`]; [`TopScene::eulerian_rhs`] gives the
//!   same scene in Eulerian form.
//! - [`TopParameters`] holds a scene's declared settings (gravity, damping, constant
//!   torques) and [`TopParameters::check`] is the one rule for them: the derive applies it to
//!   literals at compile time, [`TopDynamics::check_parameters`] to field values at run time.
//! - [`TopDynamics`] is the trait `#[top(...)]` implements over the generated code; [`TopChart`] and
//!   [`EulerianTop`] run a derived top with any stepper of [`crate::ode`].
//! - [`ChartedTop`] gets through gimbal lock by switching between the ZXZ and ZYX charts
//!   ([`AngleChart`]); [`crate::rigid::rates_from_omega`] is the one rule for when a chart
//!   is singular, and the chart machinery every scene shares is in [`crate::rigid::charts`].
//! - [`TopModel`] is a derivation interpreted at run time, for scenes built at run time.
//! - [`FastTop`] is a top as a splitting: the exact free-body flow and gravity kicks.
//! - [`HeavyTopTheory`] and [`HeavyTopMotion`] give the symmetric heavy top's closed forms
//!   (nutation, precession, the sleeping top), [`TorqueFreeSymmetric`] the free body's cones.
//! - [`angle_linearisation`] and [`reduced_linearisation`] give the linear system about a
//!   state or a steady motion, for [`crate::linalg`]'s eigenvalues and stability verdict.
//! - [`TopQuantities`] gives a run's trajectory the top's energy, |ω|, |L| and conserved
//!   momenta per sample.

mod angle_chart;
mod checks;
mod derivation;
mod driven;
mod dynamics;
mod error;
mod eulerian;
mod fast_top;
mod interpreted;
mod linear;
mod quantities;
mod run;
mod scene;
mod system;
mod theory;
mod typeset;

pub use angle_chart::AngleChart;
pub use checks::TopParameters;
pub use derivation::TopDerivation;
pub use driven::DrivenDerivation;
pub use dynamics::{TopDynamics, angle_state};
pub use error::TopError;
pub use eulerian::EulerianTop;
pub use fast_top::FastTop;
pub use interpreted::TopModel;
pub use linear::{
    LinearisationError, MOMENTUM_MAP_TOLERANCE, ReducedLinearisation, angle_linearisation,
    reduced_linearisation,
};
pub use quantities::TopQuantities;
pub use run::{ChartedTop, Charts};
pub use scene::TopScene;
pub use system::TopChart;
pub use theory::{
    HeavyTopMotion, HeavyTopTheory, STEADY_TOLERANCE, SYMMETRY_TOLERANCE, SleepingTop,
    SteadyPrecession, TheoryError, TorqueFreeSymmetric,
};
