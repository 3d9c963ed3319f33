//! Derives the heavy symmetric top's equations of motion at run time with precess's own
//! symbolic engine: the Lagrangian in ZXZ Euler angles, the Euler–Lagrange residuals, the
//! solved accelerations, each printed in LaTeX with the cost of the code generated for it.
//!
//! Run with `cargo run --example derive_top`.

use std::time::Instant;

use precess::codegen::{Program, latex};
use precess::lagrange::LagrangeError;
use precess::sym::Arena;
use precess::top::TopScene;

fn main() -> Result<(), LagrangeError> {
    let started = Instant::now();
    let mut a = Arena::new();
    // Symmetric top: I1 = I2 about the pivot, centre of mass on the symmetry axis at l.
    let (i1, i3) = (a.parameter("I_1"), a.parameter("I_3"));
    let (m, g, l) = (a.parameter("M"), a.parameter("g"), a.parameter("l"));
    let z = a.zero();
    let inertia = [[i1, z, z], [z, i1, z], [z, z, i3]];
    let mut scene = TopScene::free(&mut a, inertia);
    scene.mass = m;
    scene.center = [z, z, l];
    scene.gravity = Some(g);
    let top = scene.derive(&mut a)?;
    let elapsed = started.elapsed();

    println!("Heavy symmetric top, ZXZ Euler angles (phi, theta, psi)\n");
    println!("T = {}", latex(&a, top.kinetic));
    println!("V = {}", latex(&a, top.potential));
    println!("\nEuler–Lagrange residuals d/dt dL/dq' - dL/dq = 0:");
    let names = ["\\phi", "\\theta", "\\psi"];
    for (name, &r) in names.iter().zip(&top.equations.residuals) {
        let ops = Program::lower(&a, &[r]).op_count();
        println!("  [{name}]  {} = 0\n      ({ops})", latex(&a, r));
    }
    println!(
        "\nMass matrix blocks solved together: {:?}",
        top.accelerations.blocks
    );
    for (block, &det) in top
        .accelerations
        .blocks
        .iter()
        .zip(&top.accelerations.determinants)
    {
        println!("  det M{block:?} = {}", latex(&a, det));
    }
    println!("\nSolved accelerations:");
    for (name, &q) in names.iter().zip(&top.accelerations.accel) {
        println!("  \\ddot{{{name}}} = {}", latex(&a, q));
    }
    let all = Program::lower(&a, &top.accelerations.accel);
    println!(
        "\nGenerated code for all three accelerations: {}",
        all.op_count()
    );
    for (name, p) in names.iter().zip(&top.conserved_momenta) {
        if let Some(p) = p {
            println!("Conserved: p_{{{name}}} = {}", latex(&a, *p));
        }
    }
    println!(
        "\nDerived in {:.2} ms ({} expression nodes).",
        elapsed.as_secs_f64() * 1e3,
        a.len()
    );
    Ok(())
}
