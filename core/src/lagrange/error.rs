//! Errors of the Euler–Lagrange engine.

use thiserror::Error;

use crate::codegen::BindingError;
use crate::ode::OdeError;
use crate::sym::SymError;

/// What can go wrong while deriving or solving equations of motion.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum LagrangeError {
    /// The number of generalised forces differs from the number of coordinates.
    #[error("{forces} generalised forces given for {coordinates} coordinates")]
    ForceCount {
        /// Coordinates.
        coordinates: usize,
        /// Forces given.
        forces: usize,
    },
    /// An expression given as a coordinate is not a coordinate symbol.
    #[error("`{expr}` is not a coordinate symbol (create one with Arena::coordinate)")]
    NotACoordinate {
        /// The expression.
        expr: String,
    },
    /// The mass matrix or the forcing depends on accelerations: the Lagrangian or a force
    /// already contains a second derivative.
    #[error(
        "equation {index} is not linear in the accelerations (an input holds a second derivative)"
    )]
    AccelerationInInput {
        /// Which equation.
        index: usize,
    },
    /// A block of the mass matrix has a determinant that is identically zero.
    #[error(
        "the mass matrix is singular everywhere (block of coordinates {block:?} has zero determinant)"
    )]
    SingularMassMatrix {
        /// Coordinate indices of the singular block.
        block: Vec<usize>,
    },
    /// A coupled block larger than the symbolic solver handles.
    #[error(
        "a coupled block of {size} coordinates is larger than the symbolic solve supports ({max})"
    )]
    BlockTooLarge {
        /// Block size.
        size: usize,
        /// The largest supported.
        max: usize,
    },
    /// A constraint row with a coefficient count other than the coordinate count.
    #[error("constraint row {row} has {got} coefficients for {expected} coordinates")]
    ConstraintLength {
        /// The row.
        row: usize,
        /// Coefficients given.
        got: usize,
        /// Coordinates.
        expected: usize,
    },
    /// A constraint that is not linear in the rates: a coefficient or offset of a velocity
    /// constraint holds a rate or an acceleration, or a position constraint holds a rate.
    #[error(
        "constraint row {row} is not of the form A(q, t) q̇ + b(q, t) = 0 (`{expr}` holds a rate \
         or an acceleration)"
    )]
    ConstraintNotLinear {
        /// The row.
        row: usize,
        /// The offending coefficient, offset or position function.
        expr: String,
    },
    /// As many constraints as coordinates or more: no speed is left to move.
    #[error("{constraints} constraints on {coordinates} coordinates leave no free speed")]
    TooManyConstraints {
        /// Constraints.
        constraints: usize,
        /// Coordinates.
        coordinates: usize,
    },
    /// The dependent coordinates chosen are not one per constraint, repeat one, or name
    /// one that does not exist.
    #[error(
        "dependent coordinates {dependent:?} are not {constraints} distinct indices below \
         {coordinates} (one per constraint)"
    )]
    DependentChoice {
        /// The indices given.
        dependent: Vec<usize>,
        /// Constraints.
        constraints: usize,
        /// Coordinates.
        coordinates: usize,
    },
    /// The constraints' block of the chosen dependent coordinates is singular everywhere:
    /// their speeds cannot be solved for.
    #[error(
        "the constraint block of dependent coordinates {dependent:?} has zero determinant \
         everywhere: choose other dependent coordinates"
    )]
    SingularConstraintBlock {
        /// The dependent coordinates.
        dependent: Vec<usize>,
    },
    /// No choice of dependent coordinates gives a constraint block that is not singular
    /// everywhere: the constraints are dependent.
    #[error(
        "no {constraints} coordinates have a non-singular constraint block: the constraints are dependent"
    )]
    DependentConstraints {
        /// Constraints.
        constraints: usize,
    },
    /// A run-time state of the wrong length for the constrained model.
    #[error(
        "state of {got} entries where the model takes {expected} (coordinates, then free speeds)"
    )]
    StateLength {
        /// Entries given.
        got: usize,
        /// Entries expected.
        expected: usize,
    },
    /// A non-finite coordinate or speed in a run-time state.
    #[error("state entry {index} = {value} is not finite")]
    NonFiniteState {
        /// The entry.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// A partitioned run was started off the loop: its initial state's position residual
    /// is past what rounding in setting it up explains.
    #[error(
        "the initial state is off the loop: the position constraints' residual is {residual:e} \
         (a run starts at most {allowed:e} off; close the loop first with close_loop)"
    )]
    StartOffLoop {
        /// The largest |φ_k| of the initial state.
        residual: f64,
        /// [`super::START_RESIDUAL`].
        allowed: f64,
    },
    /// det A_D changed sign over a step of a partitioned run: the independent coordinates
    /// passed a dead point of the dependent ones (a four-bar's crank at a limit position,
    /// where the coupler and the rocker line up), through which they no longer determine
    /// the mechanism; stepping on gave an energy error of 6·10⁻³ J.
    #[error(
        "the independent coordinates pass a dead point between t = {t_start} and t = {t_end}: \
         det A_D / (its rows' norms) went from {before:e} to {after:e}; partition the \
         coordinates with another independent choice there"
    )]
    DeadPoint {
        /// The step's start.
        t_start: f64,
        /// The step's end.
        t_end: f64,
        /// det A_D over the product of its rows' norms at the start.
        before: f64,
        /// The same at the end, of the other sign.
        after: f64,
    },
    /// Newton's iteration for the dependent coordinates did not close the loop.
    #[error(
        "the loop does not close: the position constraints' residual is {residual:e} after \
         {iterations} Newton iterations (tolerance {tolerance:e})"
    )]
    LoopNotClosed {
        /// The largest |φ_k| left.
        residual: f64,
        /// Iterations taken.
        iterations: usize,
        /// The tolerance asked for.
        tolerance: f64,
    },
    /// The constraint Jacobian's dependent block is singular at the state: the mechanism
    /// is at a branch point (a four-bar folded flat) or the dependent choice fails there.
    #[error(
        "the constraint block of the dependent coordinates is singular at this state \
         (determinant {determinant:e}, scale {scale:e})"
    )]
    SingularAtState {
        /// det A_D at the state.
        determinant: f64,
        /// The size it is judged against: the product of the rows' norms of A_D in
        /// [`ConstrainedModel::close_loop`](super::ConstrainedModel::close_loop); 1 where
        /// only Δ was evaluated (a rate that came out infinite or NaN).
        scale: f64,
    },
    /// The reduced mass matrix K = Sᵀ M S of Maggi's equations is singular at the state:
    /// the free speeds do not determine a motion (a massless mechanism, or M singular on
    /// the constraints' tangent space).
    #[error(
        "the reduced mass matrix Sᵀ M S is singular at this state (determinant {determinant:e}, \
         scale {scale:e})"
    )]
    SingularReducedMass {
        /// det K at the state.
        determinant: f64,
        /// The Frobenius norm of K, the size the determinant is judged against.
        scale: f64,
    },
    /// The stepper failed while advancing a constrained model.
    #[error(transparent)]
    Ode(#[from] OdeError),
    /// A parameter could not be bound at run time.
    #[error(transparent)]
    Binding(#[from] BindingError),
    /// A constructor of the symbolic engine failed.
    #[error(transparent)]
    Sym(#[from] SymError),
}
