//! What can go wrong building or running variational equations.

use crate::codegen::BindingError;
use crate::lagrange::LagrangeError;
use crate::ode::OdeError;

/// Why variational equations could not be built, bound or run.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum VariationalError {
    /// The right-hand side has a different length from the state.
    #[error(
        "the right-hand side has {rhs} entries for a state of {state}: give one per state entry"
    )]
    RhsLength {
        /// State entries.
        state: usize,
        /// Right-hand-side entries.
        rhs: usize,
    },
    /// An empty state: there is nothing to linearise.
    #[error("the state is empty: give at least one state symbol")]
    EmptyState,
    /// A state entry that is not a bare coordinate, rate or input symbol.
    #[error(
        "state entry {index} is not a coordinate, rate or input symbol: the state must be \
         distinct symbols the caller supplies"
    )]
    NotAStateSymbol {
        /// Its position in the state.
        index: usize,
    },
    /// The same symbol twice in the state.
    #[error("state entries {first} and {second} are the same symbol: give each state symbol once")]
    RepeatedStateSymbol {
        /// The first position.
        first: usize,
        /// The second position.
        second: usize,
    },
    /// A sensitivity asked for an expression that is not a parameter symbol.
    #[error("sensitivity parameter {index} is not a parameter symbol")]
    NotAParameter {
        /// Its position in the list of sensitivity parameters.
        index: usize,
    },
    /// A sensitivity asked for a parameter the equations do not read: ∂f/∂p is identically
    /// zero, and so would be the sensitivity.
    #[error(
        "sensitivity parameter {index} is not read by the equations (∂f/∂p is identically \
         zero): give only parameters the right-hand side reads"
    )]
    UnreadParameter {
        /// Its position in the list of sensitivity parameters.
        index: usize,
    },
    /// The same parameter twice among the sensitivities.
    #[error(
        "sensitivity parameters {first} and {second} are the same symbol: give each parameter once"
    )]
    RepeatedParameter {
        /// The first position.
        first: usize,
        /// The second position.
        second: usize,
    },
    /// A sensitivity parameter named that no parameter of the scene has.
    #[error("no parameter named `{name}` for a sensitivity")]
    UnknownParameter {
        /// The name given.
        name: String,
    },
    /// More tangent vectors than state entries (they could not be independent).
    #[error("{tangents} tangent vectors asked for a state of {state}: at most {state}")]
    TooManyTangents {
        /// Tangent vectors asked for.
        tangents: usize,
        /// State entries.
        state: usize,
    },
    /// The const-generic size of the system or stepper is not the layout's.
    #[error(
        "the augmented state has {expected} entries (n + n·m + n·k) but the system was given \
         N = {got}"
    )]
    SizeMismatch {
        /// n + n·m + n·k for the layout.
        expected: usize,
        /// The size given.
        got: usize,
    },
    /// An initial state of the wrong length.
    #[error("the initial state has {got} entries for a state of {expected}")]
    InitialStateLength {
        /// State entries.
        expected: usize,
        /// Entries given.
        got: usize,
    },
    /// A NaN or infinite entry in a state or matrix handed in.
    #[error("entry {index} is {value}, not finite")]
    NonFinite {
        /// Its position (row-major for matrices).
        index: usize,
        /// The value.
        value: f64,
    },
    /// A Lyapunov run needs at least one tangent vector.
    #[error(
        "the system carries no tangent vectors: build it with tangents ≥ 1 for Lyapunov exponents"
    )]
    NoTangents,
    /// The renormalisation interval is not a positive finite number.
    #[error("the renormalisation interval is {interval}: it must be positive and finite")]
    NonPositiveInterval {
        /// The interval given.
        interval: f64,
    },
    /// The averaging time is not a positive finite number.
    #[error("the averaging time is {duration}: it must be positive and finite")]
    NonPositiveDuration {
        /// The time given.
        duration: f64,
    },
    /// More renormalisation intervals than [`MAX_INTERVALS`](super::MAX_INTERVALS): the run
    /// would not end in any useful time.
    #[error(
        "{intervals} renormalisation intervals asked for (transient and duration over the \
         interval); at most {max}: lengthen the interval or shorten the run"
    )]
    TooManyIntervals {
        /// Intervals the settings need.
        intervals: f64,
        /// The limit.
        max: u64,
    },
    /// The transient is negative or not finite.
    #[error("the transient is {transient}: it must be zero or positive and finite")]
    InvalidTransient {
        /// The time given.
        transient: f64,
    },
    /// The tangent vectors collapsed (a zero or non-finite norm in the re-orthonormalisation).
    #[error(
        "tangent vector {index} has norm {norm} at t = {t} after orthogonalisation: shorten \
         the renormalisation interval"
    )]
    DegenerateTangents {
        /// Which tangent vector.
        index: usize,
        /// Its norm.
        norm: f64,
        /// When.
        t: f64,
    },
    /// A result of the flow map that overflowed f64: Φ's entries are finite but the product
    /// is not (Φ ≈ 10²⁰⁰ squared in Φ P₀ Φᵀ).
    #[error(
        "entry {index} of the flow map's result is {value}: the product of Φ (largest entry \
         {largest:e}) with the input overflows f64"
    )]
    Overflow {
        /// Its position (row-major for matrices).
        index: usize,
        /// The value.
        value: f64,
        /// The largest |Φᵢⱼ|.
        largest: f64,
    },
    /// A covariance matrix of the wrong shape.
    #[error("the covariance is {rows}×{cols}; the flow map needs {n}×{n}")]
    CovarianceShape {
        /// Rows given.
        rows: usize,
        /// Columns given.
        cols: usize,
        /// The state size.
        n: usize,
    },
    /// The flow map needs the full state transition matrix (tangents = n).
    #[error("the system carries {tangents} tangent vectors; the flow map needs all {n}")]
    NotFullTransition {
        /// Tangent vectors carried.
        tangents: usize,
        /// State entries.
        n: usize,
    },
    /// Binding the parameters failed.
    #[error(transparent)]
    Binding(#[from] BindingError),
    /// The scene's equations could not be formed.
    #[error(transparent)]
    Lagrange(#[from] LagrangeError),
    /// The integration failed.
    #[error(transparent)]
    Ode(#[from] OdeError),
}
