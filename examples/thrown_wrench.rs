//! A T-handle wrench thrown upward spinning close to its intermediate axis: it flips over
//! and over in flight (the Dzhanibekov effect) while its centre of mass follows a parabola.
//!
//! The derived free body is integrated (DOP853, quaternion projected after every step) and
//! measured against theory: flight time 2v/g, apex height v²/2g, the flip interval 2K/λ of
//! the exact torque-free motion, the number of flips in flight, and the drift of |L| and E
//! (conserved: gravity makes no torque about the centre of mass and has a potential).
//!
//! ```text
//! cargo run --release --example thrown_wrench [directory or path.svg]
//! ```
//!
//! It writes a plot of ω(t) and of the centre of mass's path to the path given (into it as
//! `thrown_wrench.svg` if it is a directory, as for the other examples), by default
//! `target/precess-plots/thrown_wrench.svg`.

mod common;

use std::error::Error;
use std::path::PathBuf;

use plotters::prelude::*;
use precess::free::{FreeDynamics, FreeExact, FreeFlight, FreeState, FreeSystem};
use precess::ode::{AdaptiveConfig, Trajectory};
use precess::prelude::*;

/// A T-handle: a bar along x on top of a stem along z; its intermediate axis is the bar's.
#[derive(RigidBody)]
#[rigid(
    cylinder(mass = 0.3, radius = 0.01, length = 0.2, axis = x, at = [0.0, 0.0, 0.1]),
    cylinder(mass = 0.2, radius = 0.01, length = 0.2, axis = z, at = [0.0, 0.0, 0.0]),
)]
#[free(gravity = 9.81)]
struct THandle;

/// One sample of the flight.
#[derive(Clone, Copy)]
struct Sample {
    t: f64,
    state: FreeState,
    /// ω̇ in principal axes, for interpolating between samples.
    omega_dot: Vector3<f64>,
}

/// The time within [a, b] where the cubic Hermite interpolant of (f, f') crosses zero (by
/// bisection on the interpolant; f(a) and f(b) have opposite signs).
fn hermite_root(a: (f64, f64, f64), b: (f64, f64, f64)) -> f64 {
    let (ta, fa, da) = a;
    let (tb, fb, db) = b;
    let h = tb - ta;
    let at = |s: f64| {
        let (s2, s3) = (s * s, s * s * s);
        (2.0 * s3 - 3.0 * s2 + 1.0) * fa
            + (s3 - 2.0 * s2 + s) * h * da
            + (-2.0 * s3 + 3.0 * s2) * fb
            + (s3 - s2) * h * db
    };
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if (at(mid) > 0.0) == (fa > 0.0) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    ta + 0.5 * (lo + hi) * h
}

/// The times where `f` of consecutive samples changes sign, refined on the interpolant.
fn crossings(samples: &[Sample], f: impl Fn(&Sample) -> (f64, f64)) -> Vec<f64> {
    samples
        .windows(2)
        .filter_map(|w| {
            let ((fa, da), (fb, db)) = (f(&w[0]), f(&w[1]));
            ((fa > 0.0) != (fb > 0.0)).then(|| hermite_root((w[0].t, fa, da), (w[1].t, fb, db)))
        })
        .collect()
}

fn relative(measured: f64, theory: f64) -> f64 {
    ((measured - theory) / theory).abs()
}

