//! Generic time stepping: systems with an in-place right-hand side, fixed-step RK4, adaptive
//! embedded pairs (Dormand–Prince 5(4), DOP853, Verner 9(8)) driven by one adaptive driver
//! with a PI controller, stop times and dense output.
//!
//! States are fixed-size arrays: no step allocates. The rigid-body steppers (attitudes on the
//! unit quaternions, RKMK4, the splittings) live in [`crate::rigid`].
//!
//! Names: a pair type (`Dopri5Pair`, `Dop853Pair`, `Vern9Pair`) is the method — its tableau
//! and error estimate; the driver of the same name without `Pair` (`Dopri5`, `Dop853`,
//! `Vern9`) is [`Adaptive`] running it.

mod adaptive;
mod config;
mod controller;
mod drivers;
mod error;
mod pairs;
mod rk4;
mod system;

pub use adaptive::Adaptive;
pub use config::{AdaptiveConfig, FixedStepConfig};
pub use controller::PiController;
pub use drivers::{Dop853, Dopri5, Solution, Vern9, solve, solve_dense};
pub use error::OdeError;
pub(crate) use error::{check_finite, check_inertia, check_span};
pub use pairs::{
    ControllerGains, DenseCoeffs, Dop853Pair, Dopri5Pair, EmbeddedPair, Stages, Vern9Pair,
};
pub use rk4::Rk4;
pub use system::{FnSystem, Stats, System};
