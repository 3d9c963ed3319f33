//! The Dzhanibekov effect: a wing nut spun off a screw in orbit turns over every few seconds,
//! a torque-free body spinning near its intermediate principal axis. The time between flips
//! is half the period of the angular momentum in the body, 2K(m)/λ, from the Jacobi
//! elliptic solution (the library's exact free-body motion).
//!
//! ```sh
//! cargo run --release --example dzhanibekov [plot directory]
//! ```
//!
//! The flips are found as events: the intermediate component of ω crossing zero, located
//! on DOP853's dense output.

mod common;

use std::error::Error;

use common::Table;
use precess::exact::FreeBodyExact;
use precess::ode::{AdaptiveConfig, Dop853, Event, FnSystem, Run};
use precess::prelude::*;

/// A wing nut: a nut (a short cylinder about z) and two flat wings along ±x.
#[derive(RigidBody)]
#[rigid(
    cylinder(mass = 0.02, radius = 0.008, length = 0.01),
    cuboid(mass = 0.004, size = [0.02, 0.002, 0.014], at = [0.017, 0.0, 0.0]),
    cuboid(mass = 0.004, size = [0.02, 0.002, 0.014], at = [-0.017, 0.0, 0.0]),
)]
struct WingNut;

fn main() -> Result<(), Box<dyn Error>> {
    let nut = WingNut;
    let principal = nut.principal();
    let moments = principal.moments;
    // The intermediate axis: the one whose moment is neither the least nor the greatest.
    let mut order = [0usize, 1, 2];
    order.sort_by(|&a, &b| moments[a].total_cmp(&moments[b]));
    let mid = order[1];
    println!(
        "principal moments {moments:?} kg m², intermediate axis {}",
        mid + 1
    );

    // Spun at 20 rad/s about the intermediate axis, with 1 % of that about the others.
    let mut w0 = Vector3::repeat(0.2);
    w0[mid] = 20.0;
    let sys = FnSystem(|_t: f64, w: &[f64; 3], d: &mut [f64; 3]| {
        *d = nut
            .euler_rhs_principal(&Vector3::from(*w), &Vector3::zeros())
            .into();
    });
    let t_end = 20.0;
    let mut ode = Dop853::new(sys, 0.0, w0.into(), AdaptiveConfig::with_tol(1e-12, 1e-12))?;
    let mut out = Run::new(&mut ode, t_end)
        .sample_every(0.005)
        .event(Event::new("flip"), move |_t, w: &[f64; 3]| w[mid])
        .integrate()?;
    let flips: Vec<f64> = out.events.iter().map(|e| e.t).collect();

    let exact = FreeBodyExact::new(moments, moments.component_mul(&w0))?;
    let interval = 0.5 * exact.period();
    let mut table = Table::default();
    for (k, pair) in flips.windows(2).enumerate() {
        table.row(
            format!("interval between flips {} and {} [s]", k + 1, k + 2),
            pair[1] - pair[0],
            interval,
        );
    }
    if let Some(&first) = flips.first() {
        // The exact solution's own first zero of the intermediate component.
        let m = |t: f64| exact.m_at(t).map(|m| m[mid]);
        let (mut lo, mut hi) = (0.0, first + 0.5 * interval);
        let sign = m(lo)?.signum();
        for _ in 0..200 {
            let c = 0.5 * (lo + hi);
            if m(c)?.signum() == sign {
                lo = c
            } else {
                hi = c
            }
        }
        table.row("first flip [s]", first, 0.5 * (lo + hi));
    }
    table.row(
        "number of flips in 20 s",
        flips.len() as f64,
        ((t_end - flips.first().copied().unwrap_or(0.0)) / interval).floor() + 1.0,
    );
    table.print("Wing nut spun near its intermediate axis (DOP853, rtol 1e-12; theory 2K/λ)");

    // The library draws the recorded trajectory in one call, its columns named as the CSV
    // names them.
    out.trajectory.set_state_names(["ω1", "ω2", "ω3"])?;
    let path = precess::plot::trajectory(
        common::plot_dir()?.join("dzhanibekov.svg"),
        "Wing nut: body angular velocity ω [rad/s], flipping every 2K/λ",
        &out.trajectory,
        &[],
    )?;
    println!("  figure: {}", path.display());
    Ok(())
}
