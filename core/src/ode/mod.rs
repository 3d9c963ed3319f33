//! Time stepping: systems with an in-place right-hand side, fixed-step RK4, adaptive embedded
//! pairs (Dormand–Prince 5(4), DOP853, Verner 9(8)) with PI control, stop times and dense
//! output,
//! attitude integrators on the unit quaternions (exponential map, RKMK4), and geometric
//! splitting methods for rigid bodies.
//!
//! States are fixed-size arrays or nalgebra static types: no step allocates.

pub mod adaptive;
pub mod attitude;
pub mod config;
pub mod error;
pub mod lie;
pub mod pair;
pub mod rk4;
pub mod solve;
pub mod splitting;
pub mod system;
pub mod tableau;
pub mod vern;

pub use adaptive::{Adaptive, AdaptiveConfig};
pub use error::OdeError;
pub use pair::{Dp54, Dp853, EmbeddedPair};
pub use rk4::{Rk4, Rk4Config};
pub use solve::{Dop853, Dopri5, Solution, Vern9, solve, solve_dense};
pub use system::{FnSystem, Stats, System};
pub use vern::Vern98;
