//! Errors of the top scene at run time: a state a chart cannot represent, the chart-switching
//! driver, and the interpreted model.

use thiserror::Error;

use crate::ode::OdeError;
use crate::rigid::AngleSequence;

/// A state an angle chart cannot represent.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TopError {
    /// B(q) is singular: the angles are at the chart's gimbal lock.
    #[error(
        "the {sequence:?} angles {q:?} are at gimbal lock (|det B| = {det:e}); use the other chart or the Eulerian form"
    )]
    SingularChart {
        /// The sequence.
        sequence: AngleSequence,
        /// The angles.
        q: [f64; 3],
        /// |det B(q)|.
        det: f64,
    },
    /// A non-finite angle, rate or angular velocity.
    #[error("non-finite state {state:?}")]
    NonFinite {
        /// The offending values.
        state: Vec<f64>,
    },
}

/// Errors of the chart-switching driver.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ChartError {
    /// The two models are of the same angle sequence: there is nothing to switch to.
    #[error("both charts use the {0:?} sequence; give one ZXZ and one ZYX model")]
    SameSequence(AngleSequence),
    /// `B(q)` cannot be inverted at this state in either chart.
    #[error("the rate map is singular in both charts (|det B| = {primary:e} and {secondary:e})")]
    Singular {
        /// |det B| in the first chart.
        primary: f64,
        /// |det B| in the second chart.
        secondary: f64,
    },
    /// The stepper failed.
    #[error(transparent)]
    Ode(#[from] OdeError),
}

/// Errors of [`TopModel`].
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
    /// A parameter value that is NaN or infinite.
    #[error("parameter `{name}` = {value} is not finite")]
    NonFinite {
        /// The parameter.
        name: String,
        /// Its value.
        value: f64,
    },
}
