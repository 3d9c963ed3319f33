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
//! law = rolling, ..)]`) and rolled through the generated `ContactDynamics`.
//!
//! Run with `cargo run --release --example chaplygin_ball`.

mod common;
#[path = "common/contact.rs"]
mod contact;

use std::error::Error;

use common::{Axes, Series, Table, plot};
use contact::sample;
use precess::contact::theory::SphereBody;
use precess::contact::{ContactDynamics, Phase, attitude_of};
use precess::nalgebra::{Matrix3, UnitQuaternion, Vector3};
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
    let run = sample(&model, y0, 0.005, t_end, 1e-13)?;

    // The closed forms of contact::theory, evaluated beside the model's own outputs.
    let ball = SphereBody {
        radius: 0.05,
        centre: Vector3::zeros(),
        mass: 0.5,
        inertia: Matrix3::from_diagonal(&Vector3::from(moments)),
        gravity: 9.81,
    };
    let quantities = |y: &[f64; 11]| {
        let k = model.momenta(Phase::Rolling, y).contact;
        [model.energy(Phase::Rolling, y), k.z, k.norm_squared()]
    };
    let start = quantities(&y0);
    let mut worst = [0.0_f64; 3];
    let mut worst_theory = 0.0_f64;
    let mut path = Vec::new();
    for y in &run.y {
        let now = quantities(y);
        for k in 0..3 {
            worst[k] = worst[k].max((now[k] - start[k]).abs() / start[k].abs());
        }
        let q = attitude_of(y);
        let w = Vector3::new(y[8], y[9], y[10]);
        let kt = ball.contact_momentum(&q, &w);
        worst_theory = worst_theory.max((kt.norm_squared() - now[2]).abs() / now[2]);
        let cp = model.contact(y).space;
        path.push((cp.x, cp.y));
    }
    let last = run.y.last().copied().unwrap_or(y0);
    let end = quantities(&last);
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
