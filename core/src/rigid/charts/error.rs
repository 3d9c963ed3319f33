//! What the chart rule and the chart switch refuse, for every scene: a top's two charts, a
//! mechanism's spherical joints.

use thiserror::Error;

use crate::rigid::AngleSequence;

/// A state an angle chart cannot take, or an attitude and a switch setting the chart switch
/// cannot start from. Scene errors nest it (`TopError::Chart`, the mechanism's chart
/// errors) rather than copy it.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ChartError {
    /// `|det B(q)|` is below [`super::SINGULAR_DET`]: the angles are at (or within rounding
    /// of) the chart's gimbal lock, where q̇ and q̈ are not determined by ω.
    #[error(
        "the {sequence:?} chart is singular at the angles {q:?} (|det B| = {det:e}, below {limit:e}): \
         integrate through it in the partner chart (ChartedTop, ChartedMechanism) or the \
         Eulerian form (EulerianTop)",
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
    /// Angles, rates or an angular velocity given to the chart rule hold NaN or ±∞.
    #[error("non-finite {quantity}: {values:?}")]
    NonFinite {
        /// What the values are: the angles q, the body angular velocity ω, …
        quantity: &'static str,
        /// The offending values.
        values: Vec<f64>,
    },
    /// The rates solved from a finite ω in a regular chart overflow f64.
    #[error("{quantity} = {values:?} is not finite at a finite state in a regular chart")]
    NonFiniteResult {
        /// The quantity computed: the rates q̇.
        quantity: &'static str,
        /// Its values.
        values: Vec<f64>,
    },
    /// The two charts given are of the same angle sequence: there is nothing to switch to.
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
        /// The matrix given, row by row (boxed: nine numbers would make every error that
        /// nests this one large to return).
        matrix: Box<[[f64; 3]; 3]>,
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
}
