//! What the gallery examples share: the table of measured against theory, the shorthand
//! for figures drawn by `precess::plot`, and their animations (`animation`).
//!
//! Each example is one physical scene; it prints its table and writes its figures to
//! `target/precess-plots/`, or to the directory given as the first command-line argument.

#![allow(dead_code)] // each example uses the part it needs

pub mod animation;

use std::error::Error;
use std::path::PathBuf;

/// The directory for figures: the first command-line argument, else
/// [`precess::plot::DEFAULT_DIR`] (`target/precess-plots`).
///
/// `-h` or `--help` prints the usage and exits; any other argument that starts with `-` is
/// refused, so that a mistyped flag never becomes a directory of that name.
pub fn plot_dir() -> Result<PathBuf, Box<dyn Error>> {
    let dir = match std::env::args().nth(1) {
        None => PathBuf::from(precess::plot::DEFAULT_DIR),
        Some(flag) if flag == "-h" || flag == "--help" => {
            let program = std::env::args().next().unwrap_or_default();
            println!(
                "usage: {program} [DIR]\n\nPrints measured against theory and writes the \
                 figures to DIR (default {}).",
                precess::plot::DEFAULT_DIR
            );
            std::process::exit(0);
        }
        Some(flag) if flag.starts_with('-') => {
            return Err(
                format!("unknown option {flag:?}: the only argument is a directory").into(),
            );
        }
        Some(dir) => PathBuf::from(dir),
    };
    std::fs::create_dir_all(&dir)?;
    Ok(dir)
}

/// Rows of a measured quantity beside its theoretical value.
#[derive(Default)]
pub struct Table {
    rows: Vec<(String, f64, f64)>,
}

impl Table {
    /// Adds a row: what is measured, the measured value, the value theory gives.
    pub fn row(&mut self, quantity: impl Into<String>, measured: f64, theory: f64) {
        self.rows.push((quantity.into(), measured, theory));
    }

    /// The largest relative error of any row.
    pub fn worst(&self) -> f64 {
        self.rows
            .iter()
            .map(|(_, m, t)| relative_error(*m, *t))
            .fold(0.0, f64::max)
    }

    /// Prints the table with each row's relative error |measured − theory| / |theory|.
    pub fn print(&self, title: &str) {
        let width = self
            .rows
            .iter()
            .map(|r| r.0.chars().count())
            .max()
            .unwrap_or(8);
        println!("\n{title}");
        println!(
            "  {:<width$}  {:>20}  {:>20}  {:>10}",
            "quantity", "measured", "theory", "rel. error"
        );
        for (quantity, measured, theory) in &self.rows {
            println!(
                "  {quantity:<width$}  {measured:>20.12e}  {theory:>20.12e}  {:>10.2e}",
                relative_error(*measured, *theory)
            );
        }
    }
}

/// |measured − theory| / |theory| (the absolute error where theory is 0).
pub fn relative_error(measured: f64, theory: f64) -> f64 {
    let gap = (measured - theory).abs();
    if theory == 0.0 {
        gap
    } else {
        gap / theory.abs()
    }
}

/// One curve of a figure (the examples' shorthand for [`precess::plot::Series`]).
pub struct Series {
    /// The legend's label.
    pub label: String,
    /// The points (x, y).
    pub points: Vec<(f64, f64)>,
    /// Drawn as markers rather than a line (measurements beside a theory curve).
    pub markers: bool,
}

impl Series {
    /// A curve drawn as a line.
    pub fn line(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Series {
            label: label.into(),
            points,
            markers: false,
        }
    }

    /// A curve drawn as markers.
    pub fn markers(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Series {
            label: label.into(),
            points,
            markers: true,
        }
    }
}

/// A figure's axes: labels and whether each is logarithmic.
pub struct Axes<'a> {
    /// Title above the plot.
    pub title: &'a str,
    /// Label of the x axis.
    pub x: &'a str,
    /// Label of the y axis.
    pub y: &'a str,
    /// Logarithmic x axis.
    pub log_x: bool,
    /// Logarithmic y axis.
    pub log_y: bool,
}

/// Writes the series as an SVG line plot to `file` under [`plot_dir`], and returns its path.
pub fn plot(file: &str, axes: &Axes, series: &[Series]) -> Result<PathBuf, Box<dyn Error>> {
    plot_in(&plot_dir()?, file, axes, series)
}

/// As [`plot`], into the directory `dir` (for an example whose arguments are not just a
/// directory): [`precess::plot::figure`], except that points a logarithmic axis cannot show
/// (an error of exactly 0) or that are not finite are left out rather than refused, and so
/// is a series left without points, as the examples' figures always did.
pub fn plot_in(
    dir: &std::path::Path,
    file: &str,
    axes: &Axes,
    series: &[Series],
) -> Result<PathBuf, Box<dyn Error>> {
    let drawable = |v: f64, log: bool| v.is_finite() && (!log || v > 0.0);
    let series: Vec<precess::plot::Series> = series
        .iter()
        .map(|s| {
            let points = s
                .points
                .iter()
                .copied()
                .filter(|&(x, y)| drawable(x, axes.log_x) && drawable(y, axes.log_y))
                .collect();
            if s.markers {
                precess::plot::Series::markers(s.label.as_str(), points)
            } else {
                precess::plot::Series::line(s.label.as_str(), points)
            }
        })
        .filter(|s| !s.points.is_empty())
        .collect();
    let mut figure = precess::plot::Figure::new(axes.title).axes(axes.x, axes.y);
    if axes.log_x {
        figure = figure.log_x();
    }
    if axes.log_y {
        figure = figure.log_y();
    }
    Ok(precess::plot::figure(dir.join(file), &figure, &series)?)
}
