//! The figures of `precess::plot`, read back from the SVG they write: the title, the legend,
//! one polyline per line series with one point per sample, markers per point, tick labels
//! inside the axis range; and each error with the numbers it carries.

/// `plot::map` and the units of axis labels.
mod map;

use std::path::{Path, PathBuf};

use precess::ode::{AdaptiveConfig, Dop853, FnSystem, Run, Trajectory};
use precess::plot::{self, Coordinate, Figure, PlotError, Scale, Series, Style, Work, axis_range};

/// A directory of this test's own under the target's scratch space (not the system's temporary
/// directory, where a directory per run piled up): a run overwrites the last one's figures.
fn dir(test: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("plot-{test}"))
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The number of points of each `<polyline>` in `svg`.
fn polylines(svg: &str) -> Vec<usize> {
    svg.split("<polyline")
        .skip(1)
        .filter_map(|tag| {
            let start = tag.find("points=\"")? + "points=\"".len();
            let end = tag[start..].find('"')?;
            Some(tag[start..start + end].split_whitespace().count())
        })
        .collect()
}

/// The texts of `svg`'s `<text>` elements.
fn texts(svg: &str) -> Vec<String> {
    svg.split("<text")
        .skip(1)
        .filter_map(|tag| {
            let start = tag.find('>')? + 1;
            let end = tag.find("</text>")?;
            Some(tag[start..end].trim().to_string())
        })
        .collect()
}

/// The numeric labels of texts anchored as `anchor` (`middle` for the x axis's ticks, `end`
/// for the y axis's).
fn ticks(svg: &str, anchor: &str) -> Vec<f64> {
    svg.split("<text")
        .skip(1)
        .filter(|tag| tag.contains(&format!("text-anchor=\"{anchor}\"")))
        .filter_map(|tag| {
            let start = tag.find('>')? + 1;
            let end = tag.find("</text>")?;
            tag[start..end].trim().parse().ok()
        })
        .collect()
}

/// A harmonic oscillator ẍ = −x run from x = 1 at rest over 10 s, sampled every 0.05 s, with
/// its energy.
fn oscillator() -> Trajectory<[f64; 2]> {
    let sys = FnSystem(|_t: f64, y: &[f64; 2], f: &mut [f64; 2]| *f = [y[1], -y[0]]);
    let mut ode = Dop853::new(
        &sys,
        0.0,
        [1.0, 0.0],
        AdaptiveConfig::with_tol(1e-10, 1e-10),
    )
    .expect("a valid start");
    let mut out = Run::new(&mut ode, 10.0)
        .sample_every(0.05)
        .quantity("energy", |_t, y| 0.5 * (y[0] * y[0] + y[1] * y[1]))
        .integrate()
        .expect("the run");
    out.trajectory
        .set_state_names(["x", "v"])
        .expect("two names");
    out.trajectory
}

#[test]
fn a_time_series_has_its_title_legend_and_one_point_per_sample() {
    let t: Vec<f64> = (0..137).map(|k| k as f64 * 0.1).collect();
    let a: Vec<f64> = t.iter().map(|t| t.sin()).collect();
    let b: Vec<f64> = t.iter().map(|t| 3.0 * t.cos()).collect();
    let path = plot::time_series(
        dir("series").join("sub/dir/ab.svg"),
        "Two columns",
        &t,
        &[("alpha", &a), ("beta", &b)],
    )
    .expect("drawn");
    assert_eq!(path, dir("series").join("sub/dir/ab.svg"));
    let svg = read(&path);
    let texts = texts(&svg);
    for expected in ["Two columns", "alpha", "beta", "t (s)", "alpha, beta"] {
        assert!(
            texts.iter().any(|s| s == expected),
            "{expected} in {texts:?}"
        );
    }
    // One polyline of 137 points per column; the legend's are 2-point strokes.
    let long: Vec<usize> = polylines(&svg).into_iter().filter(|&n| n > 2).collect();
    assert_eq!(long, [137, 137]);
}

