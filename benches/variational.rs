//! The variational equations the derive emits (`#[top(variational(...))]`) against the
//! interpreted `VariationalSystem` of the same derivation, on the asymmetric heavy top of the
//! variational tests (I = 1, 1.5, 0.7 about the pivot; M g l = 1) in ZXZ angles:
//!
//! - `rhs/…`: one right-hand side of the whole Φ and the sensitivities to m, l, g
//!   (N = 6 + 36 + 18 = 60), at a fixed state;
//! - `benettin/…`: the maximal exponent (one tangent, N = 12) by Benettin's method over
//!   t = 20 in intervals of 0.5 with DOP853 at 10⁻¹⁰, the same run through both systems.
//!
//! `cargo bench -p precess-benches --bench variational`. The two systems evaluate the same
//! lowered program (the tests hold them bit-identical), so the ratio is the interpreter's
//! dispatch alone.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use precess::ode::{AdaptiveConfig, Dop853, System};
use precess::prelude::*;
use precess::sym::Arena;
use precess::top::TopScene;
use precess::variational::{BenettinConfig, VariationalEquations, VariationalSystem, benettin};

/// The heavy top with its fields as parameters and the whole Φ and S.
#[derive(RigidBody, Clone, Copy)]
#[rigid(
    body(mass = m, at = [0.0, 0.0, l], inertia = diag(i1, i2, i3), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = g, variational(sensitivities = [m, l, g]))]
struct Heavy {
    m: f64,
    l: f64,
    g: f64,
    i1: f64,
    i2: f64,
    i3: f64,
}

/// The same top with one tangent vector, for the maximal exponent.
#[derive(RigidBody, Clone, Copy)]
#[rigid(
    body(mass = m, at = [0.0, 0.0, l], inertia = diag(i1, i2, i3), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = g, variational(tangents = 1))]
struct HeavyMaximal {
    m: f64,
    l: f64,
    g: f64,
    i1: f64,
    i2: f64,
    i3: f64,
}

const VALUES: [(&str, f64); 6] = [
    ("m", 1.0),
    ("l", 1.0),
    ("g", 1.0),
    ("i1", 1.0),
    ("i2", 1.5),
    ("i3", 0.7),
];

/// The interpreted equations of the same scene, built by hand in an arena.
fn interpreted(a: &mut Arena, tangents: usize, sensitivities: &[&str]) -> VariationalEquations {
    let z = a.zero();
    let i = ["i1", "i2", "i3"].map(|n| a.parameter(n));
    let mut scene = TopScene::free(a, [[i[0], z, z], [z, i[1], z], [z, z, i[2]]]);
    scene.mass = a.parameter("m");
    scene.center = [z, z, a.parameter("l")];
    scene.gravity = Some(a.parameter("g"));
    let derivation = scene.derive(a).expect("the heavy top derives");
    VariationalEquations::from_top(a, &derivation, tangents, sensitivities)
        .expect("the equations build")
}

/// Benettin's maximal exponent of `sys` from the bench's start.
fn maximal<S: System<12>>(sys: S, y0: [f64; 12]) -> f64 {
    let cfg = BenettinConfig {
        interval: 0.5,
        duration: 20.0,
        transient: 0.0,
    };
    let mut ode = Dop853::new(sys, 0.0, y0, AdaptiveConfig::with_tol(1e-10, 1e-10))
        .expect("the integrator starts");
    benettin(
        &mut ode,
        precess::variational::Layout {
            n: 6,
            tangents: 1,
            sensitivities: 0,
        },
        &cfg,
    )
    .expect("the run succeeds")
    .exponents[0]
}

fn bench(c: &mut Criterion) {
    let x0 = [0.0, 1.5, 0.0, 0.3, 0.2, 0.5];
    let top = Heavy {
        m: 1.0,
        l: 1.0,
        g: 1.0,
        i1: 1.0,
        i2: 1.5,
        i3: 0.7,
    };
    let mut a = Arena::new();
    let full = interpreted(&mut a, 6, &["m", "l", "g"]);
    let sys = VariationalSystem::<60>::new(&a, &full, &VALUES).expect("the values bind");
    let generated = top.variational();
    let mut y = generated.initial_state(&x0).expect("a finite start");
    // Off the identity, so no product is trivially by one or zero.
    for (k, v) in y.iter_mut().enumerate().skip(6) {
        *v += 0.01 * k as f64;
    }
    let mut g = c.benchmark_group("variational");
    g.bench_function("rhs/generated_60", |b| {
        let mut dy = [0.0; 60];
        b.iter(|| {
            generated.rhs(0.0, black_box(&y), &mut dy);
            black_box(dy[59])
        })
    });
    g.bench_function("rhs/interpreted_60", |b| {
        let mut dy = [0.0; 60];
        b.iter(|| {
            sys.rhs(0.0, black_box(&y), &mut dy);
            black_box(dy[59])
        })
    });
    let one = HeavyMaximal {
        m: 1.0,
        l: 1.0,
        g: 1.0,
        i1: 1.0,
        i2: 1.5,
        i3: 0.7,
    };
    let mut a1 = Arena::new();
    let max_eq = interpreted(&mut a1, 1, &[]);
    let max_sys = VariationalSystem::<12>::new(&a1, &max_eq, &VALUES).expect("the values bind");
    let y0 = max_sys.initial_state(&x0).expect("a finite start");
    let (lg, li) = (maximal(one.variational(), y0), maximal(&max_sys, y0));
    println!("maximal exponent over t = 20: generated {lg}, interpreted {li}");
    g.sample_size(20);
    g.bench_function("benettin/generated_12", |b| {
        b.iter(|| maximal(one.variational(), black_box(y0)))
    });
    g.bench_function("benettin/interpreted_12", |b| {
        b.iter(|| maximal(&max_sys, black_box(y0)))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
