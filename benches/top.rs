//! Tops, in one criterion run: the derivation of the asymmetric heavy top in precess-core,
//! and the generated q̈ against a hand-written closed form (symmetric heavy top) and against
//! the numeric approach that assembles M(q) and f(q, q̇) and solves with nalgebra's LU.
//! The operation count of each generated q̈ is printed first.

use criterion::{Criterion, criterion_group, criterion_main};
use nalgebra::{Matrix3, Vector3};
use precess::prelude::*;
use precess_core::codegen::Program;
use precess_core::sym::Arena;
use precess_core::top::TopScene;
use std::hint::black_box;

/// I1 = 1, I3 = 1/2 about the pivot, M g l = 1.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 1.0)]
struct Symmetric;

/// The symmetric top with its moments and M g l as run-time fields.
#[derive(RigidBody)]
#[rigid(
    body(mass = m, at = [0.0, 0.0, l], inertia = diag(i1, i1, i3), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 1.0)]
struct SymmetricFields {
    m: f64,
    l: f64,
    i1: f64,
    i3: f64,
}

/// I = diag(0.9, 0.7, 0.4) about the pivot, centre of mass off the axis.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.3, at = [0.04, -0.03, 0.25], inertia = diag(0.9, 0.7, 0.4), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81)]
struct Asymmetric;

const I1: f64 = 1.0;
const I3: f64 = 0.5;
const MGL: f64 = 1.0;

/// The textbook closed form of the symmetric heavy top, ZXZ.
#[inline]
fn hand_written(q: &[f64; 3], qd: &[f64; 3]) -> [f64; 3] {
    let (s, c) = q[1].sin_cos();
    let (dphi, dth, dpsi) = (qd[0], qd[1], qd[2]);
    let w3 = dpsi + dphi * c;
    let th = (I1 * dphi * dphi * c - I3 * w3 * dphi + MGL) * s / I1;
    let phi = dth * (I3 * w3 - 2.0 * I1 * dphi * c) / (I1 * s);
    let psi = dphi * dth * s - phi * c;
    [phi, th, psi]
}

/// M(q) and f(q, q̇) written out for the symmetric top, solved with LU.
#[inline]
fn lu_symmetric(q: &[f64; 3], qd: &[f64; 3]) -> [f64; 3] {
    let (s, c) = q[1].sin_cos();
    let (dphi, dth, dpsi) = (qd[0], qd[1], qd[2]);
    let m = Matrix3::new(
        I1 * s * s + I3 * c * c,
        0.0,
        I3 * c,
        0.0,
        I1,
        0.0,
        I3 * c,
        0.0,
        I3,
    );
    let f = Vector3::new(
        -(2.0 * (I1 - I3) * s * c * dphi - I3 * s * dpsi) * dth,
        (I1 - I3) * s * c * dphi * dphi - I3 * s * dphi * dpsi + MGL * s,
        I3 * dphi * s * dth,
    );
    let x = m.lu().solve(&f).unwrap_or_else(Vector3::zeros);
    [x[0], x[1], x[2]]
}

/// The generic numeric approach for any top in ZXZ: ω = B q̇, M = Bᵀ I B,
/// f = Bᵀ (G − ω × I ω − I Ḃ q̇), solved with LU.
struct Numeric {
    inertia: Matrix3<f64>,
    weight_lever: Vector3<f64>,
}

impl Numeric {
    #[inline]
    fn accel(&self, q: &[f64; 3], qd: &[f64; 3]) -> [f64; 3] {
        let (st, ct) = q[1].sin_cos();
        let (sp, cp) = q[2].sin_cos();
        let (dphi, dth, dpsi) = (qd[0], qd[1], qd[2]);
        let b = Matrix3::new(st * sp, cp, 0.0, st * cp, -sp, 0.0, ct, 0.0, 1.0);
        let bdot_qd = Vector3::new(
            dphi * (ct * dth * sp + st * cp * dpsi) - dth * sp * dpsi,
            dphi * (ct * dth * cp - st * sp * dpsi) - dth * cp * dpsi,
            -dphi * st * dth,
        );
        let w = b * Vector3::new(dphi, dth, dpsi);
        let down = Vector3::new(-st * sp, -st * cp, -ct);
        let g = self.weight_lever.cross(&down);
        let iw = self.inertia * w;
        let m = b.transpose() * self.inertia * b;
        let f = b.transpose() * (g - w.cross(&iw) - self.inertia * bdot_qd);
        let x = m.lu().solve(&f).unwrap_or_else(Vector3::zeros);
        [x[0], x[1], x[2]]
    }
}

