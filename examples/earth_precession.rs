//! The Earth's free (Eulerian) precession: a rigid Earth turning once a sidereal day about
//! an axis slightly off its figure axis sees that axis circle its pole in the body with the
//! period A/(C − A) sidereal days, set by the dynamical flattening H = (C − A)/C alone.
//!
//! ```sh
//! cargo run --release --example earth_precession [plot directory]
//! ```
//!
//! With H = 3.2737949e-3 (IERS Conventions 2010, table 1.1) the rigid-Earth period is
//! 1/H − 1 = 304.46 sidereal days. The observed Chandler wobble is ~433 days: the real Earth
//! is not rigid (its elastic mantle and oceans lengthen the period), which this model leaves
//! out on purpose.

mod common;

use std::error::Error;
use std::f64::consts::TAU;

use common::{Axes, Series, Table, plot};
use precess::ode::{AdaptiveConfig, FnSystem, solve_dense};
use precess::prelude::*;
use precess::top::TorqueFreeSymmetric;

/// The Earth's dynamical flattening H = (C − A)/C.
const H: f64 = 3.273_794_9e-3;
/// C / (M a²), the Earth's polar moment in units of its mass and equatorial radius.
const C_NORMALISED: f64 = 0.330_690;

/// A rigid Earth with M = 1 and a = 1: A = C (1 − H), axisymmetric about its figure axis z.
#[derive(RigidBody)]
#[rigid(body(
    mass = 1.0,
    at = [0.0, 0.0, 0.0],
    inertia = diag(0.329_607_388_764_519, 0.329_607_388_764_519, 0.330_690),
))]
struct RigidEarth;

fn main() -> Result<(), Box<dyn Error>> {
    let earth = RigidEarth;
    let moments = earth.principal().moments;
    let (a, c) = (moments.x, moments.z);
    // The literal A above is C (1 − H) exactly (0.330690 × (1 − 3.2737949e-3)).
    let h_of_model = (c - a) / c;
    println!("model: C = {c}, A = {a}, (C − A)/C = {h_of_model:.7e} (IERS H = {H:.7e})");
    assert!((c - C_NORMALISED).abs() < 1e-15);

    // Time in sidereal days: ω3 = 2π rad/day. The pole starts 0.3″ off the figure axis
    // (polar motion is of that size).
    let omega3 = TAU;
    let tilt = 0.3 / 3600.0 * TAU / 360.0;
    let w0 = [omega3 * tilt, 0.0, omega3];
    let sys = FnSystem(|_t: f64, w: &[f64; 3], d: &mut [f64; 3]| {
        *d = earth
            .euler_rhs_principal(&Vector3::from(*w), &Vector3::zeros())
            .into();
    });
    let days = 3.0 * 305.0;
    let times: Vec<f64> = (0..=3000).map(|k| days * k as f64 / 3000.0).collect();
    let mut out = vec![[0.0; 3]; times.len()];
    let tight = AdaptiveConfig::with_tol(1e-13, 1e-16);
    let stats =
        solve_dense::<precess::ode::Dop853Pair, _, 3>(sys, 0.0, w0, &times, &mut out, tight)?;

    // The measured period: the slope of the unwrapped phase of (ω1, ω2), by least squares.
    let mut phase = Vec::with_capacity(times.len());
    let mut last = 0.0f64;
    for w in &out {
        let mut p = w[1].atan2(w[0]);
        while p - last > TAU / 2.0 {
            p -= TAU;
        }
        while p - last < -TAU / 2.0 {
            p += TAU;
        }
        phase.push(p);
        last = p;
    }
    let rate = slope(&times, &phase);
    let measured_period = TAU / rate.abs();

    let theory = TorqueFreeSymmetric::new(a, c, w0)?;
    let mut table = Table::default();
    table.row(
        "period, A/(C − A) [sidereal days]",
        measured_period,
        a / (c - a),
    );
    table.row(
        "period, library body-cone rate",
        measured_period,
        TAU / theory.body_cone_rate().abs(),
    );
    table.row(
        "period from IERS H, 1/H − 1",
        measured_period,
        1.0 / H - 1.0,
    );
    let w_end = out.last().copied().unwrap_or(w0);
    let tilt_end = w_end[0].hypot(w_end[1]) / w_end[2];
    table.row("pole offset |ω⊥|/ω3 after 3 periods", tilt_end, tilt);
    table.row("ω3 after 3 periods (constant)", w_end[2], omega3);
    table.print("Free precession of a rigid Earth (DOP853, rtol 1e-13)");
    println!(
        "  {} steps, {} evaluations; observed Chandler wobble ~433 days (elastic Earth)",
        stats.steps, stats.rhs_evals
    );

    let arcsec = 3600.0 * 360.0 / TAU;
    let to_arcsec = |k: usize| -> Vec<(f64, f64)> {
        times
            .iter()
            .zip(&out)
            .map(|(t, w)| (*t, w[k] / w[2] * arcsec))
            .collect()
    };
    let path = plot(
        "earth_precession.svg",
        &Axes {
            title: "Rigid-Earth free precession: the rotation pole in the body",
            x: "t [sidereal days]",
            y: "ω⊥/ω3 [arcsec]",
            log_x: false,
            log_y: false,
        },
        &[
            Series::line("ω1/ω3", to_arcsec(0)),
            Series::line("ω2/ω3", to_arcsec(1)),
        ],
    )?;
    println!("  figure: {}", path.display());
    Ok(())
}

/// The least-squares slope of y against x.
fn slope(x: &[f64], y: &[f64]) -> f64 {
    let n = x.len() as f64;
    let (mx, my) = (x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let sxy: f64 = x.iter().zip(y).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = x.iter().map(|a| (a - mx) * (a - mx)).sum();
    sxy / sxx
}
