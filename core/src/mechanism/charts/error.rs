//! What the chart switch of a mechanism refuses.

use thiserror::Error;

use crate::mechanism::MechanismError;
use crate::ode::OdeError;
use crate::rigid::ChartError;

/// An error of [`super::ChartedMechanism`] or [`super::MechanismCharts`].
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MechanismChartError {
    /// [`crate::rigid::ChartConfig::switch_below`] is not finite and positive.
    #[error("switch_below = {value} must be finite and > 0")]
    InvalidSwitch {
        /// The value given.
        value: f64,
    },
    /// The ODE state length is not twice the coordinate count.
    #[error("the ODE state has {got} entries, the mechanism needs 2n = {expected}")]
    StateLength {
        /// 2n.
        expected: usize,
        /// S.
        got: usize,
    },
    /// More spherical joints than a [`super::ChartSet`] can name.
    #[error("{count} spherical joints; a chart set names at most {max}")]
    TooManyJoints {
        /// The spherical joints.
        count: usize,
        /// [`super::MAX_SPHERICAL_JOINTS`].
        max: usize,
    },
    /// A chart set the mechanism does not provide ([`super::chart_variants`]).
    #[error("the mechanism provides no equations for the chart set {charts:#b}")]
    UnavailableCharts {
        /// The chart set's bits.
        charts: u32,
    },
    /// One attitude and angular velocity per spherical joint is needed.
    #[error("{got} joint attitudes given for {expected} spherical joints")]
    AttitudeCount {
        /// The spherical joints.
        expected: usize,
        /// The attitudes given.
        got: usize,
    },
    /// A joint's attitude is not a rotation matrix, or its ω is not finite.
    #[error("spherical joint `{joint}`: {source}")]
    Attitude {
        /// The joint.
        joint: String,
        /// What is wrong with it.
        source: ChartError,
    },
    /// A joint's state cannot be represented in any chart available to it (its rate map is
    /// singular in its chart and it cannot switch), or its angles or rates are not finite.
    #[error("spherical joint `{joint}` in its chart: {source}")]
    Joint {
        /// The joint.
        joint: String,
        /// The rate map's complaint.
        source: ChartError,
    },
    /// The state holds NaN or ±∞ outside the spherical joints.
    #[error("non-finite state {values:?}")]
    NonFinite {
        /// The state.
        values: Vec<f64>,
    },
    /// Deriving or binding a chart's equations failed.
    #[error(transparent)]
    Mechanism(#[from] MechanismError),
    /// The stepper failed.
    #[error(transparent)]
    Ode(#[from] OdeError),
}