fn derive_asymmetric() -> usize {
    let mut a = Arena::new();
    let (i1, i2, i3) = (a.parameter("I_1"), a.parameter("I_2"), a.parameter("I_3"));
    let z = a.zero();
    let mut scene = TopScene::free(&mut a, [[i1, z, z], [z, i2, z], [z, z, i3]]);
    scene.mass = a.parameter("M");
    scene.gravity = Some(a.parameter("g"));
    scene.center = [a.parameter("c_x"), a.parameter("c_y"), a.parameter("c_z")];
    let d = scene.derive(&mut a).expect("derives");
    Program::lower(&a, &d.accelerations.accel).ops().len()
}

fn op_counts() {
    for (name, asym) in [("symmetric", false), ("asymmetric, centre off axis", true)] {
        let mut a = Arena::new();
        let one = a.one();
        let half = a.number("0.5").unwrap_or(one);
        let z = a.zero();
        let (inertia, center, g) = if asym {
            let n = |a: &mut Arena, s: &str| a.number(s).unwrap_or(one);
            let (x, y, w) = (n(&mut a, "0.9"), n(&mut a, "0.7"), n(&mut a, "0.4"));
            let c = [n(&mut a, "0.04"), n(&mut a, "-0.03"), n(&mut a, "0.25")];
            ([[x, z, z], [z, y, z], [z, z, w]], c, n(&mut a, "9.81"))
        } else {
            ([[one, z, z], [z, one, z], [z, z, half]], [z, z, one], one)
        };
        let mut scene = TopScene::free(&mut a, inertia);
        scene.center = center;
        scene.gravity = Some(g);
        if asym {
            scene.mass = a.number("1.3").unwrap_or(one);
        }
        let d = scene.derive(&mut a).expect("derives");
        println!(
            "generated q'' ({name}, literal values): {}",
            Program::lower(&a, &d.accelerations.accel).op_count()
        );
    }
}

fn bench(c: &mut Criterion) {
    op_counts();
    let (q, qd) = ([0.3, 1.1, -0.4], [0.5, -0.7, 6.0]);
    let sym = Symmetric;
    let fields = SymmetricFields {
        m: 1.0,
        l: 1.0,
        i1: 1.0,
        i3: 0.5,
    };
    let asym = Asymmetric;
    let numeric_sym = Numeric {
        inertia: Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 0.5)),
        weight_lever: Vector3::new(0.0, 0.0, 1.0),
    };
    let numeric_asym = Numeric {
        inertia: Matrix3::from_diagonal(&Vector3::new(0.9, 0.7, 0.4)),
        weight_lever: Vector3::new(0.04, -0.03, 0.25) * (1.3 * 9.81),
    };
    // All five agree before anything is timed.
    let reference = hand_written(&q, &qd);
    for other in [
        sym.accelerations_unchecked(0.0, &q, &qd),
        fields.accelerations_unchecked(0.0, &q, &qd),
        lu_symmetric(&q, &qd),
        numeric_sym.accel(&q, &qd),
    ] {
        for k in 0..3 {
            assert!((other[k] - reference[k]).abs() < 1e-12 * (1.0 + reference[k].abs()));
        }
    }
    let (ga, na) = (
        asym.accelerations_unchecked(0.0, &q, &qd),
        numeric_asym.accel(&q, &qd),
    );
    for k in 0..3 {
        assert!((ga[k] - na[k]).abs() < 1e-12 * (1.0 + na[k].abs()));
    }

    let mut g = c.benchmark_group("top");
    g.sample_size(50);
    g.measurement_time(std::time::Duration::from_secs(2));
    g.bench_function("derive_asymmetric_heavy_top", |b| {
        b.iter(|| black_box(derive_asymmetric()))
    });
    g.bench_function("symmetric/generated_literals", |b| {
        b.iter(|| sym.accelerations_unchecked(0.0, black_box(&q), black_box(&qd)))
    });
    g.bench_function("symmetric/generated_fields", |b| {
        b.iter(|| black_box(&fields).accelerations_unchecked(0.0, black_box(&q), black_box(&qd)))
    });
    g.bench_function("symmetric/hand_written", |b| {
        b.iter(|| hand_written(black_box(&q), black_box(&qd)))
    });
    g.bench_function("symmetric/lu_written_out", |b| {
        b.iter(|| lu_symmetric(black_box(&q), black_box(&qd)))
    });
    g.bench_function("symmetric/lu_generic", |b| {
        b.iter(|| numeric_sym.accel(black_box(&q), black_box(&qd)))
    });
    g.bench_function("asymmetric/generated_literals", |b| {
        b.iter(|| asym.accelerations_unchecked(0.0, black_box(&q), black_box(&qd)))
    });
    g.bench_function("asymmetric/lu_generic", |b| {
        b.iter(|| numeric_asym.accel(black_box(&q), black_box(&qd)))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
