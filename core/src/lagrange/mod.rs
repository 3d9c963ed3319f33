//! The Euler–Lagrange engine: from a symbolic Lagrangian and generalised forces to
//! `M(q) q̈ = f(q, q̇)` and its solution, and the top scenes built on it.
//!
//! - [`EquationsOfMotion::derive`] forms the mass matrix, the forcing and the residuals, all
//!   in trig-canonical form so structural zeros are exact.
//! - [`EquationsOfMotion::solve`] solves block by block with adjugates, sharing f, the
//!   adjugate entries and one division per block.
//! - [`AngleSequence`] derives R(q) and ω = vee(Rᵀ Ṙ) for ZXZ and ZYX angles.
//! - [`TopScene`] assembles a top's Lagrangian and declared torques, and its Eulerian form.

mod angles;
mod chart;
mod chart_trait;
mod derived;
mod equations;
mod error;
mod fast;
mod model;
mod solve;
mod top;

pub use angles::{AngleSequence, Mat3, cross, dot, elementary, mat_mul, mat_vec, transpose};
pub use chart::{ChartConfig, ChartError, ChartedTop, angles_from_rotation};
pub use chart_trait::AngleChart;
pub use derived::{EulerianTop, Top, TopChart, TopError, join, rates_from_omega};
pub use equations::{Coordinates, EquationsOfMotion};
pub use error::LagrangeError;
pub use fast::FastTop;
pub use model::{ModelError, TopModel};
pub use solve::{Accelerations, MAX_BLOCK, cofactor, determinant};
pub use top::{TopDerivation, TopScene};
