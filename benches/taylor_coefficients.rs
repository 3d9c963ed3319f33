//! The price of one coefficient evaluation at order 20: the recurrences `taylor = 20`
//! generates for B5 (3 components, at orders 13 and 20), a heavy top (6), a general top (full inertia tensor, centre off
//! the axis), a free body (13) and a three-link chain on universal joints (12), the first
//! and the free body against the same recurrences interpreted from a tape built at run time
//! ([`TaylorTape`]).
//!
//! Run with `cargo bench -p precess-benches --bench taylor_coefficients -- --warm-up-time 1 --measurement-time 3`.

use criterion::{Criterion, criterion_group, criterion_main};
use precess::prelude::*;
use precess::sym::Arena;
use precess::taylor::{TaylorSystem, TaylorTape};
use precess_testkit::systems::{SpinningTop, interpreted_top};
use std::hint::black_box;

/// A torque-free body with moments (3, 5, 7), as a free body under gravity.
#[derive(RigidBody)]
#[rigid(body(mass = 1.0, center = [0.0, 0.0, 0.0], inertia = [[3.0, 0.0, 0.0], [0.0, 5.0, 0.0], [0.0, 0.0, 7.0]]))]
#[free(gravity = 9.81, taylor = 20)]
struct Body357;

/// A general top: full inertia tensor, the centre of mass off the symmetry axis.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.3, center = [0.04, -0.03, 0.25],
         inertia = [[0.9, 0.05, -0.02], [0.05, 0.7, 0.03], [-0.02, 0.03, 0.4]]),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81, taylor = 20)]
struct GeneralTop;

/// Three rods on universal joints (the first links of `examples/mechanisms/chain.rs`).
#[derive(Mechanism)]
#[mechanism(gravity = 9.81, taylor = 20)]
#[body(link1, parent = ground, joint = universal(axes = [x, y]), q = [a1, b1],
       parts(rod(mass = 1.0, length = 0.5, at = [0.0, 0.0, -0.25])))]
#[body(link2, parent = link1, joint = universal(axes = [x, y], at = [0.0, 0.0, -0.5]),
       q = [a2, b2], parts(rod(mass = 1.0, length = 0.5, at = [0.0, 0.0, -0.25])))]
#[body(link3, parent = link2, joint = universal(axes = [x, y], at = [0.0, 0.0, -0.5]),
       q = [a3, b3], parts(rod(mass = 1.0, length = 0.5, at = [0.0, 0.0, -0.25])))]
struct Chain3;

precess::taylor_system! {
    /// DETEST B5, as equations.
    struct B5;
    state [y1, y2, y3];
    taylor = 20;
    d/dt y1 = y2 * y3;
    d/dt y2 = -y1 * y3;
    d/dt y3 = -0.51 * y1 * y2;
}

const ORDER: usize = 20;

fn interpreted_free() -> TaylorTape<13> {
    use precess::free::FreeScene;
    let mut a = Arena::new();
    let num = |a: &mut Arena, x: f64| a.float(x).unwrap();
    let mass = num(&mut a, 1.0);
    let moments = [3.0, 5.0, 7.0].map(|x| num(&mut a, x));
    let mut scene = FreeScene::new(&mut a, mass, moments);
    let (z, g) = (a.zero(), num(&mut a, -9.81));
    scene.gravity = Some([z, z, g]);
    let d = scene.derive(&mut a).unwrap();
    TaylorTape::new(&a, d.state, d.rhs, None, &[], ORDER).unwrap()
}

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("taylor_coefficients");
    let y6 = [0.3, 0.5, -0.2, 0.8, -0.4, 150.0];
    let mut c6 = [[0.0; 6]; ORDER + 1];
    // Each system keeps its workspace across calls, as the integrator does.
    let mut ws = Default::default();
    group.bench_function("top/generated", |b| {
        b.iter(|| SpinningTop.coefficients_into(&mut ws, 0.0, black_box(&y6), ORDER, &mut c6))
    });
    let top = interpreted_top(&SpinningTop, 9.81, ORDER);
    let mut ws = Default::default();
    group.bench_function("top/interpreted", |b| {
        b.iter(|| top.coefficients_into(&mut ws, 0.0, black_box(&y6), ORDER, &mut c6))
    });
    group.bench_function("top/rhs", |b| {
        b.iter(|| SpinningTop.accelerations_unchecked_in(AngleSequence::Zxz, 0.0, black_box(&y6)))
    });
    let y3 = [0.3, 0.9, 0.95];
    let mut c3 = [[0.0; 3]; ORDER + 1];
    let mut ws = Default::default();
    for order in [13, ORDER] {
        group.bench_function(format!("B5/generated order {order}"), |b| {
            b.iter(|| B5.coefficients_into(&mut ws, 0.0, black_box(&y3), order, &mut c3))
        });
    }
    let mut ws = Default::default();
    group.bench_function("general top/generated", |b| {
        b.iter(|| GeneralTop.coefficients_into(&mut ws, 0.0, black_box(&y6), ORDER, &mut c6))
    });
    let y12 = [
        0.3, -0.2, 0.1, 0.25, -0.15, 0.05, 0.4, -0.3, 0.2, 0.1, -0.5, 0.3,
    ];
    let mut c12 = [[0.0; 12]; ORDER + 1];
    let mut ws = Default::default();
    group.bench_function("chain3/generated", |b| {
        b.iter(|| Chain3.coefficients_into(&mut ws, 0.0, black_box(&y12), ORDER, &mut c12))
    });
    let y13 = [
        0.0, 0.0, 1.0, 0.5, 0.0, 4.0, 0.9, 0.1, -0.3, 0.2, 0.0, 2.0, 0.01,
    ];
    let norm = (y13[6..10].iter().map(|v| v * v).sum::<f64>()).sqrt();
    let mut y13 = y13;
    y13[6..10].iter_mut().for_each(|v| *v /= norm);
    let mut c13 = [[0.0; 13]; ORDER + 1];
    let mut ws = Default::default();
    group.bench_function("free/generated", |b| {
        b.iter(|| Body357.coefficients_into(&mut ws, 0.0, black_box(&y13), ORDER, &mut c13))
    });
    let free = interpreted_free();
    let mut ws = Default::default();
    group.bench_function("free/interpreted", |b| {
        b.iter(|| free.coefficients_into(&mut ws, 0.0, black_box(&y13), ORDER, &mut c13))
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
