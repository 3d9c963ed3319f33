//! A satellite with a hinged panel on a `free` joint: the bus flies free of the ground (three
//! translations, three angles re-charted through gimbal lock), derived by
//! `#[derive(Mechanism)]`, against two independent results.
//!
//! ```sh
//! cargo run --release --example free_floating [plot directory]
//! ```
//!
//! In orbit, released at rest with the panel sprung open: the angular momentum is zero, so
//! nothing can turn the whole satellite, yet the bus turns as the panel swings (the falling
//! cat's trick, here with one shape coordinate, so the bus turns back when the panel does).
//! Its roll is a function of the hinge angle alone, the integral of the zero-momentum
//! condition (`roll_at_zero_momentum`). Thrown on Earth: the centre of mass follows the exact
//! parabola while the bus tumbles and the panel flaps, and the horizontal momentum, the
//! angular momentum about the centre and the energy stay what they were.

mod common;

use std::error::Error;

use common::{Axes, Series, Table, plot};
use precess::mechanism::MechanismDynamics;
use precess::mechanism::charts::ChartedMechanism;
use precess::ode::AdaptiveConfig;
use precess::prelude::*;

#[path = "mechanisms/free_floating.rs"]
mod mechanism;
use mechanism::{
    BUS_MASS, BUS_SIZE, HINGE, PANEL_ARM, PANEL_MASS, PANEL_SIZE, Satellite, cuboid_moments,
    roll_at_zero_momentum,
};

fn config() -> ChartConfig {
    ChartConfig {
        switch_below: 0.3,
        stepper: AdaptiveConfig::with_tol(1e-13, 1e-13),
    }
}

/// The centre of mass, its velocity and the angular momentum about it, from the bus's
/// attitude, angular velocity and origin and the hinge, by the bodies' kinematics.
fn totals(run: &ChartedMechanism<&Satellite, 14>) -> Option<[Vector3<f64>; 3]> {
    let (r, omega) = (run.joint_rotation(0)?, run.joint_omega(0)?);
    let y = run.state();
    let o = Vector3::new(y[Satellite::X], y[Satellite::Y], y[Satellite::Z]);
    let v_o = Vector3::new(
        y[7 + Satellite::X],
        y[7 + Satellite::Y],
        y[7 + Satellite::Z],
    );
    let (beta, beta_dot) = (y[Satellite::BETA], y[7 + Satellite::BETA]);
    let turn = *Rotation3::from_axis_angle(&Vector3::x_axis(), beta).matrix();
    let arm = Vector3::new(0.0, PANEL_ARM, 0.0);
    let lever = Vector3::new(0.0, HINGE, 0.0) + turn * arm;
    let centers = [o, o + r * lever];
    let velocities = [
        v_o,
        v_o + r * (omega.cross(&lever) + turn * (Vector3::x() * beta_dot).cross(&arm)),
    ];
    let i_bus = Matrix3::from_diagonal(&Vector3::from(cuboid_moments(BUS_MASS, BUS_SIZE)));
    let i_panel = Matrix3::from_diagonal(&Vector3::from(cuboid_moments(PANEL_MASS, PANEL_SIZE)));
    let panel_omega = turn.transpose() * omega + Vector3::x() * beta_dot;
    let masses = [BUS_MASS, PANEL_MASS];
    let total = BUS_MASS + PANEL_MASS;
    let center = (centers[0] * masses[0] + centers[1] * masses[1]) / total;
    let velocity = (velocities[0] * masses[0] + velocities[1] * masses[1]) / total;
    let mut l = r * i_bus * omega + r * turn * i_panel * panel_omega;
    for ((&m, c), v) in masses.iter().zip(&centers).zip(&velocities) {
        l += m * (c - center).cross(&(v - velocity));
    }
    Some([center, velocity, l])
}

