//! The symbolic engine's speed: building and differentiating a top's kinetic energy, and
//! the whole derivation of the symmetric and the asymmetric heavy top.

use criterion::{Criterion, criterion_group, criterion_main};
use precess_core::codegen::Program;
use precess_core::rigid::AngleSequence;
use precess_core::sym::{Arena, ExprId};
use precess_core::top::TopScene;
use std::hint::black_box;

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

criterion_group!(benches, bench);
criterion_main!(benches);