#[test]
fn the_axes_cover_the_data_and_their_ticks_lie_inside_the_range() {
    let t: Vec<f64> = (0..=80).map(|k| 2.0 + k as f64 * 0.1).collect(); // 2 ..= 10
    let y: Vec<f64> = t.iter().map(|t| -3.0 + 0.5 * t).collect(); // −2 ..= 2
    let path =
        plot::time_series(dir("range").join("line.svg"), "Line", &t, &[("y", &y)]).expect("drawn");
    let svg = read(&path);
    let (x_lo, x_hi) = axis_range(2.0, 10.0, Scale::Linear);
    let (y_lo, y_hi) = axis_range(-2.0, 2.0, Scale::Linear);
    // 5 % of the span beyond each end.
    assert!((x_lo - 1.6).abs() < 1e-12 && (x_hi - 10.4).abs() < 1e-12);
    assert!((y_lo + 2.2).abs() < 1e-12 && (y_hi - 2.2).abs() < 1e-12);
    for (ticks, lo, hi, first, last) in [
        (ticks(&svg, "middle"), x_lo, x_hi, 2.0, 10.0),
        (ticks(&svg, "end"), y_lo, y_hi, -2.0, 2.0),
    ] {
        assert!(ticks.len() >= 4, "{ticks:?}");
        let step = ticks[1] - ticks[0];
        for &v in &ticks {
            assert!(lo <= v && v <= hi, "tick {v} outside {lo}..{hi}");
        }
        // The labelled ticks reach the data's ends to within one step.
        let (min, max) = (ticks[0], ticks[ticks.len() - 1]);
        assert!(
            min <= first + step.abs() && max >= last - step.abs(),
            "{ticks:?}"
        );
    }
}

#[test]
fn a_log_axis_range_covers_the_data_with_a_tenth_of_a_decade_at_least() {
    let (lo, hi) = axis_range(3e-9, 3e-9, Scale::Log);
    assert!((lo.log10() - (3e-9f64.log10() - 0.1)).abs() < 1e-12);
    assert!((hi.log10() - (3e-9f64.log10() + 0.1)).abs() < 1e-12);
    let (lo, hi) = axis_range(1e-12, 1e-2, Scale::Log);
    assert!((lo.log10() + 12.5).abs() < 1e-12 && (hi.log10() + 1.5).abs() < 1e-12);
}

#[test]
fn a_trajectory_is_drawn_by_column_name() {
    let trajectory = oscillator();
    let n = trajectory.len();
    assert_eq!(n, 201);
    let d = dir("trajectory");
    let path =
        plot::trajectory(d.join("x.svg"), "ẍ = −x", &trajectory, &["x", "energy"]).expect("drawn");
    let svg = read(&path);
    assert!(
        texts_of(&svg, &["ẍ = −x", "x", "energy"]),
        "{:?}",
        texts(&svg)
    );
    let long: Vec<usize> = polylines(&svg).into_iter().filter(|&k| k > 2).collect();
    assert_eq!(long, [n, n]);
    // No names: every state column.
    let svg = read(&plot::trajectory(d.join("all.svg"), "all", &trajectory, &[]).expect("drawn"));
    assert!(texts_of(&svg, &["x", "v"]));
    assert!(!texts(&svg).iter().any(|s| s == "energy"));
}

fn texts_of(svg: &str, names: &[&str]) -> bool {
    let texts = texts(svg);
    names.iter().all(|n| texts.iter().any(|s| s == n))
}

#[test]
fn a_phase_portrait_draws_q_against_q_dot() {
    let trajectory = oscillator();
    let path = plot::trajectory_phase_portrait(
        dir("phase").join("xv.svg"),
        "Phase portrait",
        &trajectory,
        "x",
        "v",
    )
    .expect("drawn");
    let svg = read(&path);
    assert!(texts_of(
        &svg,
        &["Phase portrait", "v against x", "x (m)", "v"]
    ));
    let long: Vec<usize> = polylines(&svg).into_iter().filter(|&k| k > 2).collect();
    assert_eq!(long, [trajectory.len()]);
    // The circle x² + v² = 1: both axes run from −1.1 to 1.1, the x ticks inside.
    for v in ticks(&svg, "middle") {
        assert!(v.abs() <= 1.1 + 1e-12, "{v}");
    }
}

