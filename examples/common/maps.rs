//! Figures of many runs: a heat map of one value over a grid of initial conditions (with
//! its colour bar), and a cloud of samples with ellipses over it. Written as SVG like the
//! line plots of `common/mod.rs`; each example that needs them includes this file with
//! `#[path = "common/maps.rs"] mod maps;`.

#![allow(dead_code)] // each example uses the part it needs

use std::error::Error;
use std::path::{Path, PathBuf};

use plotters::prelude::*;

/// Stops of the colour scale, dark (low) to bright (high): a perceptually ordered ramp
/// (close to matplotlib's "inferno"), so the eye reads larger values as brighter and a
/// grey-scale print keeps the order.
const RAMP: [(u8, u8, u8); 9] = [
    (0, 0, 4),
    (31, 12, 72),
    (85, 15, 109),
    (136, 34, 106),
    (186, 54, 85),
    (227, 89, 51),
    (249, 140, 10),
    (249, 201, 50),
    (252, 255, 164),
];

/// The colour of `u` ∈ [0, 1] on [`RAMP`] (clamped; NaN is grey, a failed run).
pub fn ramp(u: f64) -> RGBColor {
    if u.is_nan() {
        return RGBColor(160, 160, 160);
    }
    let x = u.clamp(0.0, 1.0) * (RAMP.len() - 1) as f64;
    let k = (x.floor() as usize).min(RAMP.len() - 2);
    let f = x - k as f64;
    let (a, b) = (RAMP[k], RAMP[k + 1]);
    let mix = |p: u8, q: u8| (p as f64 + (q as f64 - p as f64) * f).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// A grid of values: `values[iy * nx + ix]` at the centre of cell (ix, iy), x over
/// `x_range`, y over `y_range` (the outer edges of the cells).
pub struct Grid<'a> {
    /// Cells along x.
    pub nx: usize,
    /// Cells along y.
    pub ny: usize,
    /// The x extent, edges of the outer cells.
    pub x_range: (f64, f64),
    /// The y extent, edges of the outer cells.
    pub y_range: (f64, f64),
    /// One value per cell, row by row from the lowest y; NaN for a cell without a value.
    pub values: &'a [f64],
}

/// Labels of a heat map.
pub struct HeatLabels<'a> {
    /// Title above the map.
    pub title: &'a str,
    /// The x axis.
    pub x: &'a str,
    /// The y axis.
    pub y: &'a str,
    /// The colour bar: what the colour means.
    pub value: &'a str,
}

/// Writes the grid as an SVG heat map with a colour bar from `lo` to `hi` (values outside
/// are drawn at the ends) to `dir/file`, and returns the path.
pub fn heat_map(
    dir: &Path,
    file: &str,
    labels: &HeatLabels,
    grid: &Grid,
    (lo, hi): (f64, f64),
) -> Result<PathBuf, Box<dyn Error>> {
    if grid.values.len() != grid.nx * grid.ny || grid.nx == 0 || grid.ny == 0 {
        return Err(format!(
            "{file}: {} values for a {} × {} grid",
            grid.values.len(),
            grid.nx,
            grid.ny
        )
        .into());
    }
    let path = dir.join(file);
    draw_heat_map(&path, labels, grid, (lo, hi))?;
    Ok(path)
}

/// The drawing of [`heat_map`], its borrows of the path ended before the path is returned.
fn draw_heat_map(
    path: &Path,
    labels: &HeatLabels,
    grid: &Grid,
    (lo, hi): (f64, f64),
) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (980, 640)).into_drawing_area();
    root.fill(&WHITE)?;
    let (map_area, bar_area) = root.split_horizontally(850);
    let (x0, x1) = grid.x_range;
    let (y0, y1) = grid.y_range;
    let mut chart = ChartBuilder::on(&map_area)
        .caption(labels.title, ("sans-serif", 22))
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1, y0..y1)?;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc(labels.x)
        .y_desc(labels.y)
        .axis_desc_style(("sans-serif", 16))
        .label_style(("sans-serif", 13))
        .draw()?;
    let (dx, dy) = ((x1 - x0) / grid.nx as f64, (y1 - y0) / grid.ny as f64);
    let span = if hi > lo { hi - lo } else { 1.0 };
    chart.draw_series((0..grid.ny).flat_map(|iy| {
        (0..grid.nx).map(move |ix| {
            let v = grid.values[iy * grid.nx + ix];
            let (xa, ya) = (x0 + ix as f64 * dx, y0 + iy as f64 * dy);
            Rectangle::new(
                [(xa, ya), (xa + dx, ya + dy)],
                ramp((v - lo) / span).filled(),
            )
        })
    }))?;

    // The colour bar: a column of the ramp with the value scale beside it.
    let mut bar = ChartBuilder::on(&bar_area)
        .margin_top(58)
        .margin_bottom(64)
        .margin_right(8)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..1.0, lo..lo + span)?;
    bar.configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .y_desc(labels.value)
        .axis_desc_style(("sans-serif", 15))
        .label_style(("sans-serif", 13))
        .draw()?;
    let steps = 200;
    bar.draw_series((0..steps).map(|k| {
        let (a, b) = (k as f64 / steps as f64, (k + 1) as f64 / steps as f64);
        Rectangle::new(
            [(0.0, lo + a * span), (1.0, lo + b * span)],
            ramp((a + b) / 2.0).filled(),
        )
    }))?;
    root.present()?;
    Ok(())
}