fn main() -> Result<(), Box<dyn Error>> {
    let body = THandle;
    body.check_parameters()?;
    let g = 9.81;
    let s0 = FreeState {
        position: Vector3::new(0.0, 0.0, 1.5),
        velocity: Vector3::new(0.8, 0.0, 10.0),
        attitude: UnitQuaternion::identity(),
        // 50 rad/s about the bar (the intermediate axis), a little off it.
        omega_principal: Vector3::new(50.0, 2.0, 3.0),
    };
    let exact: FreeExact = body.exact(0.0, &s0)?;
    let flight_time = 2.0 * s0.velocity.z / g;
    let apex = s0.velocity.z * s0.velocity.z / (2.0 * g);
    let flip_interval = exact
        .flip_interval()
        .ok_or("the throw is not near the intermediate axis")?;

    // Sample the flight a little past landing back at the launch height.
    let cfg = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let mut flight = FreeFlight::new(FreeSystem(&body), 0.0, &s0, cfg)?;
    let dt = 1e-3;
    let n = ((1.05 * flight_time) / dt).ceil() as usize;
    let mut samples = Vec::with_capacity(n + 1);
    let moments = body.principal_cm().moments;
    for k in 0..=n {
        let t = k as f64 * dt;
        flight.advance_to(t)?;
        let mut d = [0.0; 13];
        body.free_rhs(t, flight.y(), &mut d);
        samples.push(Sample {
            t,
            state: flight.state()?,
            omega_dot: Vector3::new(d[10], d[11], d[12]),
        });
    }

    let height = |s: &Sample| (s.state.position.z - s0.position.z, s.state.velocity.z);
    let landing = crossings(&samples[1..], height);
    let measured_flight = *landing.first().ok_or("it never came down")?;
    let rising = |s: &Sample| (s.state.velocity.z, -g);
    let apex_time = *crossings(&samples, rising).first().ok_or("no apex")?;
    // The apex height from the integration: interpolate z at the apex time.
    let measured_apex = samples
        .windows(2)
        .find(|w| w[0].t <= apex_time && apex_time <= w[1].t)
        .map(|w| {
            let s = (apex_time - w[0].t) / dt;
            let (za, zb) = (w[0].state.position.z, w[1].state.position.z);
            let (va, vb) = (w[0].state.velocity.z, w[1].state.velocity.z);
            let (s2, s3) = (s * s, s * s * s);
            (2.0 * s3 - 3.0 * s2 + 1.0) * za
                + (s3 - 2.0 * s2 + s) * dt * va
                + (-2.0 * s3 + 3.0 * s2) * zb
                + (s3 - s2) * dt * vb
                - s0.position.z
        })
        .ok_or("the apex is past the samples")?;
    // Flips: ω about the intermediate axis changes sign.
    let in_flight: Vec<Sample> = samples
        .iter()
        .copied()
        .filter(|s| s.t <= measured_flight + dt)
        .collect();
    let flips = crossings(&in_flight, |s| (s.state.omega_principal.x, s.omega_dot.x));
    let flips: Vec<f64> = flips
        .into_iter()
        .filter(|&t| t <= measured_flight)
        .collect();
    let intervals: Vec<f64> = flips.windows(2).map(|w| w[1] - w[0]).collect();
    let measured_interval = intervals.iter().sum::<f64>() / intervals.len().max(1) as f64;
    // The exact solution's own sign changes over the theoretical flight time.
    let fine = 1e-4;
    let mut theory_flips = 0;
    let mut last = exact.at(0.0)?.omega_principal.x;
    for k in 1..=((flight_time / fine) as usize) {
        let w = exact.at(k as f64 * fine)?.omega_principal.x;
        if (w > 0.0) != (last > 0.0) {
            theory_flips += 1;
        }
        last = w;
    }
    // Conserved: the spin angular momentum about the centre of mass, and the energy.
    let spin = |s: &FreeState| (s.attitude * moments.component_mul(&s.omega_principal)).norm();
    let (l0, e0) = (spin(&s0), body.energy(&s0.to_array()));
    let (mut l_drift, mut e_drift) = (0.0f64, 0.0f64);
    for s in &in_flight {
        l_drift = l_drift.max(((spin(&s.state) - l0) / l0).abs());
        e_drift = e_drift.max(((body.energy(&s.state.to_array()) - e0) / e0).abs());
    }

    println!(
        "A T-handle thrown up at {} m/s spinning at {:?} rad/s",
        s0.velocity.z,
        s0.omega_principal.as_slice()
    );
    println!(
        "principal moments about the centre of mass: {:?} kg m²\n",
        moments.as_slice()
    );
    println!(
        "{:<28} {:>16} {:>16} {:>10}",
        "quantity", "measured", "theory", "rel. err"
    );
    let row = |name: &str, m: f64, t: f64| {
        println!("{name:<28} {m:>16.10} {t:>16.10} {:>10.1e}", relative(m, t));
    };
    row("flight time 2v/g (s)", measured_flight, flight_time);
    row("apex height v²/2g (m)", measured_apex, apex);
    row("flip interval 2K/λ (s)", measured_interval, flip_interval);
    println!(
        "{:<28} {:>16} {:>16} {:>10}",
        "flips in flight",
        flips.len(),
        theory_flips,
        if flips.len() == theory_flips {
            "exact"
        } else {
            "differs"
        }
    );
    println!(
        "{:<28} {:>16.1e} {:>16} {:>10}",
        "|L| drift (relative, max)", l_drift, 0, "-"
    );
    println!(
        "{:<28} {:>16.1e} {:>16} {:>10}",
        "E drift (relative, max)", e_drift, 0, "-"
    );
    println!("\nwork: {:?}", flight.stats());

    let mut path = std::env::args()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("target/precess-plots"));
    if path.extension().is_none_or(|e| e != "svg") {
        path.push("thrown_wrench.svg");
    }
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)?;
    }
    plot(&path, &in_flight)?;
    println!("plot: {}", path.display());

    // The flight as an animation beside the figure, seen from the centre of mass (the 5 m
    // throw would dwarf the handle), four times slower than life.
    let mut run = Trajectory::new(vec![]);
    for s in &in_flight {
        let position = Vector3::zeros();
        run.push(
            s.t,
            FreeState {
                position,
                ..s.state
            },
            &[],
        )?;
    }
    let options = precess::animate::Options {
        time_scale: 4.0,
        ..Default::default()
    };
    let movie = precess::animate::free(&body, &run, options)?;
    let mut table = common::Table::default();
    table.row("flight time 2v/g (s)", measured_flight, flight_time);
    table.row("apex height v²/2g (m)", measured_apex, apex);
    table.row("flip interval 2K/λ (s)", measured_interval, flip_interval);
    let dir = path.parent().unwrap_or(std::path::Path::new("."));
    let caption = "Flight and flips against free fall and the exact free body";
    common::animation::write_animation(
        dir,
        "thrown_wrench",
        "Thrown T-handle",
        &movie,
        &table,
        caption,
    )?;
    Ok(())
}

