//! Figures from the library: a trajectory against time, a phase portrait, a work–precision
//! plot, a heat map over two parameters, one call each, written as SVG (plotters' SVG
//! backend); the crate behind the facade's `plot` feature (`precess::plot`).
//!
//! | call | draws |
//! | --- | --- |
//! | [`trajectory`] | chosen columns of a [`Trajectory`](precess_core::ode::Trajectory) (state or quantities, by name) against t |
//! | [`time_series`] | plain columns `(name, values)` against a time column |
//! | [`trajectory_phase_portrait`] | one column of a trajectory against another (q against q̇) |
//! | [`phase_portrait`] | one plain column against another |
//! | [`work_precision`] | error against time or evaluations, log–log, one line per method |
//! | [`figure`] | any [`Series`] (lines, markers, dashed) on a [`Figure`]'s axes |
//! | [`map`] | a value over a grid of two parameters (linear or log₁₀ axes) with its colour bar |
//!
//! Axes carry units: a trajectory's columns are labelled with the unit their name has by the
//! scenes' conventions ([`unit_of`]: `theta (rad)`, `energy (J)`, `t (s)`), a map's axes and
//! colour bar with the unit they are given ([`with_unit`]).
//!
//! Every call checks its data first and returns a [`PlotError`] naming the series, the index
//! and the value that cannot be drawn; the axes span the data with the margin of
//! [`axis_range`], ticks read as [`tick_label`] writes them, and a legend names each series.
//! A path with a directory is written there (the directory is created); a bare file name is
//! written under [`DEFAULT_DIR`], where the examples write theirs. Each call returns the path
//! it wrote. `docs/plots.md` shows the figures.
//!
//! # Examples
//! ```
//! use precess::plot;
//! let t: Vec<f64> = (0..200).map(|k| k as f64 * 0.05).collect();
//! let x: Vec<f64> = t.iter().map(|t| t.cos()).collect();
//! let v: Vec<f64> = t.iter().map(|t| -t.sin()).collect();
//! let dir = std::env::temp_dir().join("precess-doc-plot");
//! plot::time_series(dir.join("oscillator.svg"), "An oscillator", &t, &[("x", &x), ("v", &v)])?;
//! plot::phase_portrait(dir.join("oscillator-phase.svg"), "Its phase portrait", ("x", &x), ("v", &v))?;
//! # Ok::<(), precess::plot::PlotError>(())
//! ```
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod axes;
mod error;
mod figure;
mod map;
mod map_draw;
mod phase;
mod series;
mod units;
mod work_precision;

use std::path::{Path, PathBuf};

pub use axes::{Scale, axis_range, tick_label};
pub use error::{Coordinate, PlotError, RangeFault};
pub use figure::{Figure, SIZE, Series, Style, figure};
pub use map::{ColourBar, Map, MapAxis, map};
pub use map_draw::MAP_SIZE;
pub use phase::{phase_portrait, trajectory_phase_portrait};
pub use series::{time_series, trajectory};
pub use units::{unit_of, with_unit};
pub use work_precision::{Work, work_precision};

/// Where a figure given as a bare file name is written (relative to the working directory,
/// which `cargo run` leaves at the directory it was called from).
pub const DEFAULT_DIR: &str = "target/precess-plots";

/// The path a figure given as `path` is written to: `path` itself when it names a directory,
/// else `path` under [`DEFAULT_DIR`].
///
/// ```
/// use std::path::Path;
/// use precess::plot::output_path;
/// assert_eq!(output_path(Path::new("top.svg")), Path::new("target/precess-plots/top.svg"));
/// assert_eq!(output_path(Path::new("figs/top.svg")), Path::new("figs/top.svg"));
/// assert_eq!(output_path(Path::new("./top.svg")), Path::new("./top.svg"));
/// ```
pub fn output_path(path: &Path) -> PathBuf {
    match path.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => path.to_path_buf(),
        _ => Path::new(DEFAULT_DIR).join(path),
    }
}

/// Writes `text` to `path`, creating its directory first.
fn write(path: &Path, text: &str) -> Result<(), PlotError> {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|source| PlotError::Io {
            path: dir.to_path_buf(),
            source,
        })?;
    }
    std::fs::write(path, text).map_err(|source| PlotError::Io {
        path: path.to_path_buf(),
        source,
    })
}

/// Checks that each column is as long as `x` and pairs it with `x` into a [`Series`] drawn
/// as `style`.
fn paired(x: &[f64], columns: &[(&str, &[f64])], style: Style) -> Result<Vec<Series>, PlotError> {
    columns
        .iter()
        .map(|&(name, values)| {
            if values.len() != x.len() {
                return Err(PlotError::LengthMismatch {
                    series: name.to_string(),
                    expected: x.len(),
                    got: values.len(),
                });
            }
            let points = x.iter().copied().zip(values.iter().copied()).collect();
            Ok(Series::styled(name, points, style))
        })
        .collect()
}
