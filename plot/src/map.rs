//! A heat map: one value per cell of a grid over two parameters (the largest Lyapunov
//! exponent over initial tilt and spin, a tippe top's time to turn over over spin and
//! friction), with a colour bar that says what the colours mean.

use std::path::{Path, PathBuf};

use super::axes::{Scale, axis_range, extent};
use super::error::{PlotError, RangeFault};

/// One parameter axis of a [`Map`]: its label and unit, the outer edges of the grid's cells
/// along it, and its scale.
///
/// On a linear axis the cells are equally wide; on a logarithmic one equally wide in log₁₀
/// (each spans the same ratio), so a grid of parameters spaced by equal ratios fills it.
#[derive(Debug, Clone, PartialEq)]
pub struct MapAxis {
    /// What the parameter is (`initial spin ω3`).
    pub label: String,
    /// Its unit (`rad/s`; empty for a pure number).
    pub unit: String,
    /// The outer edges of the first and the last cell, `(from, to)` with `from < to`.
    pub edges: (f64, f64),
    /// Linear or logarithmic.
    pub scale: Scale,
}

impl MapAxis {
    /// A linear axis from `edges.0` to `edges.1`.
    pub fn linear(label: impl Into<String>, unit: impl Into<String>, edges: (f64, f64)) -> Self {
        Self {
            label: label.into(),
            unit: unit.into(),
            edges,
            scale: Scale::Linear,
        }
    }

    /// A logarithmic (log₁₀) axis from `edges.0` to `edges.1`, both positive.
    pub fn log(label: impl Into<String>, unit: impl Into<String>, edges: (f64, f64)) -> Self {
        Self {
            scale: Scale::Log,
            ..Self::linear(label, unit, edges)
        }
    }

    /// The edges of `n` cells, `n + 1` values from `edges.0` to `edges.1`.
    pub(crate) fn cell_edges(&self, n: usize) -> Vec<f64> {
        let (a, b) = self.edges;
        (0..=n)
            .map(|k| {
                let f = k as f64 / n as f64;
                match self.scale {
                    Scale::Linear => a + f * (b - a),
                    Scale::Log => a * (b / a).powf(f),
                }
            })
            .collect()
    }
}

/// The colour bar of a [`Map`]: what the colour means, its unit, the values the colour ramp
/// spans and its scale.
#[derive(Debug, Clone, PartialEq)]
pub struct ColourBar {
    /// What a cell's value is (`λ₁`).
    pub label: String,
    /// Its unit (`1/s`; empty for a pure number).
    pub unit: String,
    /// The values at the ramp's dark and bright ends; cells beyond take the end's colour.
    /// `None`: the smallest and the largest finite cell.
    pub range: Option<(f64, f64)>,
    /// Linear or logarithmic (every value must then be positive, or NaN).
    pub scale: Scale,
}

impl ColourBar {
    /// A linear colour bar spanning the finite cells.
    pub fn new(label: impl Into<String>, unit: impl Into<String>) -> Self {
        Self {
            label: label.into(),
            unit: unit.into(),
            range: None,
            scale: Scale::Linear,
        }
    }

    /// The same bar spanning `from..to` (cells outside take the colour of the nearer end).
    pub fn range(mut self, from: f64, to: f64) -> Self {
        self.range = Some((from, to));
        self
    }

    /// The same bar on a logarithmic scale.
    pub fn log(mut self) -> Self {
        self.scale = Scale::Log;
        self
    }
}

/// A heat map's title, parameter axes and colour bar.
#[derive(Debug, Clone, PartialEq)]
pub struct Map {
    /// The title above the map.
    pub title: String,
    /// The horizontal parameter (a row's cells run along it).
    pub x: MapAxis,
    /// The vertical parameter (row 0 is its lowest cells).
    pub y: MapAxis,
    /// What the colours mean.
    pub colour: ColourBar,
}

