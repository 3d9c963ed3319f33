//! The drawing of a [`Map`](super::Map): the cells on the parameter axes, the colour bar
//! beside them, and the legend of the cells without a value.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::axes::{Scale, tick_label};
use super::map::{Grid, Map};
use super::units::with_unit;

/// Width and height of a map, in SVG pixels: the map's square-ish panel and the colour bar.
pub const MAP_SIZE: (u32, u32) = (980, 640);

/// Where the colour bar's panel starts, in pixels from the left.
const BAR_LEFT: i32 = 830;

/// Stops of the colour ramp, dark (low) to bright (high): a perceptually ordered ramp (close
/// to matplotlib's "inferno"), so the eye reads larger values as brighter and a grey-scale
/// print keeps the order.
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

/// The colour of a cell without a value: a mid grey, which the ramp never takes.
pub(crate) const NO_VALUE: RGBColor = RGBColor(160, 160, 160);

/// Steps of the colour bar's ramp.
pub(crate) const BAR_STEPS: usize = 100;

/// The colour of `u` ∈ [0, 1] on the ramp (clamped; NaN is [`NO_VALUE`]).
fn ramp(u: f64) -> RGBColor {
    if u.is_nan() {
        return NO_VALUE;
    }
    let x = u.clamp(0.0, 1.0) * (RAMP.len() - 1) as f64;
    let k = (x.floor() as usize).min(RAMP.len() - 2);
    let f = x - k as f64;
    let (a, b) = (RAMP[k], RAMP[k + 1]);
    let mix = |p: u8, q: u8| (f64::from(p) + (f64::from(q) - f64::from(p)) * f).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// Where `v` lies between `lo` and `hi` on `scale`, 0 at `lo` and 1 at `hi`.
fn fraction(v: f64, (lo, hi): (f64, f64), scale: Scale) -> f64 {
    match scale {
        Scale::Linear => (v - lo) / (hi - lo),
        Scale::Log => (v / lo).ln() / (hi / lo).ln(),
    }
}

/// The range an axis is built on for `edges`: the edges themselves, a logarithmic one widened
/// by 10⁻¹² of itself at each end, because plotters places its first decade tick at
/// 10^⌈log₁₀ from⌉ and log₁₀ 0.001 rounds to −2.9999999999999996, which would drop the tick
/// at an edge that is a power of ten.
fn shown((from, to): (f64, f64), scale: Scale) -> (f64, f64) {
    match scale {
        Scale::Linear => (from, to),
        Scale::Log => (from * (1.0 - 1e-12), to * (1.0 + 1e-12)),
    }
}

/// Draws the checked map into `svg`, the colour ramp spanning `colours`.
pub(crate) fn render(
    svg: &mut String,
    map: &Map,
    grid: &Grid,
    colours: (f64, f64),
) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::with_string(svg, MAP_SIZE).into_drawing_area();
    root.fill(&WHITE)?;
    let (cells, bar) = root.split_horizontally(BAR_LEFT);
    draw_cells(&cells, map, grid, colours)?;
    draw_bar(&bar, map, colours)?;
    let missing = grid.values.iter().filter(|v| v.is_nan()).count();
    draw_no_value(&bar, missing, grid.values.len())?;
    root.present()?;
    Ok(())
}

