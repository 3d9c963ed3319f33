//! Generic time stepping: systems with an in-place right-hand side, fixed-step RK4, adaptive
//! embedded pairs (Dormand–Prince 5(4), DOP853, Verner 9(8)) driven by one adaptive driver
//! with a PI controller, stop times and dense output.
//!
//! States are fixed-size arrays: no step allocates. The rigid-body steppers (attitudes on the
//! unit quaternions, RKMK4, the splittings) live in [`crate::rigid`].
//!
//! Answers come from a [`Run`] of any [`Stepper`] (the adaptive driver, [`Rk4`], a
//! [`FixedStepper`] over a splitting): samples at chosen times through the dense output or
//! partial steps, a [`Trajectory`] with derived quantities that writes CSV, an observer of
//! every accepted step that may stop the run, events (zero crossings of g(t, y), located on
//! the stepper's own solution) and progress reports.
//!
//! Names: a pair type (`Dopri5Pair`, `Dop853Pair`, `Vern9Pair`) is the method — its tableau
//! and error estimate; the driver of the same name without `Pair` (`Dopri5`, `Dop853`,
//! `Vern9`) is [`Adaptive`] running it.

mod adaptive;
mod chebyshev;
mod config;
mod controller;
pub(crate) mod drivers;
mod error;
mod events;
mod fixed;
pub(crate) mod hybrid;
mod pairs;
mod parameters;
mod rk4;
mod run;
mod sampling;
mod scan;
mod stepper;
mod system;
mod trajectory;

pub use adaptive::Adaptive;
pub(crate) use config::check_tolerances;
pub use config::{AdaptiveConfig, FixedStepConfig};
pub use controller::PiController;
pub use drivers::{Dop853, Dopri5, Solution, Vern9, solve, solve_dense};
pub use error::OdeError;
pub(crate) use error::{check_finite, check_inertia, check_span, check_stop};
pub(crate) use events::StepRoots;
pub use events::{Direction, Event, EventHit};
pub(crate) use fixed::two_sum;
pub use fixed::{FixedStepMethod, FixedStepper};
pub(crate) use fixed::{restart_switchable, switch_by_restart};
pub(crate) use hybrid::delegate_stepper;
pub use hybrid::{
    Action, Cause, HookAction, Hooks, Hybrid, HybridState, MAX_SWITCHES_AT_ONCE, Mode, Switchable,
    Transition,
};
pub use pairs::{
    ControllerGains, DenseCoeffs, DenseOutput, Dop853Pair, Dopri5Pair, EmbeddedPair, ErrorEstimate,
    Stages, Tableau, Vern9Pair,
};
pub(crate) use parameters::{binding_quantity, body_quantity, refused};
pub use rk4::Rk4;
pub use run::{Control, Outcome, Progress, Run, StopReason};
pub use sampling::MIN_SAMPLE_SPACINGS;
pub use stepper::Stepper;
pub(crate) use stepper::{inherent_stepper, state_accessors};
pub(crate) use system::forward_to_referent;
pub use system::{FnSystem, Stats, System};
pub use trajectory::{MAX_SAMPLES, Quantities, StateColumns, Trajectory};
