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
//! The top is declared on a struct: `#[rigid]` gives its mass and inertia, `#[contact]` its
//! spherical surface and the table's law, and the derive emits the equations of motion
//! (`ContactDynamics`) as straight-line code while it expands.
//!
//! Run with `cargo run --release --example tippe_top`.

mod common;
#[path = "common/contact.rs"]
mod contact;

use std::error::Error;

use common::{Axes, Series, Table, plot};
use contact::sample;
use precess::contact::theory::TippeTop;
use precess::contact::{ContactDynamics, Phase, attitude_of};
use precess::nalgebra::{UnitQuaternion, Vector3};
use precess::prelude::RigidBody;

/// The top: mass M = 20 g with its centre of mass at the origin, I₁ = 0.35 M R² and
/// I₃ = 0.4 M R² (R = 2 cm), a sphere of radius R centred αR = 6 mm above the centre of mass,
/// gliding with viscous friction c = 0.1 kg/s (5 M per second).
#[derive(RigidBody)]
#[rigid(body(
    mass = 0.02,
    inertia = diag(0.35 * 0.02 * 0.02 * 0.02, 0.35 * 0.02 * 0.02 * 0.02, 0.4 * 0.02 * 0.02 * 0.02),
))]
#[contact(
    surface = sphere(radius = 0.02, center = [0.0, 0.0, 0.3 * 0.02]),
    law = sliding(viscous = 5.0 * 0.02),
    gravity = 9.81,
)]
struct Top;

fn main() -> Result<(), Box<dyn Error>> {
    let (m, r, alpha) = (0.02, 0.02, 0.3);
    // The closed forms take the top's numbers as written here, not as the derive read them.
    let top = TippeTop {
        radius: r,
        alpha,
        mass: m,
        i1: 0.35 * m * r * r,
        i3: 0.4 * m * r * r,
        gravity: 9.81,
    };
    let viscous = 5.0 * m;
    let model = Top;

    let tilt = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), 0.1);
    let mut y0 = [0.0; 11];
    let q = tilt.quaternion();
    y0[4..8].copy_from_slice(&[q.w, q.i, q.j, q.k]);
    y0[8..11].copy_from_slice(&[0.0, 0.0, 140.0]);

    let run = sample(&model, y0, 0.005, 20.0, 1e-12)?;
    let phase = Phase::Sliding;
    let lambda0 = model.jellett(&y0);
    let e0 = model.energy(phase, &y0);
    let (mut angle, mut energy, mut drift) = (Vec::new(), Vec::new(), Vec::new());
    let mut worst = 0.0_f64;
    for (t, y) in run.t.iter().zip(&run.y) {
        let k = attitude_of(y) * Vector3::z();
        angle.push((*t, k.z.clamp(-1.0, 1.0).acos().to_degrees()));
        energy.push((*t, model.energy(phase, y) / e0));
        let d = (model.jellett(y) - lambda0).abs() / lambda0;
        worst = worst.max(d);
        drift.push((*t, d.max(1e-17)));
    }
    let last = run.y.last().copied().unwrap_or(y0);
    let w_space = attitude_of(&last) * Vector3::new(last[8], last[9], last[10]);
    let height = model.contact(&last).height;
    let flip = angle
        .iter()
        .find(|(_, deg)| *deg > 90.0)
        .map_or(f64::NAN, |p| p.0);

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
    println!("  the axis passes the horizontal at t = {flip:.3} s");
    let mut table = Table::default();
    table.row("Jellett λ at 20 s (kg m³/s)", model.jellett(&last), lambda0);
    table.row("max |λ/λ₀ − 1| over the run", worst, 0.0);
    table.row(
        "final spin about the vertical (rad/s)",
        w_space.z,
        top.inverted_spin(lambda0),
    );
    table.row(
        "final energy (J)",
        model.energy(phase, &last),
        top.inverted_energy(lambda0),
    );
    table.row(
        "final height of the centre of mass (m)",
        height,
        r * (1.0 + alpha),
    );
    table.row(
        "energy lost, fraction",
        1.0 - model.energy(phase, &last) / e0,
        1.0 - top.inverted_energy(lambda0) / e0,
    );
    table.print("Inverted state against Jellett's integral (theory: contact::theory::TippeTop)");

    let a1 = Axes {
        title: "Tippe top: the symmetry axis turns over",
        x: "t (s)",
        y: "angle of the axis from the vertical (deg)",
        log_x: false,
        log_y: false,
    };
    let f1 = plot("tippe_top_angle.svg", &a1, &[Series::line("θ", angle)])?;
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
    Ok(())
}
