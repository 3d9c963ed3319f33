//! Phase portraits: one coordinate against another, or a coordinate against its rate.

use std::path::{Path, PathBuf};

use super::error::PlotError;
use super::figure::{Figure, Series, figure};
use super::units::columns_label;
use precess_core::ode::{StateColumns, Trajectory};

/// Draws `y` against `x` (each `(name, values)`) as one line, in sample order, to `path` (see
/// [`figure`](super::figure) for where), and returns the path written. The axes are labelled
/// with the names and their units as [`unit_of`](super::unit_of) knows them (`theta (rad)`);
/// the legend reads `y against x`.
///
/// # Errors
/// [`PlotError::EmptySeries`] for an empty `x`, [`PlotError::LengthMismatch`] for a `y` not
/// as long as `x`, [`PlotError::NonFinite`] for a NaN or infinite value, [`PlotError::Io`]
/// and [`PlotError::Backend`] as [`figure`](super::figure).
///
/// # Examples
/// A pendulum's separatrix, θ̇ = 2 cos(θ/2):
/// ```
/// use precess::plot::phase_portrait;
/// let theta: Vec<f64> = (-50..=50).map(|k| k as f64 * 0.06).collect();
/// let rate: Vec<f64> = theta.iter().map(|q| 2.0 * (q / 2.0).cos()).collect();
/// let path = std::env::temp_dir().join("precess-doc-phase/separatrix.svg");
/// phase_portrait(&path, "Pendulum separatrix", ("θ", &theta), ("θ̇", &rate))?;
/// # Ok::<(), precess::plot::PlotError>(())
/// ```
pub fn phase_portrait(
    path: impl AsRef<Path>,
    title: &str,
    (x_name, x): (&str, &[f64]),
    (y_name, y): (&str, &[f64]),
) -> Result<PathBuf, PlotError> {
    if x.is_empty() {
        return Err(PlotError::EmptySeries {
            series: x_name.to_string(),
        });
    }
    if y.len() != x.len() {
        return Err(PlotError::LengthMismatch {
            series: y_name.to_string(),
            expected: x.len(),
            got: y.len(),
        });
    }
    let points = x.iter().copied().zip(y.iter().copied()).collect();
    figure(
        path,
        &Figure::new(title).axes(columns_label(&[x_name]), columns_label(&[y_name])),
        &[Series::line(format!("{y_name} against {x_name}"), points)],
    )
}

/// Draws the column `y` of `trajectory` against its column `x` (state columns or derived
/// quantities, by name), e.g. `"theta"` against `"theta_dot"` for q against q̇.
///
/// # Errors
/// [`PlotError::UnknownColumn`] for a name the trajectory does not have, then as
/// [`phase_portrait`].
///
/// # Examples
/// ```
/// use precess::ode::{AdaptiveConfig, Dop853, FnSystem, Run};
/// use precess::plot;
/// // A pendulum θ̈ = −sin θ released at 2 rad.
/// let sys = FnSystem(|_t: f64, y: &[f64; 2], f: &mut [f64; 2]| *f = [y[1], -y[0].sin()]);
/// let mut ode = Dop853::new(&sys, 0.0, [2.0, 0.0], AdaptiveConfig::with_tol(1e-10, 1e-10))?;
/// let mut out = Run::new(&mut ode, 12.0).sample_every(0.02).integrate()?;
/// out.trajectory.set_state_names(["theta", "theta_dot"])?;
/// let path = std::env::temp_dir().join("precess-doc-phase/pendulum.svg");
/// plot::trajectory_phase_portrait(&path, "Pendulum", &out.trajectory, "theta", "theta_dot")?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn trajectory_phase_portrait<St: StateColumns>(
    path: impl AsRef<Path>,
    title: &str,
    trajectory: &Trajectory<St>,
    x: &str,
    y: &str,
) -> Result<PathBuf, PlotError> {
    let xs = super::series::column(trajectory, x)?;
    let ys = super::series::column(trajectory, y)?;
    phase_portrait(path, title, (x, &xs), (y, &ys))
}
