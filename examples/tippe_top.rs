//! The tippe top: an eccentric sphere spun with its stem up glides on the table, turns over
//! and ends spinning on its stem.
//!
//! The top is a sphere of radius R = 2 cm whose centre of mass sits αR = 6 mm below its
//! centre, mass 20 g, moments I₁ = 0.35 M R² and I₃ = 0.4 M R² about the centre of mass
//! (I₁/I₃ = 0.875, inside the inversion range 1 − α < I₁/I₃ < 1 + α). The table's friction is
//! viscous, F = −c u on the slip u of the contact point (Cohen 1977, Or 1994). Started 0.1 rad
//! off upright at 140 rad/s, it inverts within a few seconds. Friction takes more than half of
//! the energy, yet Jellett's λ = −L·a (a from the centre of mass to the contact) is conserved
//! exactly by any contact force on a sphere, so λ alone fixes the inverted state: its spin
//! about the vertical n′ = λ / (R I₃ (1 + α)) and its energy λ² / (2 I₃ R² (1 + α)²) +
//! M g R (1 + α) (`contact::theory::TippeTop`).
//!
//! The top is the library's ready model `precess::models::TippeTop` (shared with
//! `tippe_sweep`), declared on a struct as a user would: `#[rigid]` gives its mass and
//! inertia, `#[contact]` its spherical surface and the table's law, and the derive emits the
//! equations of motion (`ContactDynamics`) as straight-line code while it expands. The run is the contact's `ContactRun` in the one run loop, driven by `ode::Run`:
//! samples every 5 ms with the standard quantities (`ContactQuantities`), and the instant the
//! axis passes the horizontal as an event located on the integrator's dense output.
//!
//! It writes its figures and its animation (`tippe_top.glb`, and `tippe_top.html`, a page
//! that plays it beside the table: `precess::animate`, docs/animation.md) to
//! `target/precess-plots/`. Run with `cargo run --release --example tippe_top`.

mod common;

use std::error::Error;
use std::time::Instant;

use common::{Axes, Series, Table, plot, plot_dir};
use precess::animate;
use precess::contact::{ContactDynamics, ContactQuantities, ContactRun, Phase, attitude_of};
use precess::models::TippeTop as Top;
use precess::models::tippe_top::{ALPHA, MASS, RADIUS};
use precess::nalgebra::Vector3;
use precess::ode::{AdaptiveConfig, Event, Run, StopReason};

