//! Chaplygin's ball: a sphere whose centre of mass is at its centre but whose three moments
//! differ, rolling without slip on the table.
//!
//! Chaplygin (1903) showed the motion integrable: besides the energy E, the angular momentum
//! K about the contact point keeps its vertical component K·ẑ and its magnitude |K|² (the
//! contact force passes through the contact point, and with G at the centre gravity does
//! too, so K is constant in space). The ball (radius 5 cm, 0.5 kg, moments 3e-4, 5e-4 and
//! 6.5e-4 kg·m²) is started tumbling about an oblique axis and rolled for 100 s; the table
//! gives each integral's largest drift, and the figure the path its contact point traces.
//!
//! The ball is declared on a struct (`#[rigid(body(..))]`, `#[contact(surface = sphere(..),
//! law = rolling, ..)]`) and rolled through the generated `ContactDynamics`, as a `ContactRun`
//! in the one run loop driven by `ode::Run` with the standard `ContactQuantities` (E, K·ẑ and
//! |K|² per sample).
//!
//! Run with `cargo run --release --example chaplygin_ball`.

mod common;

use std::error::Error;

use common::{Axes, Series, Table, plot};
use precess::contact::theory::SphereBody;
use precess::contact::{ContactDynamics, ContactQuantities, ContactRun, Phase, attitude_of};
use precess::nalgebra::{Matrix3, UnitQuaternion, Vector3};
use precess::ode::{AdaptiveConfig, Run, StopReason};
use precess::prelude::RigidBody;

/// The ball: radius 5 cm, M = 0.5 kg with its centre of mass at the centre of its sphere,
/// principal moments 3e-4, 5e-4 and 6.5e-4 kg·m².
#[derive(RigidBody)]
#[rigid(body(mass = 0.5, inertia = diag(3e-4, 5e-4, 6.5e-4)))]
#[contact(surface = sphere(radius = 0.05), law = rolling, gravity = 9.81)]
struct Ball;

fn main() -> Result<(), Box<dyn Error>> {
    let moments = [3e-4, 5e-4, 6.5e-4];
    let model = Ball;

    let q0 = UnitQuaternion::from_euler_angles(0.4, -0.2, 0.3);
    let y0 = model.rolling_state([0.0, 0.0], &q0, &Vector3::new(4.0, -7.0, 9.0))?;
    let t_end = 100.0;
    let mut cfg = AdaptiveConfig::with_tol(1e-13, 1e-13);
    cfg.max_steps = 10_000_000;
    // Steps no longer than the sampling interval: between steps the samples come from
    // DOP853's dense output, of order 7, whose own error (drifts of 1e-12 rather than 1e-14
    // with the controller's own, longer steps) would hide the integration's.
    cfg.h_max = 0.005;
    let mut run = ContactRun::new(&model, Phase::Rolling, 0.0, y0, cfg)?;
    let out = Run::new(&mut run, t_end)
        .sample_every(0.005)
        .quantities(ContactQuantities::new(&model, Phase::Rolling))
        .integrate()?;
    if out.stop == StopReason::Halted {
        println!("the run stopped at t = {} s: {:?}", out.t, run.run().halt());
    }

    // The closed forms of contact::theory, evaluated beside the model's own outputs.
    let ball = SphereBody {
        radius: 0.05,
        centre: Vector3::zeros(),
        mass: 0.5,
        inertia: Matrix3::from_diagonal(&Vector3::from(moments)),
        gravity: 9.81,
    };
    let names = ["energy", "K_z", "K2"];
    let columns = names
        .iter()
        .map(|name| {
            out.trajectory
                .column(name)
                .ok_or(format!("no column {name}"))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let quantities = |y: &[f64; 11]| {
        let k = model.momenta(Phase::Rolling, y).contact;
        [model.energy(Phase::Rolling, y), k.z, k.norm_squared()]
    };
    let start = quantities(&y0);
    let worst: Vec<f64> = columns
        .iter()
        .zip(start)
        .map(|(column, s0)| {
            column
                .iter()
                .map(|v| (v - s0).abs() / s0.abs())
                .fold(0.0, f64::max)
        })
        .collect();
    let mut worst_theory = 0.0_f64;
    let mut path = Vec::new();
    for (y, k2) in out.trajectory.states().iter().zip(&columns[2]) {
        let q = attitude_of(y);
        let w = Vector3::new(y[8], y[9], y[10]);
        let kt = ball.contact_momentum(&q, &w);
        worst_theory = worst_theory.max((kt.norm_squared() - k2).abs() / k2);
        let cp = model.contact(y).space;
        path.push((cp.x, cp.y));
    }
    let end = quantities(&out.state);
    println!(
        "Chaplygin's ball: R = 0.05 m, M = 0.5 kg, moments {moments:?} kg·m², {t_end} s rolling"
    );
    let mut table = Table::default();
    let names = ["energy E (J)", "K·ẑ (kg m²/s)", "|K|² (kg² m⁴/s²)"];
    for k in 0..3 {
        table.row(format!("{} at {t_end} s", names[k]), end[k], start[k]);
    }
    for k in 0..3 {
        table.row(format!("max relative drift of {}", names[k]), worst[k], 0.0);
    }
    table.row(
        "max |K|² gap, model against theory::SphereBody",
        worst_theory,
        0.0,
    );
    table.print("Chaplygin's integrals over the run");

    let a1 = Axes {
        title: "Chaplygin's ball: the path of the contact point",
        x: "x (m)",
        y: "y (m)",
        log_x: false,
        log_y: false,
    };
    let f1 = plot(
        "chaplygin_ball_path.svg",
        &a1,
        &[Series::line(
            "contact point",
            path.iter().step_by(4).copied().collect(),
        )],
    )?;
    println!("\nfigure: {}", f1.display());
    Ok(())
}
