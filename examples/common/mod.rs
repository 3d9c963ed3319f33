//! What the gallery examples share: the table of measured against theory, and line plots
//! written as SVG.
//!
//! Each example is one physical scene; it prints its table and writes its figures to
//! `target/precess-plots/`, or to the directory given as the first command-line argument.

#![allow(dead_code)] // each example uses the part it needs

use std::error::Error;
use std::path::PathBuf;

use plotters::prelude::*;

/// The directory for figures: the first command-line argument, else `target/precess-plots`.
pub fn plot_dir() -> Result<PathBuf, Box<dyn Error>> {
    let dir = std::env::args()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("target/precess-plots"));
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

/// One curve of a figure.
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

/// A tick label: plain decimals for moderate magnitudes, scientific notation otherwise.
fn tick(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 || (1e-2..1e4).contains(&a) {
        let s = format!("{v:.4}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        format!("{v:.1e}")
    }
}

const PALETTE: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(23, 190, 207),
];

/// Writes the series as an SVG line plot to `file` under [`plot_dir`], and returns its path.
pub fn plot(file: &str, axes: &Axes, series: &[Series]) -> Result<PathBuf, Box<dyn Error>> {
    plot_in(&plot_dir()?, file, axes, series)
}

/// As [`plot`], into the directory `dir` (for an example whose arguments are not just a
/// directory).
pub fn plot_in(
    dir: &std::path::Path,
    file: &str,
    axes: &Axes,
    series: &[Series],
) -> Result<PathBuf, Box<dyn Error>> {
    let path = dir.join(file);
    let finite = |v: f64, log: bool| v.is_finite() && (!log || v > 0.0);
    let points = series
        .iter()
        .flat_map(|s| s.points.iter())
        .filter(|(x, y)| finite(*x, axes.log_x) && finite(*y, axes.log_y));
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for &(x, y) in points {
        (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
    }
    if x0 > x1 {
        return Err(format!("nothing to plot in {file}").into());
    }
    let pad = |lo: f64, hi: f64, log: bool| {
        if log {
            (lo / 1.5, hi * 1.5)
        } else {
            let d = if hi > lo {
                0.05 * (hi - lo)
            } else {
                0.5 * lo.abs().max(1.0)
            };
            (lo - d, hi + d)
        }
    };
    let ((x0, x1), (y0, y1)) = (pad(x0, x1, axes.log_x), pad(y0, y1, axes.log_y));

    let root = SVGBackend::new(&path, (900, 560)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut builder = ChartBuilder::on(&root);
    builder
        .caption(axes.title, ("sans-serif", 22))
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(80);
    // Four combinations of linear and logarithmic axes, each its own coordinate type.
    macro_rules! draw {
        ($x:expr, $y:expr) => {{
            let mut chart = builder.build_cartesian_2d($x, $y)?;
            chart
                .configure_mesh()
                .x_desc(axes.x)
                .y_desc(axes.y)
                .axis_desc_style(("sans-serif", 16))
                .label_style(("sans-serif", 13))
                .x_label_formatter(&|v| tick(*v))
                .y_label_formatter(&|v| tick(*v))
                .draw()?;
            for (k, s) in series.iter().enumerate() {
                let color = PALETTE[k % PALETTE.len()];
                let pts = s
                    .points
                    .iter()
                    .copied()
                    .filter(|(x, y)| finite(*x, axes.log_x) && finite(*y, axes.log_y));
                let drawn = if s.markers {
                    chart.draw_series(pts.map(|p| Circle::new(p, 4, color.filled())))?
                } else {
                    chart.draw_series(LineSeries::new(pts, color.stroke_width(2)))?
                };
                drawn
                    .label(s.label.as_str())
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color));
            }
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK)
                .draw()?;
        }};
    }
    match (axes.log_x, axes.log_y) {
        (false, false) => draw!(x0..x1, y0..y1),
        (true, false) => draw!((x0..x1).log_scale(), y0..y1),
        (false, true) => draw!(x0..x1, (y0..y1).log_scale()),
        (true, true) => draw!((x0..x1).log_scale(), (y0..y1).log_scale()),
    }
    root.present()?;
    drop(root);
    Ok(path)
}
