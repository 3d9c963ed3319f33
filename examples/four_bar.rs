//! A crank-rocker four-bar linkage under gravity, `precess::models::FourBar` (declared with
//! `#[derive(Mechanism)]` and a `closes = ..` joint), run over ten thousand crank turns with
//! the loop kept closed.
//!
//! ```sh
//! cargo run --release --example four_bar [plot directory]
//! ```
//!
//! Ground d = 3, crank a = 1, coupler b = 3, rocker c = 2.5 (uniform rods of 0.5, 1.5 and
//! 1.2 kg) in the xy plane, gravity along −y: Grashof's s + l < p + q holds (1 + 3 < 3 + 2.5)
//! with the shortest link the crank next to the ground, so the crank turns fully and the
//! rocker swings. The tree is crank → coupler and rocker, cut open at the coupler–rocker
//! pin, which `closes = rocker(..)` puts back: two rows φ = B_coupler − B_rocker = 0. The
//! rocker angle is checked against Freudenstein's closed form (`FourBar::positions`)
//! K₁ cos θ₃ − K₂ cos θ₁ + K₃ = cos(θ₁ − θ₃), K₁ = d/a, K₂ = d/c,
//! K₃ = (a² − b² + c² + d²)/(2ac); the energy, conserved by the equations, measures the
//! integrator's error; the loop residual max |φ| is kept at rounding by the run loop's
//! projection after every step.

mod common;

use std::error::Error;
use std::f64::consts::{PI, TAU};

use common::{Axes, Series, Table, plot};
use precess::mechanism::loops::LoopDynamics;
use precess::models::FourBar;
use precess::models::four_bar::Circuit;
use precess::ode::{AdaptiveConfig, Stepper};

const TURNS: f64 = 1e4;

/// Freudenstein's coupler (absolute) and rocker angles for the crank at θ₁, on the circuit
/// of the run.
fn freudenstein(theta1: f64) -> (f64, f64) {
    let [t1, t2, t3] = FourBar::positions(theta1, Circuit::Clockwise);
    (t1 + t2, t3)
}

/// `x − y` wrapped into (−π, π].
fn wrap(x: f64, y: f64) -> f64 {
    let d = (x - y).rem_euclid(TAU);
    if d > PI { d - TAU } else { d }
}

fn main() -> Result<(), Box<dyn Error>> {
    let bar = FourBar;
    let y0 = bar.start(0.3, 6.0, Circuit::Clockwise)?;
    let (q0, qd0) = ([y0[0], y0[1], y0[2]], [y0[3], y0[4], y0[5]]);
    let e0 = bar.energy(&q0, &qd0);
    let cfg = AdaptiveConfig::with_tol(1e-12, 1e-12);
    // The crank's period at this energy, from a probe of 20 s.
    let mut probe = bar.closed_run(0.0, y0, cfg)?;
    probe.advance_to(20.0)?;
    let period = 20.0 / ((probe.state().x[0] - q0[0]) / TAU);
    let t_end = TURNS * period;
    let mut run = bar.closed_run(0.0, y0, cfg)?;
    let (mut samples, mut worst, mut worst_rocker) = (Vec::new(), 0.0_f64, 0.0_f64);
    let n = 400;
    for k in 1..=n {
        let t = t_end * f64::from(k) / f64::from(n);
        run.advance_to(t)?;
        let y = run.state().x;
        let q = [y[0], y[1], y[2]];
        worst = worst.max(bar.residual(&q));
        worst_rocker = worst_rocker.max(wrap(y[2], freudenstein(y[0]).1).abs());
        let e = bar.energy(&q, &[y[3], y[4], y[5]]);
        samples.push((t, worst.max(1e-17), ((e - e0) / e0).abs().max(1e-17)));
    }
    let y = run.state().x;
    let turns = (y[0] - q0[0]) / TAU;
    let (coupler, rocker) = freudenstein(y[0]);
    let lambda = bar.multipliers(t_end, &[y[0], y[1], y[2]], &[y[3], y[4], y[5]])?;
    let mut table = Table::default();
    table.row("θ₃ at the end [rad]", y[2], y[2] - wrap(y[2], rocker));
    table.row(
        "coupler angle θ₁ + θ₂ at the end [rad]",
        y[0] + y[1],
        y[0] + y[1] - wrap(y[0] + y[1], coupler),
    );
    table.row(
        "energy at the end [J]",
        bar.energy(&[y[0], y[1], y[2]], &[y[3], y[4], y[5]]),
        e0,
    );
    table.print(&format!(
        "Four-bar over {turns:.0} crank turns ({t_end:.0} s), DOP853 at rtol = atol = 1e-12"
    ));
    println!(
        "  max |φ| over the run: {worst:.2e}; max |θ₃ − Freudenstein| at the samples: {worst_rocker:.2e} rad"
    );
    println!(
        "  pin force on the coupler at the end (rows {:?}): ({:.4}, {:.4}) N",
        FourBar::CLOSURE_ROWS,
        lambda[0],
        lambda[1]
    );
    println!("  {} steps", run.inner().stats().steps);
    let path = plot(
        "four_bar_residual.svg",
        &Axes {
            title: "Four-bar (derived): loop residual max |φ| and energy error over 10⁴ crank turns",
            x: "t [s]",
            y: "max |φ| [m], |E − E₀|/E₀",
            log_x: false,
            log_y: true,
        },
        &[
            Series::line("max |φ|", samples.iter().map(|s| (s.0, s.1)).collect()),
            Series::line("|E − E₀|/E₀", samples.iter().map(|s| (s.0, s.2)).collect()),
        ],
    )?;
    println!("  wrote {}", path.display());
    Ok(())
}