#[test]
fn a_work_precision_plot_has_a_line_and_a_marker_per_run() {
    let runs = |c: f64, p: f64| -> Vec<(f64, f64)> {
        // Given out of order: the line joins them in order of work.
        [1e4, 1e3, 3e4, 3e3]
            .iter()
            .map(|&n: &f64| (n, c * n.powf(-p)))
            .collect()
    };
    let path = plot::work_precision(
        dir("wp").join("wp.svg"),
        "Orders 4 and 8",
        Work::Evaluations,
        &[
            Series::line_and_markers("RK4", runs(1e2, 4.0)),
            Series::line_and_markers("DOP853", runs(1e6, 8.0)),
            Series::markers("peer", vec![(2e3, 1e-9)]),
            Series::styled("RK4 (plain sums)", runs(2e2, 4.0), Style::Dashed).with_color(0),
        ],
    )
    .expect("drawn");
    let svg = read(&path);
    assert!(texts_of(
        &svg,
        &[
            "Orders 4 and 8",
            "RK4",
            "DOP853",
            "peer",
            "RK4 (plain sums)",
            "evaluations",
            "error"
        ]
    ));
    let long: Vec<usize> = polylines(&svg).into_iter().filter(|&k| k > 2).collect();
    assert_eq!(long, [4, 4]);
    // A marker per run: 4 + 4 + 1, and the peer's legend marker.
    assert_eq!(svg.matches("<circle").count(), 10);
    // Exponent ticks on both axes.
    assert!(texts_of(&svg, &["1e-8", "1000"]), "{:?}", texts(&svg));
}

#[test]
fn a_bare_file_name_goes_under_the_default_directory() {
    assert_eq!(
        plot::output_path(Path::new("a.svg")),
        Path::new(plot::DEFAULT_DIR).join("a.svg")
    );
    assert_eq!(
        plot::output_path(Path::new("d/a.svg")),
        Path::new("d/a.svg")
    );
}

