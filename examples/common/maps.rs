//! Figures of many runs: a cloud of samples with ellipses over it, written as SVG like the
//! line plots of `common/mod.rs` (a heat map over two parameters is `precess::plot::map`);
//! an example that needs it includes this file with `#[path = "common/maps.rs"] mod maps;`.

#![allow(dead_code)] // each example uses the part it needs

use std::error::Error;
use std::path::{Path, PathBuf};

use plotters::prelude::*;

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
