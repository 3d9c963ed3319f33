//! Variational equations generated from a scene's symbolic right-hand side: the state
//! transition matrix Φ = ∂x(t)/∂x₀, the sensitivities S = ∂x(t)/∂p, and on them the
//! Lyapunov exponents (Benettin's method) and the linearised flow map for uncertainty
//! propagation.
//!
//! - [`VariationalEquations`] builds `(x, Φ, S)' = (f, J Φ, J S + ∂f/∂p)`, J = ∂f/∂x, as
//!   expressions in an [`Arena`](crate::sym::Arena), from any right-hand side
//!   ([`VariationalEquations::new`]) or from a scene ([`VariationalEquations::from_top`],
//!   [`VariationalEquations::from_eulerian_top`], [`VariationalEquations::from_mechanism`]).
//! - [`VariationalSystem`] lowers them to one program (f, J and the products share their
//!   subexpressions) and runs it as an [`ode::System`](crate::ode::System) of size
//!   N = n + n·m + n·k; [`Layout`] says where x, Φ (column-major) and S sit.
//! - [`benettin`] gives the Lyapunov spectrum over any stepper; [`FlowMap`] maps a
//!   covariance P₀ to Φ P₀ Φᵀ.
//!
//! The module sits above the scenes (it names them), like [`crate::ensemble`]; no scene
//! names it. `docs/variational.md` gives the method, the checks and the costs.

mod equations;
mod error;
mod flow_map;
mod layout;
mod lyapunov;
mod scenes;
mod system;

pub use equations::VariationalEquations;
pub use error::VariationalError;
pub use flow_map::FlowMap;
pub use layout::Layout;
pub use lyapunov::{BenettinConfig, LyapunovSpectrum, MAX_INTERVALS, SHRINK_FLOOR, benettin};
pub use system::VariationalSystem;