fn main() -> Result<(), Box<dyn Error>> {
    let (r, alpha) = (RADIUS, ALPHA);
    let top = Top::theory();
    let viscous = 5.0 * MASS;
    let model = Top { viscous };
    let y0 = Top::start(0.1, 140.0);

    // One run loop: sampled every 5 ms, the standard contact quantities per sample (each
    // under the sample's own phase), the axis's angle, and the instant the axis passes the
    // horizontal as an event located on the integrator's own solution.
    let mut cfg = AdaptiveConfig::with_tol(1e-12, 1e-12);
    cfg.max_steps = 10_000_000;
    let mut run = ContactRun::new(&model, model.law().first_phase(), 0.0, y0, cfg)?;
    let out = Run::new(&mut run, 20.0)
        .sample_every(0.005)
        .quantities(ContactQuantities::new(&model, Phase::Sliding))
        .quantity("θ (deg)", |_t, s| {
            Top::axis_up(s).clamp(-1.0, 1.0).acos().to_degrees()
        })
        .event(Event::new("axis horizontal").falling(), |_t, s| {
            Top::axis_up(s)
        })
        .integrate()?;
    if out.stop == StopReason::Halted {
        println!("the run stopped at t = {} s: {:?}", out.t, run.run().halt());
    }
    let flip = out.events.first().map_or(f64::NAN, |hit| hit.t);
    let phase = model.law().first_phase();
    let lambda0 = model.jellett(&y0);
    let e0 = model.energy(phase, &y0);
    let t = out.trajectory.times().to_vec();
    let column = |name: &str| {
        out.trajectory
            .column(name)
            .ok_or(format!("no column {name}"))
    };
    let (energies, jellett) = (column("energy")?, column("jellett")?);
    let energy: Vec<(f64, f64)> = t.iter().zip(&energies).map(|(t, e)| (*t, e / e0)).collect();
    let drift: Vec<(f64, f64)> = t
        .iter()
        .zip(&jellett)
        .map(|(t, l)| (*t, ((l - lambda0).abs() / lambda0).max(1e-17)))
        .collect();
    let worst = jellett
        .iter()
        .map(|l| (l - lambda0).abs() / lambda0)
        .fold(0.0, f64::max);
    let last = out.state.x;
    let w_space = attitude_of(&last) * Vector3::new(last[8], last[9], last[10]);
    let height = model.contact(&last).height;
    println!(
        "Tippe top: R = {r} m, α = {alpha}, I₁/I₃ = {:.3}, viscous c = {viscous} kg/s",
        top.i1 / top.i3
    );
    println!(
        "  inverts by theory: {} (1 − α < I₁/I₃ < 1 + α); least spin for the energy to allow it {:.1} rad/s",
        top.inverts(),
        top.min_inversion_spin()
    );
    if let Some(thres) = top.jellett_threshold() {
        // Their threshold is proved for 1 − α² < I₁/I₃ < 1; outside that it only indicates.
        let gamma = top.i1 / top.i3;
        let proved = 1.0 - alpha * alpha < gamma && gamma < 1.0;
        println!(
            "  λ₀ = {lambda0:.6e} is {:.2} × the threshold of Rauch-Wojciechowski & Rutstam (2014){}",
            lambda0 / thres,
            if proved {
                ""
            } else {
                " (proved there for 1 − α² < I₁/I₃ < 1, not met here)"
            }
        );
    }
    println!("  the axis passes the horizontal at t = {flip:.6} s (an event of the run)");
    let rows = vec![
        ("Jellett λ at 20 s (kg m³/s)", model.jellett(&last), lambda0),
        ("max |λ/λ₀ − 1| over the run", worst, 0.0),
        (
            "final spin about the vertical (rad/s)",
            w_space.z,
            top.inverted_spin(lambda0),
        ),
        (
            "final energy (J)",
            model.energy(phase, &last),
            top.inverted_energy(lambda0),
        ),
        (
            "final height of the centre of mass (m)",
            height,
            r * (1.0 + alpha),
        ),
        (
            "energy lost, fraction",
            1.0 - model.energy(phase, &last) / e0,
            1.0 - top.inverted_energy(lambda0) / e0,
        ),
    ];
    let mut table = Table::default();
    for (quantity, measured, theory) in &rows {
        table.row(*quantity, *measured, *theory);
    }
    table.print("Inverted state against Jellett's integral (theory: contact::theory::TippeTop)");

    let f1 = precess::plot::trajectory(
        plot_dir()?.join("tippe_top_angle.svg"),
        "Tippe top: the symmetry axis turns over",
        &out.trajectory,
        &["θ (deg)"],
    )?;
    let a2 = Axes {
        title: "Tippe top: energy falls, Jellett's λ is kept",
        x: "t (s)",
        y: "E/E₀ ; |λ/λ₀ − 1|",
        log_x: false,
        log_y: true,
    };
    let f2 = plot(
        "tippe_top_invariants.svg",
        &a2,
        &[
            Series::line("E/E₀", energy),
            Series::line("|λ/λ₀ − 1|", drift),
        ],
    )?;
    println!("\nfigures: {}, {}", f1.display(), f2.display());

    // The run as an animation beside the figures: a .glb that any glTF viewer plays, and one
    // page holding it, its viewer and the table above (open it in a browser).
    let started = Instant::now();
    let animation = animate::contact(&model, &out.trajectory, animate::Options::default())?;
    let dir = plot_dir()?;
    let (glb, page) = (dir.join("tippe_top.glb"), dir.join("tippe_top.html"));
    animation.write_glb(&glb)?;
    let caption = "Inverted state against Jellett's integral".to_string();
    let rows = rows
        .iter()
        .map(|(q, m, t)| (q.to_string(), *m, *t))
        .collect();
    let table = animate::PageTable { caption, rows };
    animate::write_page(&page, &animation, "Tippe top", &table, None)?;
    let size = |p: &std::path::Path| std::fs::metadata(p).map_or(0, |m| m.len() / 1024);
    println!(
        "animation: {} ({} KiB), {} ({} KiB), {} keyframes, written in {:.0} ms",
        glb.display(),
        size(&glb),
        page.display(),
        size(&page),
        out.trajectory.len(),
        1e3 * started.elapsed().as_secs_f64()
    );
    Ok(())
}
