//! The figure every call draws: labelled axes, one or more series, a legend, written as SVG.

use std::path::{Path, PathBuf};

use plotters::prelude::*;

use super::axes::{Scale, axis_range, extent, tick_label};
use super::error::{Coordinate, PlotError};

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Style {
    /// A solid line through the points in order.
    #[default]
    Line,
    /// A marker at each point and no line (measurements beside a theory curve).
    Markers,
    /// A line with a marker at each point (a work–precision curve).
    LineAndMarkers,
    /// A dashed line (a variant of another series, drawn in its colour).
    Dashed,
}

/// One curve of a figure: a legend label, points (x, y) and how to draw them.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// The legend's label.
    pub label: String,
    /// The points (x, y), drawn in this order.
    pub points: Vec<(f64, f64)>,
    /// Line, markers, both, or dashed.
    pub style: Style,
    /// The colour, as an index into the palette (`None`: the series' own index).
    pub color: Option<usize>,
}

impl Series {
    /// A series drawn as a line.
    pub fn line(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self::styled(label, points, Style::Line)
    }

    /// A series drawn as markers.
    pub fn markers(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self::styled(label, points, Style::Markers)
    }

    /// A series drawn as a line with a marker at each point.
    pub fn line_and_markers(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self::styled(label, points, Style::LineAndMarkers)
    }

    /// A series drawn in `style`.
    pub fn styled(label: impl Into<String>, points: Vec<(f64, f64)>, style: Style) -> Self {
        Self {
            label: label.into(),
            points,
            style,
            color: None,
        }
    }

    /// The same series in palette colour `index` (so that two series share a colour).
    pub fn with_color(mut self, index: usize) -> Self {
        self.color = Some(index);
        self
    }
}

/// A figure's title, axis labels and scales.
///
/// ```
/// use precess::plot::{Figure, Scale};
/// let f = Figure::new("Energy error").axes("t / s", "|ΔE/E|").log_y();
/// assert_eq!((f.x_scale, f.y_scale), (Scale::Linear, Scale::Log));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// The title above the plot.
    pub title: String,
    /// The label of the x axis.
    pub x_label: String,
    /// The label of the y axis.
    pub y_label: String,
    /// The x axis's scale.
    pub x_scale: Scale,
    /// The y axis's scale.
    pub y_scale: Scale,
}

impl Figure {
    /// A figure titled `title`, with axes labelled `x` and `y`, both linear.
    pub fn new(title: impl Into<String>) -> Self {
        Self {
            title: title.into(),
            x_label: "x".into(),
            y_label: "y".into(),
            x_scale: Scale::Linear,
            y_scale: Scale::Linear,
        }
    }

    /// The same figure with axis labels `x` and `y`.
    pub fn axes(mut self, x: impl Into<String>, y: impl Into<String>) -> Self {
        self.x_label = x.into();
        self.y_label = y.into();
        self
    }

    /// The same figure with a logarithmic x axis.
    pub fn log_x(mut self) -> Self {
        self.x_scale = Scale::Log;
        self
    }

    /// The same figure with a logarithmic y axis.
    pub fn log_y(mut self) -> Self {
        self.y_scale = Scale::Log;
        self
    }
}

/// Width and height of every figure, in SVG pixels.
pub const SIZE: (u32, u32) = (900, 560);

/// Colours of successive series (those of matplotlib's tab10, which most readers know).
const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(23, 190, 207),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
];

/// Writes `series` as an SVG figure to `path` (under [`DEFAULT_DIR`](super::DEFAULT_DIR)
/// when `path` is a bare file name), creating its directory, and returns the path written.
///
/// The axes span the data with the margin of [`axis_range`]; the legend names every series.
///
/// # Errors
/// [`PlotError::NoSeries`] for no series, [`PlotError::EmptySeries`] for a series without
/// points, [`PlotError::NonFinite`] for a NaN or infinite coordinate,
/// [`PlotError::NotPositiveOnLog`] for a value ≤ 0 on a logarithmic axis,
/// [`PlotError::OutOfRange`] for |v| > 10³⁰⁰, or v outside 10⁻¹⁰⁰..=10¹⁰⁰ on a logarithmic axis (each with
/// the series, the index and the value), [`PlotError::Io`] when the directory or the file cannot
/// be written, [`PlotError::Backend`] when plotters refuses the figure.
///
/// # Examples
/// ```
/// use precess::plot::{Figure, Series, figure};
/// let dir = std::env::temp_dir().join("precess-doc-figure");
/// let theory: Vec<_> = (0..=50).map(|k| (k as f64 / 10.0, (k as f64 / 10.0).powi(2))).collect();
/// let measured = vec![(1.0, 1.02), (2.0, 3.9), (4.0, 16.3)];
/// let path = figure(
///     dir.join("squares.svg"),
///     &Figure::new("Measured against theory").axes("x", "x²"),
///     &[Series::line("theory", theory), Series::markers("measured", measured)],
/// )?;
/// assert!(std::fs::read_to_string(path)?.contains("Measured against theory"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn figure(
    path: impl AsRef<Path>,
    figure: &Figure,
    series: &[Series],
) -> Result<PathBuf, PlotError> {
    let path = super::output_path(path.as_ref());
    let (x_range, y_range) = ranges(figure, series)?;
    let mut svg = String::new();
    render(&mut svg, figure, series, x_range, y_range).map_err(|e| PlotError::Backend {
        path: path.clone(),
        message: e.to_string(),
    })?;
    super::write(&path, &svg)?;
    Ok(path)
}

