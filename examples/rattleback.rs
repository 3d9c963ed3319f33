//! The rattleback: an ellipsoid whose axes of inertia are turned against its axes of shape
//! spins one way, rocks, stops and spins back.
//!
//! The body is Kane & Levinson's (Int. J. Non-Linear Mech. 17 (1982) 175): a contact surface
//! of semi-axes a = 0.2, b = 0.03, c = 0.02 m, the centre of mass h = 0.01 m below the
//! ellipsoid's centre along the short axis, M = 1 kg, moments A = 2e-4, B = 1.6e-3,
//! C = 1.7e-3 kg·m² and the product D = −2e-5 kg·m² (the misalignment of mass and shape).
//! Released tilted 0.5° about both horizontal axes and spinning at ω₃ = −5 rad/s, it rolls
//! without slip and without dissipation: energy is conserved, and the spin reverses again
//! and again. The run reports when the heading of the long axis stops turning and turns back
//! (the zeros of its rate, by linear interpolation on samples 0.25 ms apart: coarser ones miss brief pairs of zeros), and the energy's
//! drift.
//!
//! The body is declared on a struct: `#[rigid(body(..))]` with the full inertia tensor (the
//! product D kept) and `#[contact(surface = ellipsoid(..), law = rolling, ..)]`.
//!
//! Run with `cargo run --release --example rattleback`.

mod common;
#[path = "common/contact.rs"]
mod contact;

use std::error::Error;

use common::{Axes, Series, Table, plot};
use contact::sample;
use precess::contact::{ContactDynamics, Phase, STATE_LEN, attitude_of};
use precess::nalgebra::{UnitQuaternion, Vector3};
use precess::prelude::RigidBody;

/// Kane & Levinson's rattleback: M = 1 kg with its centre of mass at the origin, the inertia
/// about it with the product D = −2e-5 kg·m² in the (x, y) entries, and an ellipsoid of
/// semi-axes a, b, c whose centre is h = 0.01 m above the centre of mass.
#[derive(RigidBody)]
#[rigid(body(
    mass = 1.0,
    inertia = [[2e-4, -2e-5, 0.0], [-2e-5, 1.6e-3, 0.0], [0.0, 0.0, 1.7e-3]],
))]
#[contact(
    surface = ellipsoid(semi_axes = [0.2, 0.03, 0.02], center = [0.0, 0.0, 0.01]),
    law = rolling,
    gravity = 9.81,
)]
struct Rattleback;

/// Every 40th point (10 ms apart), enough for the figures.
fn thin(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    points.iter().step_by(40).copied().collect()
}

/// The turning rate of the long axis's heading: x = R e₁, ẋ = ω × x (space axes).
fn heading_rate(y: &[f64; STATE_LEN]) -> f64 {
    let q = attitude_of(y);
    let x = q * Vector3::x();
    let xd = (q * Vector3::new(y[8], y[9], y[10])).cross(&x);
    (x.x * xd.y - x.y * xd.x) / (x.x * x.x + x.y * x.y)
}

fn main() -> Result<(), Box<dyn Error>> {
    let model = Rattleback;

    let tilt = 0.5_f64.to_radians();
    let q = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), tilt)
        * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), tilt);
    let y0 = model.rolling_state([0.0, 0.0], &q, &Vector3::new(0.0, 0.0, -5.0))?;
    let t_end = 60.0;
    let run = sample(&model, y0, 2.5e-4, t_end, 1e-12)?;
    if let Some(t) = run.lift_off {
        println!("the rattleback left the table at t = {t} s");
    }

    let e0 = model.energy(Phase::Rolling, &y0);
    let mut worst = 0.0_f64;
    let (mut spin, mut rock, mut yaw_rate) = (Vec::new(), Vec::new(), Vec::new());
    for k in 0..run.t.len() {
        let y = &run.y[k];
        worst = worst.max((model.energy(Phase::Rolling, y) - e0).abs() / e0);
        spin.push((run.t[k], y[10]));
        rock.push((run.t[k], model.contact(y).gamma.y.asin().to_degrees()));
        yaw_rate.push((run.t[k], heading_rate(y)));
    }
    // The spin about the vertical as the turning rate of the long axis's heading: the body's
    // own ω₃ also carries the rocking and crosses zero many times while the body rattles.
    let crossings: Vec<f64> = yaw_rate
        .windows(2)
        .filter(|w| w[0].1 * w[1].1 < 0.0)
        .map(|w| w[0].0 - w[0].1 * (w[1].0 - w[0].0) / (w[1].1 - w[0].1))
        .collect();
    // One reversal is a run of crossings closer than 1 s apart: its first and last.
    let mut reversals: Vec<(f64, f64)> = Vec::new();
    for &t in &crossings {
        match reversals.last_mut() {
            Some(r) if t - r.1 < 1.0 => r.1 = t,
            _ => reversals.push((t, t)),
        }
    }

    println!(
        "Rattleback (Kane & Levinson 1982): released at ω₃ = −5 rad/s, tilted 0.5° about x and y; {t_end} s rolling"
    );
    println!(
        "  the long axis's heading stops and turns back (first and last zero of its rate, s):"
    );
    // The sense of each reversal: the heading rate 0.5 s after its last zero.
    let rate_at = |t: f64| {
        let k = ((t / 2.5e-4).round() as usize).min(yaw_rate.len() - 1);
        yaw_rate[k].1
    };
    for (k, (first, last)) in reversals.iter().enumerate() {
        let sense = if rate_at(last + 0.5) > 0.0 {
            "− → +"
        } else {
            "+ → −"
        };
        println!("    reversal {} ({sense}): {first:8.3} – {last:8.3}", k + 1);
    }
    let max_pos = spin.iter().map(|s| s.1).fold(f64::MIN, f64::max);
    let min_neg = spin.iter().map(|s| s.1).fold(f64::MAX, f64::min);
    println!("  ω₃ ranges over [{min_neg:.4}, {max_pos:.4}] rad/s");
    let mut table = Table::default();
    table.row(
        "energy after 60 s (J)",
        model.energy(Phase::Rolling, run.y.last().ok_or("empty run")?),
        e0,
    );
    table.row("max |E/E₀ − 1| over the run", worst, 0.0);
    let slip = run
        .y
        .iter()
        .map(|y| model.contact(y).velocity.norm())
        .fold(0.0, f64::max);
    table.row("max contact-point speed (m/s)", slip, 0.0);
    table.print("Invariants of rolling without dissipation");

    let a1 = Axes {
        title: "Rattleback: spin reversals without dissipation",
        x: "t (s)",
        y: "ω₃ (rad/s)",
        log_x: false,
        log_y: false,
    };
    let f1 = plot(
        "rattleback_spin.svg",
        &a1,
        &[
            Series::line("ω₃ (body)", thin(&spin)),
            Series::line("heading rate of the long axis", thin(&yaw_rate)),
        ],
    )?;
    let a2 = Axes {
        title: "Rattleback: rocking about the long axis",
        x: "t (s)",
        y: "roll: asin γ₂ (deg)",
        log_x: false,
        log_y: false,
    };
    let f2 = plot(
        "rattleback_rocking.svg",
        &a2,
        &[Series::line("roll", thin(&rock))],
    )?;
    println!("\nfigures: {}, {}", f1.display(), f2.display());
    Ok(())
}
