//! Work–precision plots: error against the work it cost, log–log, one curve per method.

use std::path::{Path, PathBuf};

use super::axes::Scale;
use super::error::{Coordinate, PlotError};
use super::figure::{Figure, Series, check, figure};

/// What a work–precision plot's x axis measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Work {
    /// Wall time in seconds (`time / s`).
    Seconds,
    /// Right-hand-side evaluations (`evaluations`).
    Evaluations,
    /// Steps taken (`steps`).
    Steps,
}

impl Work {
    /// The x axis's label.
    pub fn label(self) -> &'static str {
        match self {
            Work::Seconds => "time / s",
            Work::Evaluations => "evaluations",
            Work::Steps => "steps",
        }
    }
}

/// Draws each method's points (work, error) on logarithmic axes to `path` (see
/// [`figure`](super::figure) for where), each series's points joined in order of work, and
/// returns the path written.
///
/// Give each method as [`Series::line_and_markers`] (a line with a marker per run); a peer's
/// points may be [`Series::markers`], a variant of a method [`Style::Dashed`](super::Style)
/// in the method's colour ([`Series::with_color`]).
///
/// # Errors
/// [`PlotError::NotPositiveOnLog`] for a work or an error ≤ 0 (an exact result has no place
/// on a log axis: leave it out or floor it), then as [`figure`](super::figure).
///
/// # Examples
/// Two methods of orders 4 and 8, error = C·N^(−p):
/// ```
/// use precess::plot::{Series, Work, work_precision};
/// let runs = |c: f64, p: f64| -> Vec<(f64, f64)> {
///     [1e3, 3e3, 1e4, 3e4].iter().map(|&n: &f64| (n, c * n.powf(-p))).collect()
/// };
/// let path = std::env::temp_dir().join("precess-doc-wp/orders.svg");
/// work_precision(&path, "Work–precision", Work::Evaluations, &[
///     Series::line_and_markers("RK4", runs(1e2, 4.0)),
///     Series::line_and_markers("DOP853", runs(1e6, 8.0)),
/// ])?;
/// # Ok::<(), precess::plot::PlotError>(())
/// ```
pub fn work_precision(
    path: impl AsRef<Path>,
    title: &str,
    work: Work,
    methods: &[Series],
) -> Result<PathBuf, PlotError> {
    // Checked in the order given, so that an error's index is the caller's.
    for s in methods {
        for (index, &(w, e)) in s.points.iter().enumerate() {
            check(&s.label, Coordinate::X, index, w, Scale::Log)?;
            check(&s.label, Coordinate::Y, index, e, Scale::Log)?;
        }
    }
    let sorted: Vec<Series> = methods
        .iter()
        .map(|s| {
            let mut s = s.clone();
            s.points.sort_by(|a, b| a.0.total_cmp(&b.0));
            s
        })
        .collect();
    figure(
        path,
        &Figure::new(title)
            .axes(work.label(), "error")
            .log_x()
            .log_y(),
        &sorted,
    )
}
