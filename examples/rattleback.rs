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
//! (the zeros of its rate, an event of the run: every root inside each step is looked for on
//! the integrator's dense output and located to adjacent doubles, so the brief pairs of zeros
//! while the body rattles are found whatever the sampling), and the energy's drift.
//!
//! The body is the library's ready model `precess::models::Rattleback`, declared on a struct
//! as a user would: `#[rigid(body(..))]` with the full inertia tensor (the product D kept)
//! and `#[contact(surface = ellipsoid(..), law = rolling, ..)]`. It runs as a
//! `ContactRun` in the one run loop, driven by `ode::Run` (samples, `ContactQuantities`, the
//! event).
//!
//! Run with `cargo run --release --example rattleback`.

mod common;

use std::error::Error;

use common::{Axes, Series, Table, animation, plot, plot_dir};
use precess::contact::{
    ContactDynamics, ContactQuantities, ContactRun, Phase, STATE_LEN, attitude_of,
};
use precess::models::Rattleback;
use precess::nalgebra::Vector3;
use precess::ode::{AdaptiveConfig, Direction, Event, Run, StopReason};

/// The sampling interval [s]: fine enough for the largest drifts over the run to be those of
/// the integration, not of where it was looked at.
const SAMPLE: f64 = 2.5e-4;

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

    let y0 = model.release(0.5_f64.to_radians(), -5.0)?;
    let t_end = 60.0;
    let mut cfg = AdaptiveConfig::with_tol(1e-12, 1e-12);
    cfg.max_steps = 10_000_000;
    // Steps no longer than the sampling interval: with the controller's own, longer steps
    // the energy drifts by 3e-11 over the run rather than 1e-14, and between steps the
    // samples would carry the dense output's error besides.
    cfg.h_max = SAMPLE;
    let mut run = ContactRun::new(&model, Phase::Rolling, 0.0, y0, cfg)?;
    let out = Run::new(&mut run, t_end)
        .sample_every(SAMPLE)
        .quantities(ContactQuantities::new(&model, Phase::Rolling))
        .quantity("heading rate", |_t, s| heading_rate(s))
        .quantity("roll (deg)", |_t, s| {
            model.contact(s).gamma.y.asin().to_degrees()
        })
        .event(Event::new("heading turns"), |_t, s| heading_rate(s))
        .integrate()?;
    if out.stop == StopReason::Halted {
        println!("the run stopped at t = {} s: {:?}", out.t, run.run().halt());
    }

    let e0 = model.energy(Phase::Rolling, &y0);
    let times = out.trajectory.times();
    let column = |name: &str| {
        out.trajectory
            .column(name)
            .ok_or(format!("no column {name}"))
    };
    let (energy, slip) = (column("energy")?, column("slip")?);
    let worst = energy
        .iter()
        .map(|e| (e - e0).abs() / e0)
        .fold(0.0, f64::max);
    let series = |name: &str| -> Result<Vec<(f64, f64)>, String> {
        Ok(times.iter().copied().zip(column(name)?).collect())
    };
    let spin: Vec<(f64, f64)> = times
        .iter()
        .zip(out.trajectory.states())
        .map(|(t, s)| (*t, s[10]))
        .collect();
    let (yaw_rate, rock) = (series("heading rate")?, series("roll (deg)")?);
    // The spin about the vertical as the turning rate of the long axis's heading: the body's
    // own ω₃ also carries the rocking and crosses zero many times while the body rattles.
    // One reversal is a run of zeros of that rate closer than 1 s apart: its first and last,
    // and the sense of the last crossing.
    let mut reversals: Vec<(f64, f64, Direction)> = Vec::new();
    for hit in &out.events {
        match reversals.last_mut() {
            Some(r) if hit.t - r.1 < 1.0 => (r.1, r.2) = (hit.t, hit.direction),
            _ => reversals.push((hit.t, hit.t, hit.direction)),
        }
    }

    println!(
        "Rattleback (Kane & Levinson 1982): released at ω₃ = −5 rad/s, tilted 0.5° about x and y; {t_end} s rolling"
    );
    println!(
        "  the long axis's heading stops and turns back (first and last zero of its rate, s):"
    );
    for (k, (first, last, sense)) in reversals.iter().enumerate() {
        let sense = if *sense == Direction::Rising {
            "− → +"
        } else {
            "+ → −"
        };
        println!("    reversal {} ({sense}): {first:8.4} – {last:8.4}", k + 1);
    }
    let max_pos = spin.iter().map(|s| s.1).fold(f64::MIN, f64::max);
    let min_neg = spin.iter().map(|s| s.1).fold(f64::MAX, f64::min);
    println!("  ω₃ ranges over [{min_neg:.4}, {max_pos:.4}] rad/s");
    let mut table = Table::default();
    table.row(
        "energy after 60 s (J)",
        model.energy(Phase::Rolling, &out.state),
        e0,
    );
    table.row("max |E/E₀ − 1| over the run", worst, 0.0);
    let slip = slip.iter().copied().fold(0.0, f64::max);
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

    // The run as an animation beside the figures, every 20 ms (0.1 rad of spin at most),
    // without the contact point's path (its rocking to and fro would hide the body).
    let run = animation::thinned(&out.trajectory, 0.0, 0.02)?;
    let options = precess::animate::Options {
        traces: false,
        ..Default::default()
    };
    let movie = precess::animate::contact(&model, &run, options)?;
    let caption = "Invariants of rolling without dissipation";
    animation::write_animation(
        &plot_dir()?,
        "rattleback",
        "Rattleback",
        &movie,
        &table,
        caption,
    )?;
    Ok(())
}