/// ω(t) in principal axes beside the centre of mass's path in the x–z plane.
fn plot(path: &PathBuf, samples: &[Sample]) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (1200, 500)).into_drawing_area();
    root.fill(&WHITE)?;
    let (left, right) = root.split_horizontally(700);
    let t_end = samples.last().map_or(1.0, |s| s.t);
    let w_max = samples
        .iter()
        .map(|s| s.state.omega_principal.amax())
        .fold(0.0, f64::max)
        * 1.1;
    let mut chart = ChartBuilder::on(&left)
        .caption("ω in principal axes (rad/s)", ("sans-serif", 20))
        .margin(10)
        .x_label_area_size(30)
        .y_label_area_size(40)
        .build_cartesian_2d(0.0..t_end, -w_max..w_max)?;
    chart.configure_mesh().x_desc("t (s)").draw()?;
    let colours = [RED, BLUE, GREEN];
    for (k, colour) in colours.iter().enumerate() {
        chart
            .draw_series(LineSeries::new(
                samples.iter().map(|s| (s.t, s.state.omega_principal[k])),
                colour,
            ))?
            .label(format!("ω{}", k + 1))
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colours[k]));
    }
    chart.configure_series_labels().border_style(BLACK).draw()?;
    let x_max = samples
        .iter()
        .map(|s| s.state.position.x)
        .fold(0.0, f64::max)
        * 1.1
        + 0.1;
    let z_max = samples
        .iter()
        .map(|s| s.state.position.z)
        .fold(0.0, f64::max)
        * 1.1;
    let mut path_chart = ChartBuilder::on(&right)
        .caption("centre of mass, x–z (m)", ("sans-serif", 20))
        .margin(10)
        .x_label_area_size(30)
        .y_label_area_size(40)
        .build_cartesian_2d(0.0..x_max, 0.0..z_max)?;
    path_chart
        .configure_mesh()
        .x_desc("x (m)")
        .y_desc("z (m)")
        .draw()?;
    path_chart.draw_series(LineSeries::new(
        samples
            .iter()
            .map(|s| (s.state.position.x, s.state.position.z)),
        &BLACK,
    ))?;
    root.present()?;
    Ok(())
}
