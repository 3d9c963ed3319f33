//! `plot::map` read back from its SVG: one rectangle per cell in the map's panel, the colour
//! bar's ramp beside it with its label and unit, ticks at the decades of a logarithmic axis,
//! NaN cells grey and counted; and each refusal with the numbers it carries. Axis labels of
//! trajectories with the units their columns' names carry.

use std::path::Path;

use precess::plot::{self, ColourBar, MAP_SIZE, Map, MapAxis, PlotError, RangeFault};

use super::{dir, oscillator, read, texts};

/// A `<rect>` of the SVG: its left edge, width and fill.
#[derive(Debug)]
struct Rect {
    x: f64,
    width: f64,
    fill: String,
}

fn attribute<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let start = tag.find(&key)? + key.len();
    Some(&tag[start..start + tag[start..].find('"')?])
}

fn rects(svg: &str) -> Vec<Rect> {
    svg.split("<rect")
        .skip(1)
        .filter_map(|tag| {
            let tag = &tag[..tag.find("/>")?];
            let number = |name| attribute(tag, name)?.parse::<f64>().ok();
            Some(Rect {
                x: number("x")?,
                width: number("width")?,
                fill: attribute(tag, "fill")?.to_string(),
            })
        })
        .collect()
}

/// The filled rectangles left of the colour bar's panel, less the white background: the cells.
fn cells(svg: &str) -> Vec<Rect> {
    let full = MAP_SIZE.0 as f64;
    rects(svg)
        .into_iter()
        .filter(|r| r.x + r.width <= 830.0 && r.width < full && r.fill != "none")
        .collect()
}

/// A map with x on a log axis over four decades, y linear, the value i + j.
fn four_decades(nx: usize, ny: usize, value: impl Fn(usize, usize) -> f64) -> Vec<Vec<f64>> {
    (0..ny)
        .map(|j| (0..nx).map(|i| value(i, j)).collect())
        .collect()
}

fn damping_map() -> Map {
    Map {
        title: "A map".into(),
        x: MapAxis::log("damping c", "kg/s", (1e-3, 10.0)),
        y: MapAxis::linear("initial spin ω3", "rad/s", (0.0, 40.0)),
        colour: ColourBar::new("inversion time", "s"),
    }
}

#[test]
fn a_map_has_one_cell_per_value_a_colour_bar_and_its_units() {
    let (nx, ny) = (12, 7);
    let rows = four_decades(nx, ny, |i, j| (i + j) as f64);
    let path = plot::map(dir("map").join("cells.svg"), &damping_map(), &rows).expect("drawn");
    let svg = read(&path);
    let cells = cells(&svg);
    assert_eq!(cells.len(), nx * ny, "{cells:?}");
    // Equal ratios on the log axis are equal widths: every cell is as wide as the first.
    for c in &cells {
        assert!((c.width - cells[0].width).abs() <= 1.0, "{c:?}");
    }
    // The colour bar: its ramp's steps, right of the map, all of one width.
    let bar: Vec<Rect> = rects(&svg).into_iter().filter(|r| r.x >= 830.0).collect();
    assert!(bar.len() >= 100, "{} rectangles in the bar", bar.len());
    // The darkest cell (value 0) has the ramp's dark end, the brightest (i + j = 17) its
    // bright end.
    assert!(cells.iter().any(|c| c.fill == "#000004"));
    assert!(cells.iter().any(|c| c.fill == "#FCFFA4"), "{cells:?}");
    let texts = texts(&svg);
    for label in [
        "damping c (kg/s)",
        "initial spin ω3 (rad/s)",
        "inversion time (s)",
        "no value (NaN):",
        "0 of 84 cells",
    ] {
        assert!(texts.iter().any(|t| t == label), "{label} in {texts:?}");
    }
    // The log axis is ticked at its decades 10⁻³ … 10¹ (written as tick_label writes them).
    for decade in ["0.001", "0.01", "0.1", "1", "10"] {
        assert!(texts.iter().any(|t| t == decade), "{decade} in {texts:?}");
    }
}

#[test]
fn nan_cells_are_grey_and_counted() {
    let rows = four_decades(5, 4, |i, j| {
        if (i + j) % 3 == 0 {
            f64::NAN
        } else {
            1.0 + i as f64
        }
    });
    let nan = rows.iter().flatten().filter(|v| v.is_nan()).count();
    assert_eq!(nan, 7);
    let path = plot::map(dir("map").join("nan.svg"), &damping_map(), &rows).expect("drawn");
    let svg = read(&path);
    let grey = cells(&svg).iter().filter(|c| c.fill == "#A0A0A0").count();
    assert_eq!(grey, nan);
    assert!(texts(&svg).iter().any(|t| t == "7 of 20 cells"));
}

