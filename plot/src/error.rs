//! What can stop a figure from being drawn: the data (empty, ragged, non-finite, not positive
//! on a logarithmic axis), a column name, or the file.

use std::fmt;
use std::path::PathBuf;

use thiserror::Error;

/// Which coordinate of a point a value is: along the x axis or the y axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Coordinate {
    /// The horizontal axis (time, for a series against time).
    X,
    /// The vertical axis.
    Y,
}

impl fmt::Display for Coordinate {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Coordinate::X => "x",
            Coordinate::Y => "y",
        })
    }
}

/// Why a figure was not written.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum PlotError {
    /// The figure was given no series at all.
    #[error("nothing to plot: the figure has no series (give at least one)")]
    NoSeries,
    /// A series (or a column) has no points.
    #[error("series `{series}` has no points (each series needs at least one)")]
    EmptySeries {
        /// The series' label or the column's name.
        series: String,
    },
    /// A column is not as long as the column it is drawn against.
    #[error("column `{series}` has {got} values where its x column has {expected}")]
    LengthMismatch {
        /// The column's name.
        series: String,
        /// The x column's length.
        expected: usize,
        /// This column's length.
        got: usize,
    },
    /// A value is NaN or infinite.
    #[error("the {coordinate} value {value} at index {index} of `{series}` is not finite")]
    NonFinite {
        /// The series' label or the column's name.
        series: String,
        /// The axis the value is drawn along.
        coordinate: Coordinate,
        /// The value's index in its series.
        index: usize,
        /// The value.
        value: f64,
    },
    /// A value on a logarithmic axis is zero or negative.
    #[error(
        "the {coordinate} value {value} at index {index} of `{series}` is not positive, \
         and its axis is logarithmic (only values > 0 can be drawn there)"
    )]
    NotPositiveOnLog {
        /// The series' label or the column's name.
        series: String,
        /// The logarithmic axis the value is drawn along.
        coordinate: Coordinate,
        /// The value's index in its series.
        index: usize,
        /// The value.
        value: f64,
    },
    /// A value too large (|v| > 10³⁰⁰), or outside 10⁻¹⁰⁰..=10¹⁰⁰ on a logarithmic axis, for
    /// the axis's range, its margin and its ticks to stay finite.
    #[error(
        "the {coordinate} value {value:e} at index {index} of `{series}` is out of range \
         (a figure takes |v| ≤ 1e300, and 1e-100 ≤ v ≤ 1e100 on a logarithmic axis)"
    )]
    OutOfRange {
        /// The series' label or the column's name.
        series: String,
        /// The axis the value is drawn along.
        coordinate: Coordinate,
        /// The value's index in its series.
        index: usize,
        /// The value.
        value: f64,
    },
    /// A column asked for by name is neither a state column nor a quantity of the trajectory.
    #[error("the trajectory has no column `{name}` (it has: {available})")]
    UnknownColumn {
        /// The name asked for.
        name: String,
        /// The trajectory's state columns and quantities, comma-separated.
        available: String,
    },
    /// The file or its directory could not be written.
    #[error("cannot write {}: {source}", path.display())]
    Io {
        /// The file (or the directory) that could not be written.
        path: PathBuf,
        /// What the file system said.
        #[source]
        source: std::io::Error,
    },
    /// The drawing backend refused the figure.
    #[error("cannot draw {}: {message}", path.display())]
    Backend {
        /// The figure's file.
        path: PathBuf,
        /// What the backend said.
        message: String,
    },
}
