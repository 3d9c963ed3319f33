//! The Whipple bicycle's derivation, what `#[derive(Mechanism)]` runs while it expands
//! examples/mechanisms/bicycle.rs: `MechanismScene::derive_rolling` (Kane's M and f of the
//! seven-body tree, the five rolling rows A, Ȧq̇, the heights and tilts, all exactly), and
//! the same followed by `RollingModel::new` (the lowering to straight-line programs). SymPy's
//! `KanesMethod` on the same bicycle is `scripts/sympy_bicycle.py`; docs/performance.md
//! compares the two. The operation counts of the lowered programs are printed first;
//! `PRECESS_BICYCLE_ONCE=1` runs one derivation alone (for `valgrind --tool=callgrind`).

use criterion::{Criterion, criterion_group, criterion_main};
use precess::mechanism::rolling::RollingModel;
use precess::sym::Arena;
use std::hint::black_box;

use precess_testkit::bicycle::mechanism_scene;

/// The paper's Table 1, named as the scene's parameters.
const BENCHMARK: [(&str, f64); 26] = [
    ("w", 1.02),
    ("c", 0.08),
    ("lambda", std::f64::consts::PI / 10.0),
    ("g", 9.81),
    ("r_r", 0.3),
    ("m_r", 2.0),
    ("i_rxx", 0.0603),
    ("i_ryy", 0.12),
    ("x_b", 0.3),
    ("z_b", -0.9),
    ("m_b", 85.0),
    ("i_bxx", 9.2),
    ("i_byy", 11.0),
    ("i_bzz", 2.8),
    ("i_bxz", 2.4),
    ("x_h", 0.9),
    ("z_h", -0.7),
    ("m_h", 4.0),
    ("i_hxx", 0.05892),
    ("i_hyy", 0.06),
    ("i_hzz", 0.00708),
    ("i_hxz", -0.00756),
    ("r_f", 0.35),
    ("m_f", 3.0),
    ("i_fxx", 0.1405),
    ("i_fyy", 0.28),
];

const NAMES: [&str; 8] = [
    "x", "y", "psi", "phi", "theta", "theta_r", "delta", "theta_f",
];

fn lowered() -> RollingModel<8, 5, 3> {
    let mut a = Arena::new();
    let (scene, rolling) = mechanism_scene(&mut a);
    let d = scene
        .derive_rolling(&mut a, &rolling)
        .expect("the bicycle derives");
    RollingModel::new(&mut a, &d, NAMES, &BENCHMARK).expect("the bicycle lowers")
}

fn bicycle(c: &mut Criterion) {
    // PRECESS_BICYCLE_ONCE=1 runs one derivation (the scene built, derived and dropped) and
    // nothing else, for callgrind's instruction counts.
    if std::env::var("PRECESS_BICYCLE_ONCE").as_deref() == Ok("1") {
        let mut a = Arena::new();
        let (scene, rolling) = mechanism_scene(&mut a);
        let d = scene
            .derive_rolling(&mut a, &rolling)
            .expect("the bicycle derives");
        println!("bicycle derived: {} rows", d.rows());
        return;
    }
    println!("bicycle lowered: {:?}", lowered().op_counts());
    let mut group = c.benchmark_group("bicycle_derive");
    group.sample_size(20);
    group.bench_function("derive_rolling", |b| {
        b.iter(|| {
            let mut a = Arena::new();
            let (scene, rolling) = mechanism_scene(&mut a);
            black_box(
                scene
                    .derive_rolling(&mut a, &rolling)
                    .expect("the bicycle derives"),
            )
        })
    });
    group.bench_function("derive_and_lower", |b| b.iter(|| black_box(lowered())));
    group.finish();
}

criterion_group!(benches, bicycle);
criterion_main!(benches);