#[test]
fn each_error_names_what_cannot_be_drawn() {
    let d = dir("errors");
    let t = [0.0, 1.0, 2.0];
    let fig = Figure::new("f");
    assert!(matches!(
        plot::figure(d.join("a.svg"), &fig, &[]),
        Err(PlotError::NoSeries)
    ));
    assert!(matches!(
        plot::time_series(d.join("a.svg"), "f", &t, &[]),
        Err(PlotError::NoSeries)
    ));
    match plot::figure(d.join("a.svg"), &fig, &[Series::line("empty", vec![])]) {
        Err(PlotError::EmptySeries { series }) => assert_eq!(series, "empty"),
        other => panic!("{other:?}"),
    }
    match plot::time_series(d.join("a.svg"), "f", &[], &[("y", &[])]) {
        Err(PlotError::EmptySeries { series }) => assert_eq!(series, "t"),
        other => panic!("{other:?}"),
    }
    match plot::time_series(d.join("a.svg"), "f", &t, &[("y", &[1.0, 2.0])]) {
        Err(PlotError::LengthMismatch {
            series,
            expected,
            got,
        }) => {
            assert_eq!((series.as_str(), expected, got), ("y", 3, 2));
        }
        other => panic!("{other:?}"),
    }
    match plot::phase_portrait(d.join("a.svg"), "f", ("q", &t), ("p", &[1.0])) {
        Err(PlotError::LengthMismatch {
            series,
            expected,
            got,
        }) => {
            assert_eq!((series.as_str(), expected, got), ("p", 3, 1));
        }
        other => panic!("{other:?}"),
    }
    match plot::time_series(d.join("a.svg"), "f", &t, &[("y", &[1.0, f64::NAN, 2.0])]) {
        Err(e @ PlotError::NonFinite { .. }) => {
            assert_eq!(
                e.to_string(),
                "the y value NaN at index 1 of `y` is not finite"
            );
        }
        other => panic!("{other:?}"),
    }
    match plot::time_series(
        d.join("a.svg"),
        "f",
        &[0.0, 1.0, f64::INFINITY],
        &[("y", &t)],
    ) {
        Err(PlotError::NonFinite {
            series,
            coordinate,
            index,
            value,
        }) => {
            assert_eq!(
                (series.as_str(), coordinate, index),
                ("t", Coordinate::X, 2)
            );
            assert_eq!(value, f64::INFINITY);
        }
        other => panic!("{other:?}"),
    }
    let wp = [Series::line_and_markers(
        "m",
        vec![(1e3, 1e-6), (3e3, 0.0), (1e2, 1e-3)],
    )];
    match plot::work_precision(d.join("a.svg"), "f", Work::Seconds, &wp) {
        Err(PlotError::NotPositiveOnLog {
            series,
            coordinate,
            index,
            value,
        }) => {
            assert_eq!(
                (series.as_str(), coordinate, index, value),
                ("m", Coordinate::Y, 1, 0.0)
            );
        }
        other => panic!("{other:?}"),
    }
    let neg = [Series::line("s", vec![(-1.0, 1.0)])];
    match plot::figure(d.join("a.svg"), &Figure::new("f").log_x(), &neg) {
        Err(PlotError::NotPositiveOnLog {
            coordinate,
            index,
            value,
            ..
        }) => {
            assert_eq!((coordinate, index, value), (Coordinate::X, 0, -1.0));
        }
        other => panic!("{other:?}"),
    }
    match plot::trajectory(d.join("a.svg"), "f", &oscillator(), &["x", "theta"]) {
        Err(PlotError::UnknownColumn { name, available }) => {
            assert_eq!(
                (name.as_str(), available.as_str()),
                ("theta", "x, v, energy")
            );
        }
        other => panic!("{other:?}"),
    }
    // A directory cannot be made under a file: the error names the directory.
    std::fs::create_dir_all(&d).expect("the test's directory");
    let file = d.join("a-file");
    std::fs::write(&file, "").expect("a file");
    match plot::time_series(file.join("sub/a.svg"), "f", &t, &[("y", &t)]) {
        Err(PlotError::Io { path, .. }) => assert_eq!(path, file.join("sub")),
        other => panic!("{other:?}"),
    }
    // Nor a file where a directory is.
    match plot::time_series(&d, "f", &t, &[("y", &t)]) {
        Err(PlotError::Io { path, .. }) => assert_eq!(path, d),
        other => panic!("{other:?}"),
    }
}

#[test]
fn values_past_the_figure_range_are_refused_and_those_inside_it_drawn() {
    let d = dir("extreme");
    let series = |points: Vec<(f64, f64)>| [Series::line("s", points)];
    match plot::figure(
        d.join("e.svg"),
        &Figure::new("e"),
        &series(vec![(0.0, 1.0), (1.0, f64::MAX)]),
    ) {
        Err(PlotError::OutOfRange {
            coordinate,
            index,
            value,
            ..
        }) => {
            assert_eq!((coordinate, index, value), (Coordinate::Y, 1, f64::MAX));
        }
        other => panic!("{other:?}"),
    }
    match plot::figure(
        d.join("e.svg"),
        &Figure::new("e").log_x(),
        &series(vec![(1e-101, 1.0)]),
    ) {
        Err(PlotError::OutOfRange {
            coordinate, index, ..
        }) => {
            assert_eq!((coordinate, index), (Coordinate::X, 0));
        }
        other => panic!("{other:?}"),
    }
    // At the limits themselves every axis still has a finite range and draws.
    for points in [
        vec![(-1e300, 0.0), (1e300, 1.0)],
        vec![(5.0, 1e-300), (5.0, 1e-300)],
        vec![(1.0, 1e-310), (2.0, -1e-310)],
        // An energy constant to a few ulps.
        vec![(0.0, 100.5), (1.0, 100.5 + 1.5e-14), (2.0, 100.5 - 1.5e-14)],
    ] {
        plot::figure(d.join("e.svg"), &Figure::new("e"), &series(points)).expect("drawn");
    }
    for points in [vec![(1e-100, 1e-100), (1e100, 1e100)], vec![(3.0, 1e100)]] {
        let fig = Figure::new("e").log_x().log_y();
        plot::figure(d.join("e.svg"), &fig, &series(points)).expect("drawn");
    }
}