/// The cells on the two parameter axes.
fn draw_cells(
    area: &DrawingArea<SVGBackend, Shift>,
    map: &Map,
    grid: &Grid,
    colours: (f64, f64),
) -> Result<(), Box<dyn std::error::Error>> {
    let (xs, ys) = (map.x.cell_edges(grid.nx), map.y.cell_edges(grid.ny));
    let ((x0, x1), (y0, y1)) = (
        shown(map.x.edges, map.x.scale),
        shown(map.y.edges, map.y.scale),
    );
    let mut builder = ChartBuilder::on(area);
    builder
        .caption(map.title.as_str(), ("sans-serif", 22))
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(80);
    let scale = map.colour.scale;
    let cell = |k: usize| {
        let (ix, iy) = (k % grid.nx, k / grid.nx);
        let colour = ramp(fraction(grid.values[k], colours, scale));
        Rectangle::new(
            [(xs[ix], ys[iy]), (xs[ix + 1], ys[iy + 1])],
            colour.filled(),
        )
    };
    // Each combination of linear and logarithmic axes is its own coordinate type.
    macro_rules! draw {
        ($x:expr, $y:expr) => {{
            let mut chart = builder.build_cartesian_2d($x, $y)?;
            chart
                .configure_mesh()
                .disable_mesh()
                .x_desc(with_unit(&map.x.label, &map.x.unit))
                .y_desc(with_unit(&map.y.label, &map.y.unit))
                .axis_desc_style(("sans-serif", 16))
                .label_style(("sans-serif", 13))
                .x_label_formatter(&|v| tick_label(*v))
                .y_label_formatter(&|v| tick_label(*v))
                .draw()?;
            chart.draw_series((0..grid.values.len()).map(cell))?;
        }};
    }
    match (map.x.scale, map.y.scale) {
        (Scale::Linear, Scale::Linear) => draw!(x0..x1, y0..y1),
        (Scale::Log, Scale::Linear) => draw!((x0..x1).log_scale(), y0..y1),
        (Scale::Linear, Scale::Log) => draw!(x0..x1, (y0..y1).log_scale()),
        (Scale::Log, Scale::Log) => draw!((x0..x1).log_scale(), (y0..y1).log_scale()),
    }
    Ok(())
}

/// The colour bar: a column of the ramp, the value scale beside it, labelled with the unit.
fn draw_bar(
    area: &DrawingArea<SVGBackend, Shift>,
    map: &Map,
    (lo, hi): (f64, f64),
) -> Result<(), Box<dyn std::error::Error>> {
    let mut builder = ChartBuilder::on(area);
    builder
        .margin_top(58)
        .margin_bottom(110)
        .margin_right(8)
        .y_label_area_size(80);
    let scale = map.colour.scale;
    // The value at fraction f of the bar, as the cells' colours place it.
    let at = |f: f64| match scale {
        Scale::Linear => lo + f * (hi - lo),
        Scale::Log => lo * (hi / lo).powf(f),
    };
    let step = |k: usize| {
        let (a, b) = (
            k as f64 / BAR_STEPS as f64,
            (k + 1) as f64 / BAR_STEPS as f64,
        );
        Rectangle::new([(0.0, at(a)), (1.0, at(b))], ramp((a + b) / 2.0).filled())
    };
    macro_rules! draw {
        ($y:expr) => {{
            let mut chart = builder.build_cartesian_2d(0.0..1.0, $y)?;
            chart
                .configure_mesh()
                .disable_mesh()
                .disable_x_axis()
                .y_desc(with_unit(&map.colour.label, &map.colour.unit))
                .axis_desc_style(("sans-serif", 15))
                .label_style(("sans-serif", 13))
                .y_label_formatter(&|v| tick_label(*v))
                .draw()?;
            chart.draw_series((0..BAR_STEPS).map(step))?;
        }};
    }
    let (from, to) = shown((lo, hi), scale);
    match scale {
        Scale::Linear => draw!(from..to),
        Scale::Log => draw!((from..to).log_scale()),
    }
    Ok(())
}

/// Under the bar: a swatch of the no-value grey and how many cells have no value.
fn draw_no_value(
    area: &DrawingArea<SVGBackend, Shift>,
    missing: usize,
    cells: usize,
) -> Result<(), Box<dyn std::error::Error>> {
    let (_, height) = area.dim_in_pixel();
    let y = height as i32 - 80;
    area.draw(&Rectangle::new([(12, y), (30, y + 18)], NO_VALUE.filled()))?;
    area.draw(&Rectangle::new([(12, y), (30, y + 18)], BLACK))?;
    let style = ("sans-serif", 13).into_font().color(&BLACK);
    area.draw(&Text::new("no value (NaN):", (36, y + 2), style.clone()))?;
    area.draw(&Text::new(
        format!("{missing} of {cells} cells"),
        (36, y + 20),
        style,
    ))?;
    Ok(())
}
