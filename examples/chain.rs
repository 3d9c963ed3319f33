//! A chain of four rods hanging from universal joints, a 3D pendulum of eight coordinates
//! derived by `#[derive(Mechanism)]`: its energy along a tangled swing, and its accelerations
//! against the run-time `MechanismModel` of the same scene built by hand.
//!
//! ```sh
//! cargo run --release --example chain [plot directory]
//! ```
//!
//! Each rod (mass 1 kg, length 0.5 m) hangs from the end of the one above by a universal
//! joint: a turn about the parent's x, then about the once-turned y. The rods' centres are
//! at their middles and their moments about the centre m l²/12 across, none along. The swing
//! starts with the rods bent out of one plane and at rest; with no damping the energy is
//! conserved, and its drift under Dop853 at rtol 1e-12 measures the integration. The
//! run-time model interprets the same derivation with the parameters bound at run time (no
//! code generated): the two agree at random states to rounding.

mod common;

use std::error::Error;

use common::{Axes, Series, Table, plot};
use precess::mechanism::{
    JointKind, MechanismDynamics, MechanismModel, MechanismScene, Parent, Route,
};
use precess::ode::{AdaptiveConfig, Dop853};
use precess::sym::Arena;

#[path = "mechanisms/chain.rs"]
mod mechanism;
use mechanism::{Chain, LINKS};

/// The same chain built at run time.
fn scene(a: &mut Arena) -> Result<MechanismScene, Box<dyn Error>> {
    let mut scene = MechanismScene::new();
    let z = a.zero();
    let g = a.number("-9.81")?;
    scene.gravity = Some([z, z, g]);
    let (one, half, quarter) = (a.one(), a.number("0.5")?, a.number("-0.25")?);
    // m l²/12 = 1/48 exactly, as the macro's rod has it.
    let (l2, twelve) = (a.number("0.25")?, a.number("12")?);
    let across = a.div(l2, twelve)?;
    for k in 0..LINKS {
        let parent = if k == 0 {
            Parent::Ground
        } else {
            Parent::Body(k - 1)
        };
        let kind = JointKind::Universal {
            axes: [[one, z, z], [z, one, z]],
        };
        let (qa, qb) = (format!("a{}", k + 1), format!("b{}", k + 1));
        let mut body =
            MechanismScene::body(a, &format!("link{}", k + 1), parent, kind, &[&qa, &qb]);
        if k > 0 {
            body.joint.at = [z, z, a.neg(half)];
        }
        body.mass = one;
        body.center = [z, z, quarter];
        body.inertia = [[across, z, z], [z, across, z], [z, z, z]];
        scene.bodies.push(body);
    }
    Ok(scene)
}

fn main() -> Result<(), Box<dyn Error>> {
    let mut arena = Arena::new();
    let scene = scene(&mut arena)?;
    let model = MechanismModel::new(&mut arena, &scene, Route::Auto, &[])?;

    // Derived against interpreted, at random states (a fixed SplitMix64 stream).
    let mut seed: u64 = 14;
    let mut uniform = |lo: f64, hi: f64| {
        seed = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = seed;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        lo + (hi - lo) * ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut worst: f64 = 0.0;
    let samples = 1000;
    for _ in 0..samples {
        let q: [f64; 8] = std::array::from_fn(|_| uniform(-1.5, 1.5));
        let qd: [f64; 8] = std::array::from_fn(|_| uniform(-3.0, 3.0));
        let derived = Chain.accelerations(0.0, &q, &qd)?;
        let interpreted = model.accelerations(0.0, &q, &qd)?;
        let scale = interpreted.iter().fold(1.0f64, |m, v| m.max(v.abs()));
        for (d, i) in derived.iter().zip(&interpreted) {
            worst = worst.max((d - i).abs() / scale);
        }
    }

    let y0 = [
        0.8, 0.0, -0.4, 0.6, 0.3, -0.5, 0.0, 0.9, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
    ];
    let (q0, qd0) = precess::mechanism::split_state::<8, 16>(&y0).ok_or("state")?;
    let e0 = Chain.energy(&q0, &qd0);
    let mut ode = Dop853::new(Chain, 0.0, y0, AdaptiveConfig::with_tol(1e-12, 1e-14))?;
    let (mut drift, mut tip) = (Vec::new(), Vec::new());
    let mut largest: f64 = 0.0;
    for k in 1..=1000 {
        let t = 0.01 * k as f64;
        ode.advance_to(t)?;
        let (q, qd) = precess::mechanism::split_state::<8, 16>(ode.y()).ok_or("state")?;
        let rel = ((Chain.energy(&q, &qd) - e0) / e0).abs();
        largest = largest.max(rel);
        drift.push((t, rel.max(1e-18)));
        tip.push((t, q[Chain::A4], q[Chain::B4]));
    }
    let (q, qd) = precess::mechanism::split_state::<8, 16>(ode.y()).ok_or("state")?;
    let mut table = Table::default();
    table.row("energy after 10 s [J]", Chain.energy(&q, &qd), e0);
    table.row(
        "largest |q̈ derived − q̈ interpreted| / max|q̈| over 1000 states",
        worst,
        0.0,
    );
    table.print(&format!(
        "Chain of {LINKS} rods on universal joints ({} route, {} steps; theory: energy conservation, the run-time model)",
        <Chain as MechanismDynamics<8>>::ROUTE,
        ode.stats().steps
    ));
    println!("  largest relative energy error over the swing: {largest:.2e}");
    println!(
        "  run-time model: {} coordinates, {:?}",
        model.dof(),
        model.op_count()
    );

    let path = plot(
        "chain.svg",
        &Axes {
            title: "Chain of four rods: the lowest joint's angles",
            x: "t [s]",
            y: "angle [rad]",
            log_x: false,
            log_y: false,
        },
        &[
            Series::line("a4", tip.iter().map(|&(t, a, _)| (t, a)).collect()),
            Series::line("b4", tip.iter().map(|&(t, _, b)| (t, b)).collect()),
        ],
    )?;
    println!("  wrote {}", path.display());
    let path = plot(
        "chain_energy.svg",
        &Axes {
            title: "Chain of four rods: relative energy error, Dop853 at rtol 1e-12",
            x: "t [s]",
            y: "|E − E0| / |E0|",
            log_x: false,
            log_y: true,
        },
        &[Series::line("energy error", drift)],
    )?;
    println!("  wrote {}", path.display());
    Ok(())
}
