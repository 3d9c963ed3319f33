//! Series against time: plain columns, or a trajectory's columns by name.

use std::path::{Path, PathBuf};

use super::error::PlotError;
use super::figure::{Figure, Style, figure};
use precess_core::ode::{StateColumns, Trajectory};

/// Draws each column `(name, values)` against the times `t`, one line per column, to `path`
/// (see [`figure`](super::figure) for where), and returns the path written.
///
/// The x axis is labelled `t (s)` (precess's times are in seconds), the y axis with the
/// columns' names and their units as [`unit_of`](super::unit_of) knows them (`theta, phi
/// (rad)`, `x (m), energy (J)`; up to three names, else `value`); the legend names each
/// column. A name the table does not know keeps its own spelling, so a column named
/// `q1 (m)` carries its unit in.
///
/// # Errors
/// [`PlotError::NoSeries`] for no columns, [`PlotError::EmptySeries`] for an empty `t`,
/// [`PlotError::LengthMismatch`] for a column not as long as `t`, [`PlotError::NonFinite`]
/// for a NaN or infinite value (the series `t` for a time), [`PlotError::Io`] and
/// [`PlotError::Backend`] as [`figure`](super::figure).
///
/// # Examples
/// ```
/// use precess::plot::{PlotError, time_series};
/// let t = [0.0, 0.5, 1.0, 1.5];
/// let theta = [0.2, 0.3, 0.35, 0.3];
/// let path = std::env::temp_dir().join("precess-doc-series/theta.svg");
/// time_series(&path, "Nutation", &t, &[("θ", &theta)])?;
/// // A column shorter than the times is refused with both lengths.
/// let short = [0.2, 0.3];
/// let err = time_series(&path, "Nutation", &t, &[("θ", &short)]).unwrap_err();
/// assert!(matches!(err, PlotError::LengthMismatch { expected: 4, got: 2, .. }));
/// # Ok::<(), PlotError>(())
/// ```
pub fn time_series(
    path: impl AsRef<Path>,
    title: &str,
    t: &[f64],
    columns: &[(&str, &[f64])],
) -> Result<PathBuf, PlotError> {
    if columns.is_empty() {
        return Err(PlotError::NoSeries);
    }
    if t.is_empty() {
        return Err(PlotError::EmptySeries { series: "t".into() });
    }
    // A bad time is reported against `t`, not against the first column drawn with it.
    for (index, &v) in t.iter().enumerate() {
        super::figure::check("t", super::Coordinate::X, index, v, super::Scale::Linear)?;
    }
    let series = super::paired(t, columns, Style::Line)?;
    let names: Vec<&str> = columns.iter().map(|c| c.0).collect();
    let x_label = super::with_unit("t", super::unit_of("t").unwrap_or(""));
    let axes = Figure::new(title).axes(x_label, super::units::columns_label(&names));
    figure(path, &axes, &series)
}

/// Draws the columns `names` of `trajectory` against its times: state columns (named as the
/// CSV names them, see [`Trajectory::set_state_names`]) or derived quantities; no names draws
/// every state column.
///
/// # Errors
/// [`PlotError::UnknownColumn`] for a name the trajectory does not have (the error lists
/// those it has), then as [`time_series`].
///
/// # Examples
/// A harmonic oscillator ẍ = −x from x = 1 at rest, and its energy:
/// ```
/// use precess::ode::{AdaptiveConfig, Dop853, FnSystem, Run};
/// use precess::plot;
/// let sys = FnSystem(|_t: f64, y: &[f64; 2], f: &mut [f64; 2]| *f = [y[1], -y[0]]);
/// let mut ode = Dop853::new(&sys, 0.0, [1.0, 0.0], AdaptiveConfig::with_tol(1e-10, 1e-10))?;
/// let mut out = Run::new(&mut ode, 10.0)
///     .sample_every(0.05)
///     .quantity("energy", |_t, y| 0.5 * (y[0] * y[0] + y[1] * y[1]))
///     .integrate()?;
/// out.trajectory.set_state_names(["x", "v"])?;
/// let dir = std::env::temp_dir().join("precess-doc-trajectory");
/// plot::trajectory(dir.join("oscillator.svg"), "ẍ = −x", &out.trajectory, &["x", "energy"])?;
/// let err = plot::trajectory(dir.join("no.svg"), "", &out.trajectory, &["theta"]).unwrap_err();
/// assert_eq!(err.to_string(), "the trajectory has no column `theta` (it has: x, v, energy)");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn trajectory<St: StateColumns>(
    path: impl AsRef<Path>,
    title: &str,
    trajectory: &Trajectory<St>,
    names: &[&str],
) -> Result<PathBuf, PlotError> {
    let columns: Vec<(String, Vec<f64>)> = if names.is_empty() {
        let state = trajectory.state_column_names();
        (0..state.len())
            .map(|j| (state[j].clone(), state_column(trajectory, j)))
            .collect()
    } else {
        names
            .iter()
            .map(|&name| Ok((name.to_string(), column(trajectory, name)?)))
            .collect::<Result<_, PlotError>>()?
    };
    let borrowed: Vec<(&str, &[f64])> = columns
        .iter()
        .map(|(n, v)| (n.as_str(), v.as_slice()))
        .collect();
    time_series(path, title, trajectory.times(), &borrowed)
}

/// State column `j` over all samples.
fn state_column<St: StateColumns>(trajectory: &Trajectory<St>, j: usize) -> Vec<f64> {
    trajectory.states().iter().map(|s| s.column(j)).collect()
}

/// The column `name` of `trajectory`: a state column, else a derived quantity.
pub(super) fn column<St: StateColumns>(
    trajectory: &Trajectory<St>,
    name: &str,
) -> Result<Vec<f64>, PlotError> {
    let state = trajectory.state_column_names();
    if let Some(j) = state.iter().position(|n| n == name) {
        return Ok(state_column(trajectory, j));
    }
    trajectory
        .column(name)
        .ok_or_else(|| PlotError::UnknownColumn {
            name: name.to_string(),
            available: state
                .iter()
                .chain(trajectory.quantity_names())
                .map(String::as_str)
                .collect::<Vec<_>>()
                .join(", "),
        })
}
