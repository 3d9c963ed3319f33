//! Errors of the top scene at run time: a state a chart cannot represent, the chart-switching
//! driver, and the interpreted model.

use thiserror::Error;

use crate::body::BodyError;
use crate::codegen::BindingError;
use crate::ode::OdeError;
use crate::rigid::AngleSequence;

/// A state the angle form or the Eulerian form of a top cannot take.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TopError {
    /// `|det B(q)|` is below [`super::SINGULAR_DET`]: the angles are at (or within rounding
    /// of) the chart's gimbal lock, where q̇ and q̈ are not determined by ω.
    #[error(
        "the {sequence:?} chart is singular at the angles {q:?} (|det B| = {det:e}, below {limit:e}): \
         integrate through it with ChartedTop (TopChart::both) or the Eulerian form (EulerianTop)",
        limit = super::SINGULAR_DET
    )]
    SingularChart {
        /// The chart's sequence.
        sequence: AngleSequence,
        /// The angles.
        q: [f64; 3],
        /// |det B(q)|.
        det: f64,
    },
    /// An input holds NaN or ±∞.
    #[error("non-finite {quantity}: {values:?}")]
    NonFinite {
        /// What the values are: the angles q, the rates q̇, the body angular velocity ω, …
        quantity: &'static str,
        /// The offending values.
        values: Vec<f64>,
    },
    /// A finite state in a regular chart gave a non-finite result: a parameter or the user
    /// torque is NaN or infinite, or the result overflows f64.
    #[error(
        "{quantity} = {values:?} is not finite at a finite state in a regular chart \
         (a NaN or infinite parameter or torque, or an overflow)"
    )]
    NonFiniteResult {
        /// The quantity computed: q̈ or the rates q̇.
        quantity: &'static str,
        /// Its values.
        values: Vec<f64>,
    },
    /// A declared setting of the scene (`#[top(gravity = g)]`, `damping`, a constant torque)
    /// is NaN or infinite.
    #[error("the top's `{parameter}` is {value}: it must be finite")]
    NonFiniteParameter {
        /// The setting, as `#[top(...)]` names it.
        parameter: &'static str,
        /// Its value.
        value: f64,
    },
    /// The gravity is negative. It is the magnitude g ≥ 0 of a field along −z in space, so a
    /// gravity written with the sign of its direction would pull the top up.
    #[error(
        "the top's `gravity` is {value}: it must be zero or positive, the magnitude g of \
         gravity along −z (write 9.81, not −9.81)"
    )]
    NegativeGravity {
        /// The value given.
        value: f64,
    },
    /// The damping coefficient is negative: the torque −k ω would feed energy in.
    #[error(
        "the top's `damping` is {value}: it must be zero or positive (the torque is −k ω; a \
         negative k feeds energy in)"
    )]
    NegativeDamping {
        /// The value given.
        value: f64,
    },
    /// The body of a top breaks a rule of its description (a field-valued mass, say), found
    /// by [`super::TopDynamics::check_all`].
    #[error(transparent)]
    Body(#[from] BodyError),
    /// The attitude quaternion of an Eulerian state is zero, so it names no attitude.
    #[error(
        "the attitude quaternion {quaternion:?} is zero; a state needs a non-zero quaternion \
         (EulerianTop::state builds one from a UnitQuaternion)"
    )]
    ZeroQuaternion {
        /// The quaternion as stored, `[w, x, y, z]`.
        quaternion: [f64; 4],
    },
}

/// Errors of the chart-switching driver [`super::ChartedTop`].
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ChartError {
    /// The two models are of the same angle sequence: there is nothing to switch to.
    #[error("both charts use the {0:?} sequence; give one ZXZ and one ZYX model")]
    SameSequence(AngleSequence),
    /// The attitude given is not a rotation matrix: not finite, not orthogonal within
    /// [`super::ROTATION_TOLERANCE`], or a reflection.
    #[error(
        "the attitude is not a rotation matrix: max |RᵀR − I| = {orthogonality:e} and det R = \
         {det} (a rotation has 0 and 1, within {tol:e}), R = {matrix:?}",
        tol = super::ROTATION_TOLERANCE
    )]
    NotARotation {
        /// The matrix given, row by row.
        matrix: [[f64; 3]; 3],
        /// The largest entry of |RᵀR − I|.
        orthogonality: f64,
        /// Its determinant.
        det: f64,
    },
    /// The body angular velocity holds NaN or ±∞.
    #[error("non-finite body angular velocity ω = {omega:?}")]
    NonFiniteOmega {
        /// ω as given.
        omega: [f64; 3],
    },
    /// [`super::ChartConfig::switch_below`] is not finite and positive.
    #[error("switch_below = {value} must be finite and > 0")]
    InvalidSwitch {
        /// The value given.
        value: f64,
    },
    /// `B(q)` cannot be inverted at this state in either chart (for a rotation matrix and a
    /// finite ω this does not happen: the two charts are never singular together).
    #[error("the rate map is singular in both charts (|det B| = {primary:e} and {secondary:e})")]
    Singular {
        /// |det B| in the first chart.
        primary: f64,
        /// |det B| in the second chart.
        secondary: f64,
    },
    /// The top fails its checks ([`super::TopDynamics::check_all`]): a setting out of its
    /// range ([`super::TopParameters::check`]) or a body that breaks a rule
    /// ([`TopError::Body`]).
    #[error(transparent)]
    Parameter(TopError),
    /// The stepper failed, or the stop time is not finite or lies in the past.
    #[error(transparent)]
    Ode(#[from] OdeError),
}

/// Errors of [`super::TopModel`].
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ModelError {
    /// No parameter of that name appears in the derivation.
    #[error("no parameter named `{name}` in this top (parameters: {known})")]
    UnknownParameter {
        /// The name asked for.
        name: String,
        /// The parameters that exist, comma-separated.
        known: String,
    },
    /// A parameter the derivation reads was not given a value.
    #[error("parameter `{name}` is not set: give a value for each of {known}")]
    UnsetParameter {
        /// The parameter.
        name: String,
        /// The parameters the derivation reads, comma-separated.
        known: String,
    },
    /// A parameter value that is NaN or infinite.
    #[error("parameter `{name}` = {value} is not finite")]
    NonFinite {
        /// The parameter.
        name: String,
        /// Its value.
        value: f64,
    },
    /// The derivation reads a value fed in at evaluation (a user torque's input symbols),
    /// which the interpreted model has no way to supply.
    #[error(
        "the derivation reads `{name}`, a run-time input (a user torque): the interpreted model \
         cannot supply it; derive the top with #[top(torque = ..)] instead"
    )]
    RunTimeInput {
        /// The input symbol's name.
        name: String,
    },
}

impl From<BindingError> for ModelError {
    fn from(e: BindingError) -> Self {
        match e {
            BindingError::UnknownParameter { name, known } => {
                ModelError::UnknownParameter { name, known }
            }
            BindingError::UnsetParameter { name, known } => {
                ModelError::UnsetParameter { name, known }
            }
            BindingError::NonFinite { name, value } => ModelError::NonFinite { name, value },
            BindingError::RunTimeInput { name } => ModelError::RunTimeInput { name },
        }
    }
}
