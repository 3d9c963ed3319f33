//! The symbolic engine's speed: building and differentiating a top's kinetic energy, the
//! whole derivation of the symmetric and the asymmetric heavy top, and how expansion and
//! derivation grow with the number of terms, the power and the number of point masses.

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use precess_core::body::{Description, Part, Shape, SymbolicBody};
use precess_core::codegen::Program;
use precess_core::rigid::AngleSequence;
use precess_core::sym::{Arena, ExprId};
use precess_core::top::TopScene;
use std::hint::black_box;

/// `(x₁ + … + x_terms)^power`, expanded in a fresh arena.
fn expand_power(terms: usize, power: i64) -> usize {
    let mut a = Arena::new();
    let vars: Vec<ExprId> = (0..terms).map(|i| a.parameter(&format!("x{i}"))).collect();
    let s = a.sum(&vars);
    let p = a.powi(s, power).expect("a power of a sum");
    let x = a.expand(p);
    a.node(x).children().len()
}

/// The top of `n` field-valued point masses under gravity, derived and lowered as the
/// derive macro does (the body's mass properties, then the angle-form equations).
fn point_mass_top(n: usize) -> usize {
    let mut a = Arena::new();
    let z = a.zero();
    let parts: Vec<Part<ExprId>> = (0..n)
        .map(|i| Part {
            shape: Shape::Particle {
                mass: a.parameter(&format!("m{i}")),
            },
            at: ["x", "y", "z"].map(|c| a.parameter(&format!("{c}{i}"))),
            orientation: None,
        })
        .collect();
    let d = Description {
        parts,
        pivot: Some([z, z, z]),
    };
    let body = SymbolicBody::new(&mut a, &d).expect("a cloud of masses is a body");
    let mut scene = TopScene::free(&mut a, body.props.inertia);
    scene.mass = body.props.mass;
    scene.center = body.props.center;
    scene.gravity = Some(a.number("9.81").expect("a literal"));
    let top = scene.derive(&mut a).expect("the top derives");
    Program::lower(&a, &top.accelerations.accel).ops().len()
}

fn scaling(c: &mut Criterion) {
    let mut g = c.benchmark_group("sym_expand");
    g.sample_size(10);
    for power in [6, 8, 11] {
        g.bench_with_input(
            BenchmarkId::new("five_terms_power", power),
            &power,
            |b, &p| b.iter(|| black_box(expand_power(5, p))),
        );
    }
    for terms in [3, 5, 8] {
        g.bench_with_input(BenchmarkId::new("power_6_terms", terms), &terms, |b, &t| {
            b.iter(|| black_box(expand_power(t, 6)))
        });
    }
    g.finish();
    let mut g = c.benchmark_group("sym_point_masses");
    g.sample_size(10);
    for n in [5, 20, 80] {
        g.bench_with_input(BenchmarkId::new("derive_top", n), &n, |b, &n| {
            b.iter(|| black_box(point_mass_top(n)))
        });
    }
    g.finish();
}

/// ½ ωᵀ I ω for a general (diagonal, asymmetric) I, and its derivatives ∂T/∂q̇ and d/dt.
fn kinetic_energy_and_derivatives() -> (Arena, ExprId) {
    let mut a = Arena::new();
    let seq = AngleSequence::Zxz;
    let coords = seq.coordinates(&mut a);
    let omega = seq.body_rates(&mut a, &coords);
    let inertia = [a.parameter("I_1"), a.parameter("I_2"), a.parameter("I_3")];
    let terms: Vec<ExprId> = (0..3)
        .map(|k| {
            let w2 = a.mul(omega[k], omega[k]);
            a.mul(inertia[k], w2)
        })
        .collect();
    let two_t = a.sum(&terms);
    let t = a.expand(two_t);
    let mut last = t;
    for &qd in &coords.rates {
        let s = a.as_symbol(qd).expect("rates are symbols");
        let p = a.diff(t, s);
        last = a.dt(p);
    }
    (a, last)
}

fn heavy_top(asymmetric: bool) -> (Arena, Vec<ExprId>) {
    let mut a = Arena::new();
    let i1 = a.parameter("I_1");
    let i2 = if asymmetric { a.parameter("I_2") } else { i1 };
    let i3 = a.parameter("I_3");
    let z = a.zero();
    let mut scene = TopScene::free(&mut a, [[i1, z, z], [z, i2, z], [z, z, i3]]);
    scene.mass = a.parameter("M");
    scene.gravity = Some(a.parameter("g"));
    scene.center = if asymmetric {
        [a.parameter("c_x"), a.parameter("c_y"), a.parameter("c_z")]
    } else {
        [z, z, a.parameter("l")]
    };
    let d = scene.derive(&mut a).expect("the heavy top derives");
    let accel = d.accelerations.accel.clone();
    (a, accel)
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("sym");
    g.sample_size(30);
    g.bench_function("kinetic_energy_build_and_differentiate", |b| {
        b.iter(|| black_box(kinetic_energy_and_derivatives()))
    });
    g.bench_function("derive_symmetric_heavy_top", |b| {
        b.iter(|| black_box(heavy_top(false)))
    });
    g.bench_function("derive_asymmetric_heavy_top", |b| {
        b.iter(|| black_box(heavy_top(true)))
    });
    g.bench_function("derive_and_lower_asymmetric_heavy_top", |b| {
        b.iter(|| {
            let (a, accel) = heavy_top(true);
            black_box(Program::lower(&a, &accel))
        })
    });
    g.finish();
    for (name, asym) in [("symmetric", false), ("asymmetric", true)] {
        let (a, accel) = heavy_top(asym);
        println!(
            "{name} heavy top q'': {}",
            Program::lower(&a, &accel).op_count()
        );
    }
}

criterion_group!(benches, bench, scaling);
criterion_main!(benches);
