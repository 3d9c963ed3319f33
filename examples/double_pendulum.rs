//! The double pendulum, derived by `#[derive(Mechanism)]`: its small oscillations against
//! the two normal-mode frequencies of the linearised equations, and its energy along a
//! chaotic swing.
//!
//! ```sh
//! cargo run --release --example double_pendulum [plot directory]
//! ```
//!
//! Two point masses m1, m2 hang on massless rods l1, l2; θ1 is the upper rod's angle from the
//! downward vertical and θ2 the lower rod's angle relative to the upper. Near the bottom, in
//! absolute angles φ = (θ1, θ1 + θ2), the motion is M φ̈ = −K φ with
//!
//! M = [[(m1 + m2) l1², m2 l1 l2], [m2 l1 l2, m2 l2²]],  K = diag((m1 + m2) g l1, m2 g l2),
//!
//! so det(K − ω² M) = 0 gives the normal-mode frequencies
//!
//! ω² = g [(m1 + m2)(l1 + l2) ± √((m1 + m2)²(l1 + l2)² − 4 (m1 + m2) m1 l1 l2)] / (2 m1 l1 l2).
//!
//! Started in a mode with amplitude 1e-4 rad, each frequency is measured from the zero
//! crossings of θ1 over twenty periods; the nonlinear shift (of order the amplitude
//! squared) and the crossings' interpolation leave a few parts in 1e9. The chaotic swing starts with both rods horizontal-ish and runs 30 s with
//! Dop853 at rtol = 1e-12: the energy, conserved by the equations, is its measure of error.

mod common;

use std::error::Error;

use common::{Axes, Series, Table, plot};
use precess::animate;
use precess::mechanism::MechanismDynamics;
use precess::ode::{AdaptiveConfig, Dop853, Trajectory};

const G: f64 = 9.81;

#[path = "mechanisms/double_pendulum.rs"]
mod mechanism;
use mechanism::DoublePendulum;

impl DoublePendulum {
    /// The normal-mode frequencies (slow, fast) of the linearised pendulum.
    fn mode_frequencies(&self) -> [f64; 2] {
        let (m1, m2, l1, l2) = (self.m1, self.m2, self.l1, self.l2);
        let s = (m1 + m2) * (l1 + l2);
        let root = (s * s - 4.0 * (m1 + m2) * m1 * l1 * l2).sqrt();
        let den = 2.0 * m1 * l1 * l2;
        [(G * (s - root) / den).sqrt(), (G * (s + root) / den).sqrt()]
    }

    /// The mode of frequency ω as the state's (θ1, θ2): (K − ω² M) v = 0 in absolute angles.
    fn mode_shape(&self, omega: f64) -> [f64; 2] {
        let (m1, m2, l1, l2) = (self.m1, self.m2, self.l1, self.l2);
        let w2 = omega * omega;
        let v1 = w2 * m2 * l1 * l2;
        let v2 = (m1 + m2) * G * l1 - w2 * (m1 + m2) * l1 * l1;
        let norm = v1.hypot(v2);
        [v1 / norm, (v2 - v1) / norm]
    }
}

/// The frequency of θ1's oscillation from its upward zero crossings over `periods` periods
/// of the expected frequency `omega`, sampled 400 times a period.
fn measured_frequency(
    p: &DoublePendulum,
    y0: [f64; 4],
    omega: f64,
    periods: usize,
) -> Result<f64, Box<dyn Error>> {
    let period = std::f64::consts::TAU / omega;
    let dt = period / 400.0;
    let mut ode = Dop853::new(p, 0.0, y0, AdaptiveConfig::with_tol(1e-13, 1e-16))?;
    let mut crossings = Vec::new();
    let (mut t, mut prev) = (0.0, y0[0]);
    while crossings.len() <= periods {
        let next_t = t + dt;
        ode.advance_to(next_t)?;
        let now = ode.y()[0];
        if prev < 0.0 && now >= 0.0 {
            // The crossing by linear interpolation: θ1 is nearly linear across its zero.
            crossings.push(t + dt * prev / (prev - now));
        }
        (t, prev) = (next_t, now);
    }
    let (first, last) = match (crossings.first(), crossings.last()) {
        (Some(f), Some(l)) => (*f, *l),
        _ => return Err("no crossings".into()),
    };
    Ok(std::f64::consts::TAU * (crossings.len() - 1) as f64 / (last - first))
}