/// Draws `rows` as an SVG heat map to `path` (see [`figure`](super::figure) for where) and
/// returns the path written.
///
/// `rows[j][i]` is the value of the cell i along x, j along y (row 0 lowest): the cells
/// divide each axis's edges into equal steps (equal ratios on a logarithmic axis). Each cell
/// is coloured on a perceptually ordered ramp, dark for the colour bar's low end and bright
/// for its high end (linear in the value, or in log₁₀ of it); a NaN cell (a failed run, a
/// value that does not exist) is grey, and the legend under the colour bar counts them.
/// Axis labels read `label (unit)`.
///
/// # Errors
/// [`PlotError::EmptyGrid`] for no rows or an empty first row, [`PlotError::RaggedGrid`] for
/// a row not as long as the first, [`PlotError::CellOutOfRange`] for an infinite cell (or
/// beyond ±10³⁰⁰), [`PlotError::CellNotPositiveOnLog`] for a cell ≤ 0 on a logarithmic colour
/// bar, [`PlotError::InvalidRange`] for edges or a colour range that are not finite, do not
/// increase or are not positive on a logarithmic axis; [`PlotError::Io`] and
/// [`PlotError::Backend`] as [`figure`](super::figure).
///
/// # Examples
/// The period 2π√(ℓ/g) of a pendulum over length and gravity, ℓ on a log axis:
/// ```
/// use precess::plot::{self, ColourBar, Map, MapAxis, PlotError};
/// let (nx, ny) = (30, 20);
/// let length = |i: usize| 0.1 * 100f64.powf((i as f64 + 0.5) / nx as f64);
/// let gravity = |j: usize| 1.0 + 24.0 * (j as f64 + 0.5) / ny as f64;
/// let rows: Vec<Vec<f64>> = (0..ny)
///     .map(|j| (0..nx).map(|i| std::f64::consts::TAU * (length(i) / gravity(j)).sqrt()).collect())
///     .collect();
/// let map = Map {
///     title: "Period of a pendulum".into(),
///     x: MapAxis::log("length ℓ", "m", (0.1, 10.0)),
///     y: MapAxis::linear("gravity g", "m/s²", (1.0, 25.0)),
///     colour: ColourBar::new("period", "s").log(),
/// };
/// let path = plot::map(std::env::temp_dir().join("precess-doc-map/period.svg"), &map, &rows)?;
/// assert!(std::fs::read_to_string(path)?.contains("length ℓ (m)"));
/// // A ragged grid is refused with the row and both lengths.
/// let err = plot::map("ragged.svg", &map, &[vec![1.0, 2.0], vec![3.0]]).unwrap_err();
/// assert!(matches!(err, PlotError::RaggedGrid { row: 1, expected: 2, got: 1 }));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn map<R: AsRef<[f64]>>(
    path: impl AsRef<Path>,
    map: &Map,
    rows: &[R],
) -> Result<PathBuf, PlotError> {
    let path = super::output_path(path.as_ref());
    let grid = check_grid(rows, map.colour.scale)?;
    check_range("x", map.x.edges, map.x.scale)?;
    check_range("y", map.y.edges, map.y.scale)?;
    let colours = colour_range(&map.colour, &grid)?;
    let mut svg = String::new();
    super::map_draw::render(&mut svg, map, &grid, colours).map_err(|e| PlotError::Backend {
        path: path.clone(),
        message: e.to_string(),
    })?;
    super::write(&path, &svg)?;
    Ok(path)
}

/// A checked grid: `nx` cells a row, row by row from the lowest y.
pub(crate) struct Grid {
    pub(crate) nx: usize,
    pub(crate) ny: usize,
    pub(crate) values: Vec<f64>,
}

/// Checks the shape and every cell of `rows`.
fn check_grid<R: AsRef<[f64]>>(rows: &[R], scale: Scale) -> Result<Grid, PlotError> {
    let nx = rows.first().map_or(0, |r| r.as_ref().len());
    if nx == 0 {
        return Err(PlotError::EmptyGrid {
            rows: rows.len(),
            columns: nx,
        });
    }
    let mut values = Vec::with_capacity(nx * rows.len());
    for (row, cells) in rows.iter().enumerate() {
        let cells = cells.as_ref();
        if cells.len() != nx {
            return Err(PlotError::RaggedGrid {
                row,
                expected: nx,
                got: cells.len(),
            });
        }
        for (column, &value) in cells.iter().enumerate() {
            if value.is_nan() {
                values.push(value);
                continue;
            }
            if scale == Scale::Log && value <= 0.0 {
                return Err(PlotError::CellNotPositiveOnLog { row, column, value });
            }
            if !within(value, scale) {
                return Err(PlotError::CellOutOfRange { row, column, value });
            }
            values.push(value);
        }
    }
    Ok(Grid {
        nx,
        ny: rows.len(),
        values,
    })
}

/// Whether a finite, positive-on-log value is within what an axis of `scale` can show (an
/// infinity is not).
fn within(v: f64, scale: Scale) -> bool {
    match scale {
        Scale::Linear => v.abs() <= 1e300,
        Scale::Log => (1e-100..=1e100).contains(&v),
    }
}

/// Checks that `(from, to)` is a range an axis of `scale` can show.
fn check_range(axis: &'static str, (from, to): (f64, f64), scale: Scale) -> Result<(), PlotError> {
    let fault = if !from.is_finite() || !to.is_finite() {
        Some(RangeFault::NotFinite)
    } else if scale == Scale::Log && (from <= 0.0 || to <= 0.0) {
        Some(RangeFault::NotPositiveOnLog)
    } else if !within(from, scale) || !within(to, scale) {
        Some(RangeFault::OutOfRange)
    } else if from >= to {
        Some(RangeFault::NotIncreasing)
    } else {
        None
    };
    match fault {
        Some(fault) => Err(PlotError::InvalidRange {
            axis,
            from,
            to,
            fault,
        }),
        None => Ok(()),
    }
}

/// The values at the colour ramp's ends: the bar's range when given (checked), else the
/// finite cells' extent, widened as [`axis_range`] widens a single value.
fn colour_range(bar: &ColourBar, grid: &Grid) -> Result<(f64, f64), PlotError> {
    if let Some(range) = bar.range {
        check_range("colour bar", range, bar.scale)?;
        return Ok(range);
    }
    let finite = grid.values.iter().copied().filter(|v| !v.is_nan());
    Ok(match (extent(finite), bar.scale) {
        (Some((lo, hi)), _) if lo < hi => (lo, hi),
        (Some((v, _)), scale) => axis_range(v, v, scale),
        // Every cell is NaN: the bar still reads, the map is all grey.
        (None, Scale::Linear) => (0.0, 1.0),
        (None, Scale::Log) => (1.0, 10.0),
    })
}
