//! What can stop a figure from being drawn: the data (empty, ragged, non-finite, not positive
//! on a logarithmic axis), a map's grid or ranges, a column name, or the file.

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

/// What is wrong with an axis's range (a map's parameter axis or its colour bar).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RangeFault {
    /// An end is NaN or infinite.
    NotFinite,
    /// The range does not increase (`from ≥ to`).
    NotIncreasing,
    /// An end is zero or negative, and the axis is logarithmic.
    NotPositiveOnLog,
    /// An end is beyond ±10³⁰⁰, or outside 10⁻¹⁰⁰..=10¹⁰⁰ on a logarithmic axis.
    OutOfRange,
}

impl fmt::Display for RangeFault {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            RangeFault::NotFinite => "an end is not finite",
            RangeFault::NotIncreasing => "it does not increase (give from < to)",
            RangeFault::NotPositiveOnLog => {
                "an end is not positive, and the axis is logarithmic (only values > 0 can be drawn there)"
            }
            RangeFault::OutOfRange => {
                "an end is out of range (|v| ≤ 1e300, and 1e-100 ≤ v ≤ 1e100 on a logarithmic axis)"
            }
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
    /// A map's grid has no rows, or its first row has no cells.
    #[error(
        "the map's grid is empty ({rows} rows, {columns} cells in the first): a map needs at least one cell"
    )]
    EmptyGrid {
        /// The number of rows.
        rows: usize,
        /// The number of cells in the first row (0 when there is no row).
        columns: usize,
    },
    /// A row of a map's grid is not as long as the first.
    #[error("row {row} of the map's grid has {got} cells where row 0 has {expected}")]
    RaggedGrid {
        /// The row's index (0 is the lowest y).
        row: usize,
        /// The first row's length.
        expected: usize,
        /// This row's length.
        got: usize,
    },
    /// A cell of a map is infinite, beyond ±10³⁰⁰, or outside 10⁻¹⁰⁰..=10¹⁰⁰ on a logarithmic
    /// colour bar (NaN is drawn: a cell without a value).
    #[error(
        "cell (column {column}, row {row}) of the map is {value:e}: a cell is NaN (no value) \
         or finite with |v| ≤ 1e300 (1e-100 ≤ v ≤ 1e100 on a logarithmic colour bar)"
    )]
    CellOutOfRange {
        /// The cell's row (0 is the lowest y).
        row: usize,
        /// The cell's column (0 is the lowest x).
        column: usize,
        /// The value.
        value: f64,
    },
    /// A cell of a map is zero or negative, and the colour bar is logarithmic.
    #[error(
        "cell (column {column}, row {row}) of the map is {value}, and the colour bar is \
         logarithmic (only values > 0, or NaN for no value, can be drawn there)"
    )]
    CellNotPositiveOnLog {
        /// The cell's row (0 is the lowest y).
        row: usize,
        /// The cell's column (0 is the lowest x).
        column: usize,
        /// The value.
        value: f64,
    },
    /// An axis's range cannot be drawn: a map's `x` or `y` axis, or its `colour bar`.
    #[error("the {axis} axis runs from {from} to {to}: {fault}")]
    InvalidRange {
        /// `x`, `y` or `colour bar`.
        axis: &'static str,
        /// The range's start.
        from: f64,
        /// The range's end.
        to: f64,
        /// What is wrong with it.
        fault: RangeFault,
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