/// An axis's shown range, (from, to).
type Span = (f64, f64);

/// Checks every point and returns the padded x and y ranges.
fn ranges(figure: &Figure, series: &[Series]) -> Result<(Span, Span), PlotError> {
    if series.is_empty() {
        return Err(PlotError::NoSeries);
    }
    for s in series {
        if s.points.is_empty() {
            return Err(PlotError::EmptySeries {
                series: s.label.clone(),
            });
        }
        for (index, &(x, y)) in s.points.iter().enumerate() {
            check(&s.label, Coordinate::X, index, x, figure.x_scale)?;
            check(&s.label, Coordinate::Y, index, y, figure.y_scale)?;
        }
    }
    let all = || series.iter().flat_map(|s| s.points.iter());
    // Every series has a point, so both extents exist.
    let (x0, x1) = extent(all().map(|p| p.0)).unwrap_or((0.0, 1.0));
    let (y0, y1) = extent(all().map(|p| p.1)).unwrap_or((0.0, 1.0));
    Ok((
        axis_range(x0, x1, figure.x_scale),
        axis_range(y0, y1, figure.y_scale),
    ))
}

/// One value's check: finite, and positive on a logarithmic axis.
pub(crate) fn check(
    series: &str,
    coordinate: Coordinate,
    index: usize,
    value: f64,
    scale: Scale,
) -> Result<(), PlotError> {
    if !value.is_finite() {
        return Err(PlotError::NonFinite {
            series: series.to_string(),
            coordinate,
            index,
            value,
        });
    }
    if scale == Scale::Log && value <= 0.0 {
        return Err(PlotError::NotPositiveOnLog {
            series: series.to_string(),
            coordinate,
            index,
            value,
        });
    }
    // Beyond these the padded range, or plotters' ticks, would overflow to infinity.
    let out = match scale {
        Scale::Linear => value.abs() > LIMIT,
        // plotters' logarithmic ticks do not finish over some 600 decades.
        Scale::Log => !(1.0 / LOG_LIMIT..=LOG_LIMIT).contains(&value),
    };
    if out {
        return Err(PlotError::OutOfRange {
            series: series.to_string(),
            coordinate,
            index,
            value,
        });
    }
    Ok(())
}

/// The largest magnitude a figure takes on a linear axis.
const LIMIT: f64 = 1e300;

/// The largest value a logarithmic axis takes, and its inverse the smallest.
const LOG_LIMIT: f64 = 1e100;

/// `v` as a tick shows it: 0 for a linear tick that is 0 but for rounding (−2.2e-16 on an
/// axis 2 wide). A log axis has no ticks that small beside its others.
fn snap(v: f64, span: f64) -> f64 {
    if v.abs() < 1e-9 * span.abs() { 0.0 } else { v }
}

/// Draws the checked figure into `svg`.
fn render(
    svg: &mut String,
    figure: &Figure,
    series: &[Series],
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::with_string(svg, SIZE).into_drawing_area();
    root.fill(&WHITE)?;
    let mut builder = ChartBuilder::on(&root);
    builder
        .caption(figure.title.as_str(), ("sans-serif", 22))
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(80);
    // Each combination of linear and logarithmic axes is its own coordinate type.
    macro_rules! draw {
        ($x:expr, $y:expr) => {{
            let mut chart = builder.build_cartesian_2d($x, $y)?;
            chart
                .configure_mesh()
                .x_desc(figure.x_label.as_str())
                .y_desc(figure.y_label.as_str())
                .axis_desc_style(("sans-serif", 16))
                .label_style(("sans-serif", 13))
                .light_line_style(RGBColor(235, 235, 235))
                .x_label_formatter(&|v| tick_label(snap(*v, x1 - x0)))
                .y_label_formatter(&|v| tick_label(snap(*v, y1 - y0)))
                .draw()?;
            for (k, s) in series.iter().enumerate() {
                let color = PALETTE[s.color.unwrap_or(k) % PALETTE.len()];
                let points = s.points.iter().copied();
                let line = color.stroke_width(2);
                let legend = match s.style {
                    Style::Line | Style::LineAndMarkers => {
                        if s.style == Style::LineAndMarkers {
                            chart.draw_series(
                                points.clone().map(|p| Circle::new(p, 3, color.filled())),
                            )?;
                        }
                        chart.draw_series(LineSeries::new(points, line))?
                    }
                    Style::Dashed => {
                        chart.draw_series(DashedLineSeries::new(points, 6, 4, line))?
                    }
                    Style::Markers => {
                        chart.draw_series(points.map(|p| Circle::new(p, 4, color.filled())))?
                    }
                };
                match s.style {
                    Style::Markers => legend
                        .label(s.label.as_str())
                        .legend(move |(x, y)| Circle::new((x + 10, y), 4, color.filled())),
                    _ => legend
                        .label(s.label.as_str())
                        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], line)),
                };
            }
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::UpperRight)
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK)
                .label_font(("sans-serif", 13))
                .draw()?;
        }};
    }
    match (figure.x_scale, figure.y_scale) {
        (Scale::Linear, Scale::Linear) => draw!(x0..x1, y0..y1),
        (Scale::Log, Scale::Linear) => draw!((x0..x1).log_scale(), y0..y1),
        (Scale::Linear, Scale::Log) => draw!(x0..x1, (y0..y1).log_scale()),
        (Scale::Log, Scale::Log) => draw!((x0..x1).log_scale(), (y0..y1).log_scale()),
    }
    root.present()?;
    Ok(())
}
