//! A coin spun on its edge comes to rest in finite time: Coulomb friction with stick–slip
//! holds its contact point, and pivoting friction, the torque −ℓ_p N sign(ω·γ) γ about the
//! vertical (ℓ_p = μ_p r_p, a pivoting coefficient times the contact patch's radius;
//! Leine & Glocker's drilling friction), brakes its spin at the constant rate ℓ_p M g / I_d.
//! Spun about its vertical diameter the contact point is on the spin axis, N = M g, and the
//! spin stops at t* = I_d ω₀ / (ℓ_p M g), I_d = M ρ²/4; there the friction holds the spin at
//! zero and the run goes on with it held (a switch of the `spin` witness): the coin stands at
//! rest on its edge, an unstable equilibrium whose rounding-sized tilt grows as e^(st),
//! s = √(4g/(5ρ)). A linear spin resistance −c_s ω_⊥ with the same initial torque only slows
//! the spin exponentially: that coin spins for ever.
//!
//! The coin is declared on a struct (`#[contact(.., law = stick_slip(mu = 0.3,
//! pivoting = 2e-4), ..)]`) and runs in `ContactRun`, the contact's instance of the one run
//! loop, whose `spin` witness finds where the friction comes to hold the spin.
//!
//! Run with `cargo run --release --example coin_at_rest`.

mod common;

use std::error::Error;

use common::{Axes, Series, Table, plot};
use precess::contact::{ContactDynamics, ContactRun, Phase, STATE_LEN};
use precess::nalgebra::{UnitQuaternion, Vector3};
use precess::ode::{AdaptiveConfig, Run};
use precess::prelude::RigidBody;

/// A coin of radius 12 mm and 5.7 g under Coulomb stick–slip and pivoting friction.
#[derive(RigidBody)]
#[rigid(disk(mass = 0.0057, radius = 0.012))]
#[contact(
    surface = disk_rim(radius = 0.012),
    law = stick_slip(mu = 0.3, pivoting = 2e-4),
    gravity = 9.81,
)]
struct Coin;

/// The same coin under a linear spin resistance c_s instead.
#[derive(RigidBody)]
#[rigid(disk(mass = 0.0057, radius = 0.012))]
#[contact(
    surface = disk_rim(radius = 0.012),
    law = stick_slip(mu = 0.3, spin_resistance = cs),
    gravity = 9.81,
)]
struct Damped {
    /// The spin resistance c_s (N m s).
    cs: f64,
}

const MASS: f64 = 0.0057;
const RADIUS: f64 = 0.012;
const GRAVITY: f64 = 9.81;
const PIVOTING: f64 = 2e-4;

/// Standing on its edge, its axis along space y, spinning at `w0` about the vertical.
fn on_edge(coin: &dyn ContactDynamics, w0: f64) -> Result<[f64; STATE_LEN], Box<dyn Error>> {
    let q = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::FRAC_PI_2);
    Ok(coin.rolling_state([0.0, 0.0], &q, &(q.inverse() * Vector3::new(0.0, 0.0, w0)))?)
}

/// The spin about the vertical, ω·γ.
fn spin(coin: &dyn ContactDynamics, y: &[f64; STATE_LEN]) -> f64 {
    coin.contact(y).gamma.dot(&Vector3::new(y[8], y[9], y[10]))
}

fn main() -> Result<(), Box<dyn Error>> {
    let w0 = 20.0;
    let i_d = MASS * RADIUS * RADIUS / 4.0;
    let brake = PIVOTING * MASS * GRAVITY;
    let t_star = i_d * w0 / brake;
    let cfg = AdaptiveConfig::with_tol(1e-12, 1e-14);

    let mut run = ContactRun::new(&Coin, Phase::Rolling, 0.0, on_edge(&Coin, w0)?, cfg)?;
    let out = Run::new(&mut run, 3.0 * t_star)
        .sample_every(t_star / 200.0)
        .quantity("spin", |_t, y| spin(&Coin, y))
        .integrate()?;
    if let Some(halt) = run.run().halt() {
        return Err(format!("the run stopped: {halt:?}").into());
    }
    let Some(held) = run.switches().into_iter().find(|s| s.spin_held_after) else {
        return Err("the friction never held the spin".into());
    };
    let (t, state) = (held.t, out.state.x);
    let damped = Damped { cs: brake / w0 };
    let mut slow = ContactRun::new(&damped, Phase::Rolling, 0.0, on_edge(&damped, w0)?, cfg)?;
    let on = Run::new(&mut slow, 3.0 * t_star)
        .sample_every(t_star / 200.0)
        .quantity("spin", |_t, y| spin(&damped, y))
        .integrate()?;

    println!(
        "A coin (ρ = {RADIUS} m, M = {MASS} kg) spun on its edge at {w0} rad/s, μ = 0.3, ℓ_p = {PIVOTING} m"
    );
    let mut table = Table::default();
    table.row("time the spin is held (s)", t, t_star);
    table.row(
        "spin halfway (rad/s)",
        out.trajectory
            .column("spin")
            .and_then(|c| c.get(100).copied())
            .unwrap_or(f64::NAN),
        0.5 * w0,
    );
    let end = on.state;
    table.row(
        "linear resistance: spin at 3 t* (rad/s)",
        spin(&damped, &end),
        w0 * (-3.0 * brake / w0 * t_star / i_d).exp(),
    );
    table.print("Pivoting friction stops the coin at t* = I_d ω₀ / (ℓ_p M g)");
    println!(
        "  at 3 t* = {:.3} s, the spin held ({}): |ω| = {:e} rad/s and the centre's speed {:e} m/s, the\n  coin starting to topple from its edge, the rounding's tilt grown at √(4g/(5ρ)) = {:.2} 1/s",
        run.t(),
        run.spin_held(),
        Vector3::new(state[8], state[9], state[10]).norm(),
        state[2].hypot(state[3]),
        (4.0 * GRAVITY / (5.0 * RADIUS)).sqrt()
    );
    let curve = |trajectory: &precess::ode::Trajectory<_>| -> Vec<(f64, f64)> {
        let s = trajectory.column("spin").unwrap_or_default();
        trajectory
            .times()
            .iter()
            .copied()
            .zip(s.iter().copied())
            .collect()
    };
    let axes = Axes {
        title: "A coin spun on its edge",
        x: "t (s)",
        y: "spin ω·γ (rad/s)",
        log_x: false,
        log_y: false,
    };
    let figure = plot(
        "coin_at_rest.svg",
        &axes,
        &[
            Series::line("pivoting friction ℓ_p N sign(ω)", curve(&out.trajectory)),
            Series::line("linear spin resistance c_s ω", curve(&on.trajectory)),
        ],
    )?;
    println!("\nfigure: {}", figure.display());
    Ok(())
}