fn main() -> Result<(), Box<dyn Error>> {
    let p = DoublePendulum {
        m1: 1.0,
        l1: 1.0,
        m2: 0.5,
        l2: 0.7,
    };
    let mut table = Table::default();
    let amplitude = 1e-4;
    for (name, omega) in ["slow", "fast"].iter().zip(p.mode_frequencies()) {
        let v = p.mode_shape(omega);
        // Start at the mode's zero with its velocity, so θ1 crosses upward at once.
        let y0 = [0.0, 0.0, amplitude * omega * v[0], amplitude * omega * v[1]];
        let measured = measured_frequency(&p, y0, omega, 20)?;
        table.row(format!("{name} mode frequency ω [rad/s]"), measured, omega);
    }

    // A chaotic swing: energy is the measure of the integration's error.
    let y0 = [2.0, -1.0, 0.0, 0.0];
    let e0 = p.energy(&[y0[0], y0[1]], &[y0[2], y0[3]]);
    let mut ode = Dop853::new(&p, 0.0, y0, AdaptiveConfig::with_tol(1e-12, 1e-14))?;
    let (mut times, mut theta1, mut theta2, mut rate1) = (vec![], vec![], vec![], vec![]);
    let mut drift = Vec::new();
    let mut worst: f64 = 0.0;
    // The first 10 s of the swing, every 10 ms, for the animation.
    let mut swing = Trajectory::new(vec![]);
    swing.push(0.0, y0, &[])?;
    for k in 1..=3000 {
        let t = 0.01 * k as f64;
        ode.advance_to(t)?;
        let y = ode.y();
        let e = p.energy(&[y[0], y[1]], &[y[2], y[3]]);
        let rel = ((e - e0) / e0).abs();
        worst = worst.max(rel);
        times.push(t);
        theta1.push(y[0]);
        theta2.push(y[1]);
        rate1.push(y[2]);
        drift.push((t, rel.max(1e-18)));
        if t <= 10.0 + 1e-9 {
            swing.push(t, *y, &[])?;
        }
    }
    let y = ode.y();
    table.row(
        "energy after 30 s of chaos [J]",
        p.energy(&[y[0], y[1]], &[y[2], y[3]]),
        e0,
    );
    table.print(&format!(
        "Double pendulum, m1 = 1, l1 = 1, m2 = 0.5, l2 = 0.7 (derived by the {} route; theory: linearised normal modes, energy conservation)",
        <DoublePendulum as MechanismDynamics<2>>::ROUTE
    ));
    println!(
        "  largest relative energy error over the swing: {worst:.2e} ({} steps)",
        ode.stats().steps
    );

    // The library's one-call figures: the angles against time, and the upper rod's phase
    // portrait (θ1 against θ̇1), which a chaotic swing fills instead of closing.
    let dir = common::plot_dir()?;
    let path = precess::plot::time_series(
        dir.join("double_pendulum.svg"),
        "Double pendulum: a chaotic swing from θ = (2, −1)",
        &times,
        &[("θ1", &theta1), ("θ2 (relative)", &theta2)],
    )?;
    println!("  wrote {}", path.display());
    let path = precess::plot::phase_portrait(
        dir.join("double_pendulum_phase.svg"),
        "Double pendulum: the upper rod's phase portrait over 30 s",
        ("θ1 [rad]", &theta1),
        ("θ̇1 [rad/s]", &rate1),
    )?;
    println!("  wrote {}", path.display());
    let path = plot(
        "double_pendulum_energy.svg",
        &Axes {
            title: "Double pendulum: relative energy error, Dop853 at rtol 1e-12",
            x: "t [s]",
            y: "|E − E0| / |E0|",
            log_x: false,
            log_y: true,
        },
        &[Series::line("energy error", drift)],
    )?;
    println!("  wrote {}", path.display());

    // The first 10 s of the swing in motion: each rod keyframed from the derived link poses,
    // the joints as balls, the lower bob's path.
    let movie = animate::mechanism(&p, &swing, animate::Options::default())?;
    common::animation::write_animation(
        &dir,
        "double_pendulum",
        "Double pendulum: a chaotic swing from θ = (2, −1)",
        &movie,
        &table,
        "Dop853 at rtol 1e-12 against the normal modes and energy conservation",
    )?;
    Ok(())
}
