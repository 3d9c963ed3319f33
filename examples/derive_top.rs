//! The equations of a user's own derived top, as a paper prints them: the heavy symmetric
//! top's Lagrangian, its Euler–Lagrange equations, q̈ and the conserved momenta in LaTeX,
//! with the operation counts of the code `#[top]` generated. All of it was computed when the
//! derive expanded; `equations()` only hands out `'static` data. The same scene built at run
//! time with precess's own symbolic engine prints the same lines.
//!
//! Run with `cargo run --example derive_top`.

use std::time::Instant;

use precess::codegen::latex;
use precess::lagrange::LagrangeError;
use precess::prelude::*;
use precess::sym::Arena;
use precess::top::TopScene;

/// The heavy symmetric top, its fields named as the textbook names them (they print as
/// `I_{1}`, `M`, …): I₁ = I₂ and I₃ about the pivot, the centre of mass at l on the axis.
#[allow(non_snake_case)]
#[derive(RigidBody)]
#[rigid(
    body(mass = M, at = [0.0, 0.0, l], inertia = diag(I_1, I_1, I_3), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = g)]
struct HeavyTop {
    I_1: f64,
    I_3: f64,
    M: f64,
    g: f64,
    l: f64,
}

fn main() -> Result<(), LagrangeError> {
    let top = HeavyTop {
        I_1: 1.0,
        I_3: 0.5,
        M: 1.0,
        g: 9.81,
        l: 0.1,
    };
    let eq = top.equations();
    println!("Heavy symmetric top, ZXZ Euler angles (φ, θ, ψ), as derived by #[top]:\n");
    println!("{}\n", eq.align());
    println!("Operations of the generated methods (declared chart):");
    for c in eq.costs.iter() {
        println!("  {:<18} {}", c.method, c.ops);
    }

    // The engine's own canonical form keeps sin θ to degree one, so sin² θ reads 1 − cos² θ.
    let started = Instant::now();
    let mut a = Arena::new();
    let (i1, i3) = (a.parameter("I_1"), a.parameter("I_3"));
    let z = a.zero();
    let mut scene = TopScene::free(&mut a, [[i1, z, z], [z, i1, z], [z, z, i3]]);
    scene.mass = a.parameter("M");
    scene.center = [z, z, a.parameter("l")];
    scene.gravity = Some(a.parameter("g"));
    let run_time = scene.typeset(&mut a)?;
    let elapsed = started.elapsed();
    let derivation = scene.derive(&mut a)?;
    let l = a.sub(derivation.kinetic, derivation.potential);
    println!(
        "\nThe same L in the engine's canonical form:\n  L = {}",
        latex(&a, l)
    );
    println!(
        "\nThe same scene built at run time prints the same lines: {} \
         (derived and typeset in {:.2} ms).",
        if run_time == *eq { "yes" } else { "no" },
        elapsed.as_secs_f64() * 1e3
    );
    Ok(())
}
