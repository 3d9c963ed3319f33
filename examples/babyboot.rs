//! The chaotic babyboot of Drake's `multibody/benchmarks/chaotic_babyboot` (after T. R.
//! Kane, "Mechanical demonstration of mathematical stability and instability", 1974),
//! derived by `#[derive(Mechanism)]`: the state at t = 10 s against the published
//! MotionGenesis values, and its convergence as the tolerance tightens.
//!
//! ```sh
//! cargo run --release --example babyboot [plot directory]
//! ```
//!
//! A rod A turns on a horizontal revolute (x) through its top, with its centre of mass LA
//! below the axis; a plate B turns on a revolute along A's long axis, its centre LB below the
//! first axis. Drake's parameters (converted to kg, m): g = 9.81, mA = 0.01, LA = 0.075,
//! IAx = 5e-6 (A about its centre, across the rod), mB = 0.1, LB = 0.2 and B's principal
//! moments about its centre IBx = 2.5e-4, IBy = 5e-5, IBz = 2e-4 (z along A's axis). Only
//! A's moment about x enters the motion (A turns about x alone); its other two moments are
//! set to keep the description a valid body. Released at rest from qA = 90°, qB = 1°, the
//! plate's small tilt grows and the motion turns chaotic; MotionGenesis's Kutta–Merson
//! integrator at 1e-12 gives, at t = 10 s, qA = −61.312983340691°, qB = −929.47789677244°,
//! q̇A = −6.7440081040646 rad/s, q̇B = −2.7795690128833 rad/s (Drake's test, which quotes
//! four simulations agreeing to 6–7 significant digits: the reference itself is good to
//! about 1e-7).

mod common;

use std::error::Error;

use common::{Axes, Series, Table, plot};
use precess::ode::{AdaptiveConfig, Dop853, Vern9};
use precess::prelude::*;

#[path = "mechanisms/babyboot.rs"]
mod mechanism;
use mechanism::Babyboot;

/// MotionGenesis's state at t = 10 s: qA, qB [rad], q̇A, q̇B [rad/s].
const REFERENCE: [f64; 4] = [
    -61.312983340691 * std::f64::consts::PI / 180.0,
    -929.47789677244 * std::f64::consts::PI / 180.0,
    -6.7440081040646,
    -2.7795690128833,
];
/// Its accelerations at t = 10 s [rad/s²].
const REFERENCE_ACCEL: [f64; 2] = [41.137023263571, 19.483647096003];

fn y0() -> [f64; 4] {
    [90f64.to_radians(), 1f64.to_radians(), 0.0, 0.0]
}

fn main() -> Result<(), Box<dyn Error>> {
    // The tolerance ladder: Dop853 from 1e-8 to 1e-14, then Vern9 at 1e-15 as the best.
    let mut finals = Vec::new();
    for k in 8..=14 {
        let tol = 10f64.powi(-k);
        let mut ode = Dop853::new(Babyboot, 0.0, y0(), AdaptiveConfig::with_tol(tol, tol))?;
        ode.advance_to(10.0)?;
        finals.push((format!("Dop853 tol 1e-{k}"), *ode.y(), ode.stats().steps));
    }
    let mut best = Vern9::new(Babyboot, 0.0, y0(), AdaptiveConfig::with_tol(1e-15, 1e-16))?;
    let mut path_a = Vec::new();
    let mut path_b = Vec::new();
    for k in 1..=1000 {
        let t = 0.01 * k as f64;
        best.advance_to(t)?;
        path_a.push((t, best.y()[0].to_degrees()));
        path_b.push((t, best.y()[1].to_degrees()));
    }
    let y = *best.y();
    println!(
        "\nBabyboot at t = 10 s, convergence as the tolerance tightens (distance from Vern9 at 1e-15)"
    );
    println!(
        "  {:<18} {:>20} {:>20} {:>10} {:>8}",
        "integrator", "qA [deg]", "qB [deg]", "|Δy|∞", "steps"
    );
    let mut convergence = Vec::new();
    for (name, f, steps) in &finals {
        let gap = f
            .iter()
            .zip(&y)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        println!(
            "  {name:<18} {:>20.12} {:>20.12} {gap:>10.2e} {steps:>8}",
            f[0].to_degrees(),
            f[1].to_degrees()
        );
        convergence.push((*steps as f64, gap.max(1e-16)));
    }
    let accel = Babyboot.accelerations(10.0, &[y[0], y[1]], &[y[2], y[3]])?;
    let mut table = Table::default();
    table.row(
        "qA at 10 s [deg]",
        y[0].to_degrees(),
        REFERENCE[0].to_degrees(),
    );
    table.row(
        "qB at 10 s [deg]",
        y[1].to_degrees(),
        REFERENCE[1].to_degrees(),
    );
    table.row("q̇A at 10 s [rad/s]", y[2], REFERENCE[2]);
    table.row("q̇B at 10 s [rad/s]", y[3], REFERENCE[3]);
    table.row(
        "q̈A at 10 s [rad/s²]",
        accel[Babyboot::Q_A],
        REFERENCE_ACCEL[0],
    );
    table.row(
        "q̈B at 10 s [rad/s²]",
        accel[Babyboot::Q_B],
        REFERENCE_ACCEL[1],
    );
    // E is zero at the start (rest, rod horizontal): the row's error is absolute.
    let e0 = Babyboot.energy(&[y0()[0], y0()[1]], &[0.0, 0.0]);
    table.row(
        "energy change over 10 s [J]",
        Babyboot.energy(&[y[0], y[1]], &[y[2], y[3]]) - e0,
        0.0,
    );
    table.print("Babyboot against MotionGenesis (Drake's benchmark; the reference agrees with three other runs to ~1e-7)");
    // Drake's test quotes two more MotionGenesis runs (A, B) beside the reference: their
    // spread is the reference's own uncertainty.
    for (name, value, runs) in [
        ("q̇A", y[2], [-6.7440080750248, -6.7440080514955]),
        ("q̇B", y[3], [-2.7795696971631, -2.7795695154087]),
    ] {
        println!(
            "  {name}: ours {value:.13}, MotionGenesis runs A {:.13} and B {:.13}",
            runs[0], runs[1]
        );
    }

    let path = plot(
        "babyboot.svg",
        &Axes {
            title: "Chaotic babyboot: rod angle qA and plate angle qB (Vern9, tol 1e-15)",
            x: "t [s]",
            y: "angle [deg]",
            log_x: false,
            log_y: false,
        },
        &[Series::line("qA", path_a), Series::line("qB", path_b)],
    )?;
    println!("  wrote {}", path.display());
    let path = plot(
        "babyboot_convergence.svg",
        &Axes {
            title: "Babyboot: state error at 10 s against steps (Dop853, tol 1e-8 … 1e-14)",
            x: "steps",
            y: "|y − y_Vern9|∞",
            log_x: true,
            log_y: true,
        },
        &[Series::markers("Dop853", convergence)],
    )?;
    println!("  wrote {}", path.display());
    Ok(())
}
