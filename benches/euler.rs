//! Euler's equations three ways, on the same asymmetric body and the same 1024 states:
//! the code `#[derive(RigidBody)]` generates, the hand-written three-line formula (as written,
//! dividing by each moment, and with its coefficients folded into constants), and the generic
//! nalgebra form I⁻¹ (G − ω × I ω) with the inverse precomputed.
//!
//! Run with `cargo bench -p precess-benches --bench euler`.

use criterion::{Criterion, criterion_group, criterion_main};
use nalgebra::{Matrix3, Vector3};
use precess::prelude::*;
use std::hint::black_box;

/// A brick with three different moments about its centre of mass.
#[derive(RigidBody)]
#[rigid(box(mass = 2.0, size = [0.1, 0.2, 0.3]))]
struct Brick;

// The same moments written out: m (b² + c²)/12 and cyclic.
const I1: f64 = 2.0 * (0.04 + 0.09) / 12.0;
const I2: f64 = 2.0 * (0.01 + 0.09) / 12.0;
const I3: f64 = 2.0 * (0.01 + 0.04) / 12.0;

/// Euler's equations by hand.
#[inline]
fn hand_written(w: &Vector3<f64>, g: &Vector3<f64>) -> Vector3<f64> {
    Vector3::new(
        ((I2 - I3) * w[1] * w[2] + g[0]) / I1,
        ((I3 - I1) * w[2] * w[0] + g[1]) / I2,
        ((I1 - I2) * w[0] * w[1] + g[2]) / I3,
    )
}

/// Euler's equations by hand with the coefficients and reciprocals folded into constants
/// (what the derive emits, written out).
#[inline]
fn hand_folded(w: &Vector3<f64>, g: &Vector3<f64>) -> Vector3<f64> {
    const K: [f64; 3] = [(I2 - I3) / I1, (I3 - I1) / I2, (I1 - I2) / I3];
    const D: [f64; 3] = [1.0 / I1, 1.0 / I2, 1.0 / I3];
    Vector3::new(
        K[0] * w[1] * w[2] + D[0] * g[0],
        K[1] * w[2] * w[0] + D[1] * g[1],
        K[2] * w[0] * w[1] + D[2] * g[2],
    )
}

/// The generic form, I⁻¹ (G − ω × I ω).
#[inline]
fn generic(
    i: &Matrix3<f64>,
    inv: &Matrix3<f64>,
    w: &Vector3<f64>,
    g: &Vector3<f64>,
) -> Vector3<f64> {
    inv * (g - w.cross(&(i * w)))
}

fn states() -> Vec<(Vector3<f64>, Vector3<f64>)> {
    let mut s = 0x2545_F491_4F6C_DD1Du64;
    let mut next = move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    (0..1024)
        .map(|_| {
            (
                Vector3::new(next(), next(), next()) * 10.0,
                Vector3::new(next(), next(), next()),
            )
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let body = Brick;
    let xs = states();
    let i = Matrix3::from_diagonal(&Vector3::new(I1, I2, I3));
    let inv = i.try_inverse().expect("invertible");
    // The three agree before they race.
    for (w, g) in &xs {
        let (a, b, d) = (
            body.euler_rhs_principal(w, g),
            hand_written(w, g),
            generic(&i, &inv, w, g),
        );
        assert!(
            (a - b).norm() <= 1e-12 * b.norm().max(1.0)
                && (d - b).norm() <= 1e-12 * b.norm().max(1.0)
        );
    }
    let mut group = c.benchmark_group("euler_rhs_1024_states");
    group.bench_function("generated", |bch| {
        bch.iter(|| {
            let body = black_box(&body);
            let mut acc = Vector3::zeros();
            for (w, g) in black_box(&xs) {
                acc += body.euler_rhs_principal(w, g);
            }
            acc
        })
    });
    group.bench_function("hand_written", |bch| {
        bch.iter(|| {
            let mut acc = Vector3::zeros();
            for (w, g) in black_box(&xs) {
                acc += hand_written(w, g);
            }
            acc
        })
    });
    group.bench_function("hand_written_folded", |bch| {
        bch.iter(|| {
            let mut acc = Vector3::zeros();
            for (w, g) in black_box(&xs) {
                acc += hand_folded(w, g);
            }
            acc
        })
    });
    group.bench_function("nalgebra_generic", |bch| {
        bch.iter(|| {
            let (i, inv) = (black_box(&i), black_box(&inv));
            let mut acc = Vector3::zeros();
            for (w, g) in black_box(&xs) {
                acc += generic(i, inv, w, g);
            }
            acc
        })
    });
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().warm_up_time(std::time::Duration::from_secs(1)).measurement_time(std::time::Duration::from_secs(3)).sample_size(50);
    targets = bench
}
criterion_main!(benches);
