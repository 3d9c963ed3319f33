//! The sleeping top: a symmetric top spinning upright stays up when ω3² > 4 M g l I1 / I3²
//! and falls away from the vertical below. The threshold is located here from simulations
//! alone, by bisection on ω3, and compared with the formula.
//!
//! ```sh
//! cargo run --release --example sleeping_top [plot directory]
//! ```
//!
//! Each run starts θ0 = 1e-6 rad from the vertical at rest in the tilt, spinning at ω3, and
//! integrates through the vertical (the ZXZ chart is singular there, so `ChartedTop` moves
//! to ZYX). Above the threshold the tilt stays of order θ0: linear theory gives the largest
//! tilt θ0 L / √(L² − 4 I1 M g l) with L = I3 ω3, which grows without bound at the
//! threshold. Below it the upright state is unstable and the tilt grows to a finite
//! nutation, √(−c2/c4) in the quartic expansion of the effective potential, independent of
//! θ0. A run counts as fallen once the tilt passes 1e-3 rad, far from both.

mod common;

use std::error::Error;

use common::{Axes, Series, Table, plot};
use precess::ode::AdaptiveConfig;
use precess::prelude::*;
use precess::top::HeavyTopTheory;

/// I1 = 1, I3 = ½ about the pivot, M g l = 1: threshold ω3 = √(4 · 1 · 1) / ½ = 4.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 1.0)]
struct Top;

const THETA0: f64 = 1e-6;
const FALLEN: f64 = 1e-3;
const T_END: f64 = 600.0;

/// The largest tilt from the vertical over [0, T_END] (stopping early once fallen).
fn largest_tilt(omega3: f64) -> Result<f64, Box<dyn Error>> {
    let r0 = *Rotation3::from_axis_angle(&Vector3::x_axis(), THETA0).matrix();
    let w0 = Vector3::new(0.0, 0.0, omega3);
    let config = ChartConfig {
        stepper: AdaptiveConfig::with_tol(1e-11, 1e-14),
        ..ChartConfig::default()
    };
    let mut top = ChartedTop::new(TopChart::both(&Top), 0.0, &r0, &w0, config)?;
    let mut largest = THETA0;
    let mut t = 0.0;
    while t < T_END && largest < FALLEN {
        t += 0.25;
        top.advance_to(t)?;
        // The figure axis in space is R's third column.
        let r = top.rotation();
        largest = largest.max(r[(0, 2)].hypot(r[(1, 2)]).atan2(r[(2, 2)]));
    }
    Ok(largest)
}

fn main() -> Result<(), Box<dyn Error>> {
    let theory = HeavyTopTheory::from_principal(Top.principal().moments, 1.0)?;
    let threshold = theory.sleeping_threshold();

    // Bisection on "fallen" from simulations only.
    let (mut lo, mut hi) = (3.0, 5.0);
    assert!(largest_tilt(lo)? >= FALLEN && largest_tilt(hi)? < FALLEN);
    while hi - lo > 1e-3 * lo {
        let mid = 0.5 * (lo + hi);
        if largest_tilt(mid)? >= FALLEN {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let located = 0.5 * (lo + hi);

    let linear = |omega3: f64| {
        let l = theory.i3() * omega3;
        THETA0 * l / (l * l - 4.0 * theory.i1() * theory.mgl()).sqrt()
    };
    let mut table = Table::default();
    table.row("threshold ω3 from simulations [rad/s]", located, threshold);
    for omega3 in [4.4, 5.0, 8.0] {
        table.row(
            format!("largest tilt at ω3 = {omega3} [rad]"),
            largest_tilt(omega3)?,
            linear(omega3),
        );
    }
    table.print("Sleeping top: I1 = 1, I3 = 0.5, M g l = 1 (theory: ω3² = 4 M g l I1 / I3²)");
    println!("  bisection bracket [{lo:.5}, {hi:.5}], each run to t = {T_END} s unless fallen");

    let scan: Vec<f64> = (0..=40).map(|k| 3.0 + 0.05 * k as f64).collect();
    let mut measured = Vec::new();
    for &w in &scan {
        measured.push((w, largest_tilt(w)?));
    }
    let above: Vec<(f64, f64)> = scan
        .iter()
        .filter(|&&w| w > threshold * 1.0005)
        .map(|&w| (w, linear(w)))
        .collect();
    let path = plot(
        "sleeping_top.svg",
        &Axes {
            title: "Sleeping top: largest tilt from θ0 = 1e-6 rad against spin",
            x: "ω3 [rad/s]",
            y: "largest tilt [rad]",
            log_x: false,
            log_y: true,
        },
        &[
            Series::markers("simulated", measured),
            Series::line("linear theory above threshold", above),
            Series::line(
                "threshold ω3 = 4",
                vec![(threshold, 1e-6), (threshold, 1.0)],
            ),
        ],
    )?;
    println!("  figure: {}", path.display());
    Ok(())
}