#[test]
fn a_log_colour_bar_is_ticked_at_decades() {
    let rows = four_decades(6, 6, |i, j| {
        10f64.powi(i as i32 - 2) * (1.0 + j as f64 / 10.0)
    });
    let map = Map {
        colour: ColourBar::new("rate", "1/s").log(),
        ..damping_map()
    };
    let svg = read(&plot::map(dir("map").join("log-bar.svg"), &map, &rows).expect("drawn"));
    let texts = texts(&svg);
    // The cells span 10⁻² … 1.5·10³: the bar's decades 0.01 … 1000 each get a tick.
    for decade in ["0.01", "0.1", "1", "10", "100", "1000"] {
        assert!(
            texts.iter().filter(|t| *t == decade).count() >= 1,
            "{decade} in {texts:?}"
        );
    }
    assert!(texts.iter().any(|t| t == "rate (1/s)"));
}

#[test]
fn a_map_refuses_ragged_empty_and_undrawable_grids() {
    let path = Path::new("refused.svg");
    let map = damping_map();
    let empty: [Vec<f64>; 0] = [];
    assert!(matches!(
        plot::map(path, &map, &empty),
        Err(PlotError::EmptyGrid {
            rows: 0,
            columns: 0
        })
    ));
    assert!(matches!(
        plot::map(path, &map, &[Vec::<f64>::new()]),
        Err(PlotError::EmptyGrid {
            rows: 1,
            columns: 0
        })
    ));
    assert!(matches!(
        plot::map(
            path,
            &map,
            &[vec![1.0, 2.0, 3.0], vec![1.0, 2.0, 3.0], vec![4.0]]
        ),
        Err(PlotError::RaggedGrid {
            row: 2,
            expected: 3,
            got: 1
        })
    ));
    match plot::map(path, &map, &[[1.0, f64::INFINITY]]) {
        Err(PlotError::CellOutOfRange {
            row: 0,
            column: 1,
            value,
        }) => {
            assert_eq!(value, f64::INFINITY)
        }
        other => panic!("{other:?}"),
    }
    let log = Map {
        colour: ColourBar::new("rate", "1/s").log(),
        ..damping_map()
    };
    assert!(matches!(
        plot::map(path, &log, &[[1.0, 2.0], [0.5, -0.25]]),
        Err(PlotError::CellNotPositiveOnLog { row: 1, column: 1, value }) if value == -0.25
    ));
}

#[test]
fn a_map_refuses_ranges_it_cannot_draw() {
    let path = Path::new("refused.svg");
    let rows = [[1.0, 2.0]];
    let with = |x: MapAxis, y: MapAxis, colour: ColourBar| Map {
        title: "bad".into(),
        x,
        y,
        colour,
    };
    let good_y = MapAxis::linear("y", "m", (0.0, 1.0));
    let bar = ColourBar::new("v", "");
    let cases = [
        (
            with(
                MapAxis::log("c", "kg/s", (0.0, 10.0)),
                good_y.clone(),
                bar.clone(),
            ),
            ("x", 0.0, 10.0, RangeFault::NotPositiveOnLog),
        ),
        (
            with(
                MapAxis::linear("c", "", (1.0, f64::NAN)),
                good_y.clone(),
                bar.clone(),
            ),
            ("x", 1.0, f64::NAN, RangeFault::NotFinite),
        ),
        (
            with(
                good_y.clone(),
                MapAxis::linear("y", "", (2.0, 2.0)),
                bar.clone(),
            ),
            ("y", 2.0, 2.0, RangeFault::NotIncreasing),
        ),
        (
            with(
                good_y.clone(),
                good_y.clone(),
                bar.clone().range(0.0, f64::INFINITY),
            ),
            ("colour bar", 0.0, f64::INFINITY, RangeFault::NotFinite),
        ),
        (
            with(
                good_y.clone(),
                good_y.clone(),
                bar.clone().log().range(-1.0, 1.0),
            ),
            ("colour bar", -1.0, 1.0, RangeFault::NotPositiveOnLog),
        ),
    ];
    for (map, (axis, from, to, fault)) in cases {
        match plot::map(path, &map, &rows) {
            Err(PlotError::InvalidRange {
                axis: a,
                from: f,
                to: t,
                fault: g,
            }) => {
                assert_eq!((a, g), (axis, fault));
                assert!(
                    f.total_cmp(&from).is_eq() && t.total_cmp(&to).is_eq(),
                    "{f} {t}"
                );
            }
            other => panic!("{axis}: {other:?}"),
        }
    }
}

#[test]
fn trajectory_axes_carry_the_units_of_their_columns() {
    let trajectory = oscillator();
    let d = dir("units");
    let svg = read(
        &plot::trajectory(d.join("x.svg"), "ẍ = −x", &trajectory, &["x", "energy"]).expect("drawn"),
    );
    let texts = texts(&svg);
    for label in ["t (s)", "x (m), energy (J)"] {
        assert!(texts.iter().any(|t| t == label), "{label} in {texts:?}");
    }
    let svg = read(
        &plot::trajectory_phase_portrait(d.join("phase.svg"), "phase", &trajectory, "x", "energy")
            .expect("drawn"),
    );
    let texts = self::texts(&svg);
    for label in ["x (m)", "energy (J)"] {
        assert!(texts.iter().any(|t| t == label), "{label} in {texts:?}");
    }
}