fn main() -> Result<(), Box<dyn Error>> {
    // In orbit, at zero angular momentum.
    let orbit = Satellite { g: 0.0, k: 200.0 };
    let beta0 = 1.0;
    let mut y0 = [0.0; 14];
    y0[Satellite::BETA] = beta0;
    let still = [(Matrix3::identity(), Vector3::zeros())];
    let mut run = ChartedMechanism::from_attitudes(&orbit, 0.0, y0, &still, config())?;
    let (mut rolls, mut betas) = (Vec::new(), Vec::new());
    let (mut worst_roll, mut largest_l) = (0.0f64, 0.0f64);
    // The sample where the panel has swung furthest the other way: (β, roll).
    let mut far = (beta0, 0.0);
    for k in 1..=400 {
        let t = 0.005 * f64::from(k);
        run.advance_to(t)?;
        let r = run.joint_rotation(0).ok_or("the bus's attitude")?;
        let roll = r[(2, 1)].atan2(r[(1, 1)]);
        let beta = run.state()[Satellite::BETA];
        let theory = roll_at_zero_momentum(beta0, beta);
        worst_roll = worst_roll.max((roll - theory).abs());
        if beta < far.0 {
            far = (beta, roll);
        }
        largest_l = largest_l.max(totals(&run).ok_or("state")?[2].norm());
        rolls.push((t, roll));
        betas.push((t, beta));
    }
    let mut table = Table::default();
    table.row(
        "largest |roll − roll(β) of L = 0| over 2 s [rad]",
        worst_roll,
        0.0,
    );
    table.row("largest |L| about the centre [kg·m²/s]", largest_l, 0.0);
    table.row(
        format!(
            "the bus's roll at the panel's far swing, β = {:.4} [rad]",
            far.0
        ),
        far.1,
        roll_at_zero_momentum(beta0, far.0),
    );
    table.print(&format!(
        "Satellite in orbit at zero angular momentum ({} route; theory: L = 0 integrated in β)",
        <Satellite as MechanismDynamics<7>>::ROUTE
    ));

    // Thrown on Earth, tumbling.
    let thrown = Satellite { g: 9.81, k: 40.0 };
    let (y0, r0, omega0) = mechanism::thrown_start();
    let spin = [(r0, omega0)];
    let mut run = ChartedMechanism::from_attitudes(&thrown, 0.0, y0, &spin, config())?;
    let [c0, v0, l0] = totals(&run).ok_or("state")?;
    let e0 = run.energy();
    let apex_time = v0.z / 9.81;
    let mut heights = Vec::new();
    let (mut worst_centre, mut worst_l) = (0.0f64, 0.0f64);
    let steps = 200;
    for k in 1..=steps {
        let t = 2.0 * apex_time * f64::from(k) / f64::from(steps);
        run.advance_to(t)?;
        let [c, _, l] = totals(&run).ok_or("state")?;
        let parabola = c0 + v0 * t - Vector3::new(0.0, 0.0, 0.5 * 9.81 * t * t);
        worst_centre = worst_centre.max((c - parabola).norm());
        worst_l = worst_l.max((l - l0).norm() / l0.norm());
        heights.push((t, c.z));
    }
    let [_, v, _] = totals(&run).ok_or("state")?;
    let mut table = Table::default();
    table.row(
        "centre's height on landing [m]",
        heights.last().map_or(f64::NAN, |h| h.1),
        c0.z,
    );
    table.row("largest |centre − parabola| [m]", worst_centre, 0.0);
    table.row("horizontal velocity of the centre, x [m/s]", v.x, v0.x);
    table.row("horizontal velocity of the centre, y [m/s]", v.y, v0.y);
    table.row("largest |L − L0| / |L0| about the centre", worst_l, 0.0);
    table.row("energy on landing [J]", run.energy(), e0);
    table.print(&format!(
        "Satellite thrown under gravity ({} chart switches; theory: the parabola, the conservation laws)",
        run.switches()
    ));

    let path = plot(
        "free_floating.svg",
        &Axes {
            title: "Satellite at zero angular momentum: the panel swings, the bus turns",
            x: "t [s]",
            y: "angle [rad]",
            log_x: false,
            log_y: false,
        },
        &[
            Series::line("hinge β", betas),
            Series::line("bus roll", rolls),
        ],
    )?;
    println!("  wrote {}", path.display());
    Ok(())
}
