//! The variational equations the derive emits (`#[top(variational(...))]`) against the
//! interpreted `VariationalSystem` of the same derivation, on the asymmetric heavy top of the
//! variational tests (I = 1, 1.5, 0.7 about the pivot; M g l = 1) in ZXZ angles:
//!
//! - `rhs/…`: one right-hand side of the whole Φ and the sensitivities to m, l, g
//!   (N = 6 + 36 + 18 = 60), at a fixed state;
//! - `benettin/…`: the maximal exponent (one tangent, N = 12) by Benettin's method over
//!   t = 20 in intervals of 0.5 with DOP853 at 10⁻¹⁰, the same run through both systems.
//!
//! The same pair for `#[mechanism(variational(...))]`, on the double pendulum of the
//! mechanism's variational tests (equal masses and lengths, g = 9.81, released from rest at
//! θ1 = 2, θ2 = 0.5):
//!
//! - `mechanism/rhs/…`: the whole Φ and the sensitivities to l1 and m2 (N = 4 + 16 + 8 = 28);
//! - `mechanism/benettin/…`: the maximal exponent (N = 8) over t = 20 in intervals of 0.25
//!   at 10⁻¹⁰.
//!
//! `cargo bench -p precess-benches --bench variational`. For the top the two systems
//! evaluate the same lowered program (the tests hold them bit-identical), so the ratio is
//! the interpreter's dispatch alone; the mechanism's interpreted scene is built by hand, so
//! its program is an equal one, not the same (the tests hold them equal to rounding).

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use precess::mechanism::Route;
use precess::ode::{AdaptiveConfig, Dop853, System};
use precess::prelude::*;
use precess::sym::Arena;
use precess::top::TopScene;
use precess::variational::{
    BenettinConfig, Layout, VariationalEquations, VariationalSystem, benettin,
};

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
        Layout {
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

/// The double pendulum with its fields as parameters, the whole Φ and S to l1, m2.
#[derive(Mechanism, Clone, Copy)]
#[mechanism(gravity = g, variational(sensitivities = [l1, m2]))]
#[body(upper, parent = ground, joint = revolute(axis = x), q = theta1,
       parts(particle(mass = m1, at = [0.0, 0.0, -l1])))]
#[body(lower, parent = upper, joint = revolute(axis = x, at = [0.0, 0.0, -l1]), q = theta2,
       parts(particle(mass = m2, at = [0.0, 0.0, -l2])))]
struct Double {
    m1: f64,
    l1: f64,
    m2: f64,
    l2: f64,
    g: f64,
}

/// The same pendulum with one tangent vector, for the maximal exponent.
#[derive(Mechanism, Clone, Copy)]
#[mechanism(gravity = g, variational(tangents = 1))]
#[body(upper, parent = ground, joint = revolute(axis = x), q = theta1,
       parts(particle(mass = m1, at = [0.0, 0.0, -l1])))]
#[body(lower, parent = upper, joint = revolute(axis = x, at = [0.0, 0.0, -l1]), q = theta2,
       parts(particle(mass = m2, at = [0.0, 0.0, -l2])))]
struct DoubleMaximal {
    m1: f64,
    l1: f64,
    m2: f64,
    l2: f64,
    g: f64,
}

/// The hand scene's parameters: m0, l0 the upper body's, m1, l1 the lower's.
const PENDULUM: [(&str, f64); 5] = [
    ("m0", 1.0),
    ("l0", 1.0),
    ("m1", 1.0),
    ("l1", 1.0),
    ("g", 9.81),
];

/// The interpreted equations of the same pendulum, its scene built by hand in an arena.
fn interpreted_pendulum(
    a: &mut Arena,
    tangents: usize,
    sensitivities: &[&str],
) -> VariationalEquations {
    let scene = precess_testkit::scenes::double_pendulum(a, None);
    let derivation = scene.derive(a, Route::Auto).expect("the pendulum derives");
    VariationalEquations::from_mechanism(a, &derivation, tangents, sensitivities)
        .expect("the equations build")
}

/// Benettin's maximal exponent of the pendulum's `sys` from the bench's start.
fn maximal_pendulum<S: System<8>>(sys: S, y0: [f64; 8]) -> f64 {
    let cfg = BenettinConfig {
        interval: 0.25,
        duration: 20.0,
        transient: 0.0,
    };
    let mut ode = Dop853::new(sys, 0.0, y0, AdaptiveConfig::with_tol(1e-10, 1e-10))
        .expect("the integrator starts");
    let layout = Layout {
        n: 4,
        tangents: 1,
        sensitivities: 0,
    };
    benettin(&mut ode, layout, &cfg)
        .expect("the run succeeds")
        .exponents[0]
}

fn bench_mechanism(c: &mut Criterion) {
    let x0 = [2.0, 0.5, 0.0, 0.0];
    let p = Double {
        m1: 1.0,
        l1: 1.0,
        m2: 1.0,
        l2: 1.0,
        g: 9.81,
    };
    let mut a = Arena::new();
    let full = interpreted_pendulum(&mut a, 4, &["l0", "m1"]);
    let sys = VariationalSystem::<28>::new(&a, &full, &PENDULUM).expect("the values bind");
    let generated = p.variational();
    let mut y = generated.initial_state(&x0).expect("a finite start");
    // Off the identity, so no product is trivially by one or zero.
    for (k, v) in y.iter_mut().enumerate().skip(4) {
        *v += 0.01 * k as f64;
    }
    let mut g = c.benchmark_group("variational");
    g.bench_function("mechanism/rhs/generated_28", |b| {
        let mut dy = [0.0; 28];
        b.iter(|| {
            generated.rhs(0.0, black_box(&y), &mut dy);
            black_box(dy[27])
        })
    });
    g.bench_function("mechanism/rhs/interpreted_28", |b| {
        let mut dy = [0.0; 28];
        b.iter(|| {
            sys.rhs(0.0, black_box(&y), &mut dy);
            black_box(dy[27])
        })
    });
    let one = DoubleMaximal {
        m1: 1.0,
        l1: 1.0,
        m2: 1.0,
        l2: 1.0,
        g: 9.81,
    };
    let mut a1 = Arena::new();
    let max_eq = interpreted_pendulum(&mut a1, 1, &[]);
    let max_sys = VariationalSystem::<8>::new(&a1, &max_eq, &PENDULUM).expect("the values bind");
    let y0 = max_sys.initial_state(&x0).expect("a finite start");
    let (lg, li) = (
        maximal_pendulum(one.variational(), y0),
        maximal_pendulum(&max_sys, y0),
    );
    println!("double pendulum maximal exponent over t = 20: generated {lg}, interpreted {li}");
    g.sample_size(20);
    g.bench_function("mechanism/benettin/generated_8", |b| {
        b.iter(|| maximal_pendulum(one.variational(), black_box(y0)))
    });
    g.bench_function("mechanism/benettin/interpreted_8", |b| {
        b.iter(|| maximal_pendulum(&max_sys, black_box(y0)))
    });
    g.finish();
}

criterion_group!(benches, bench, bench_mechanism);
criterion_main!(benches);