/// One panel of a cloud figure: samples drawn as small dots and curves (ellipses, say) drawn
/// as lines over them.
pub struct CloudGroup {
    /// The panel's caption.
    pub label: String,
    /// The samples.
    pub dots: Vec<(f64, f64)>,
    /// Closed or open curves drawn over the dots.
    pub curves: Vec<Vec<(f64, f64)>>,
}

/// Writes the groups side by side, one panel each with its own scale (a cloud that grows
/// tenfold would shrink the first to a dot on a shared one), to `path`; returns the path.
pub fn cloud(
    path: &Path,
    title: &str,
    (x_label, y_label): (&str, &str),
    groups: &[CloudGroup],
) -> Result<PathBuf, Box<dyn Error>> {
    if groups.is_empty() {
        return Err(format!("nothing to plot in {}", path.display()).into());
    }
    let root = SVGBackend::new(path, (480 * groups.len() as u32, 560)).into_drawing_area();
    root.fill(&WHITE)?;
    let root = root.titled(title, ("sans-serif", 22))?;
    let panels = root.split_evenly((1, groups.len()));
    const COLOURS: [RGBColor; 4] = [
        RGBColor(31, 119, 180),
        RGBColor(214, 39, 40),
        RGBColor(44, 160, 44),
        RGBColor(148, 103, 189),
    ];
    for (k, (g, panel)) in groups.iter().zip(&panels).enumerate() {
        let colour = COLOURS[k % COLOURS.len()];
        let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for &(x, y) in g.dots.iter().chain(g.curves.iter().flatten()) {
            if x.is_finite() && y.is_finite() {
                (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
            }
        }
        if x0 > x1 {
            return Err(format!("panel {} of {} is empty", g.label, path.display()).into());
        }
        let pad = |lo: f64, hi: f64| {
            let d = if hi > lo { 0.05 * (hi - lo) } else { 0.5 };
            (lo - d, hi + d)
        };
        let ((x0, x1), (y0, y1)) = (pad(x0, x1), pad(y0, y1));
        let mut chart = ChartBuilder::on(panel)
            .caption(&g.label, ("sans-serif", 17))
            .margin(12)
            .x_label_area_size(44)
            .y_label_area_size(64)
            .build_cartesian_2d(x0..x1, y0..y1)?;
        chart
            .configure_mesh()
            .light_line_style(WHITE)
            .x_desc(x_label)
            .y_desc(y_label)
            .axis_desc_style(("sans-serif", 14))
            .label_style(("sans-serif", 12))
            .x_labels(5)
            .draw()?;
        chart.draw_series(
            g.dots
                .iter()
                .map(|&p| Circle::new(p, 2, colour.mix(0.6).filled())),
        )?;
        for curve in &g.curves {
            chart.draw_series(LineSeries::new(
                curve.iter().copied(),
                BLACK.stroke_width(2),
            ))?;
        }
    }
    root.present()?;
    Ok(path.to_path_buf())
}

/// The ellipse {x : (x − c)ᵀ P⁻¹ (x − c) = k²} of a 2 × 2 covariance `p` about `centre`: the
/// k-σ contour of a Gaussian, as a closed polyline.
pub fn ellipse(centre: (f64, f64), p: [[f64; 2]; 2], k: f64) -> Vec<(f64, f64)> {
    // P = L Lᵀ (Cholesky); the circle of radius k mapped by L is the ellipse.
    let l11 = p[0][0].max(0.0).sqrt();
    let l21 = if l11 > 0.0 { p[1][0] / l11 } else { 0.0 };
    let l22 = (p[1][1] - l21 * l21).max(0.0).sqrt();
    (0..=120)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / 120.0;
            let (u, v) = (k * a.cos(), k * a.sin());
            (centre.0 + l11 * u, centre.1 + l21 * u + l22 * v)
        })
        .collect()
}
