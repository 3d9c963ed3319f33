//! Free bodies, in one criterion run: the generated right-hand side against the same body's
//! written by hand, and a whole flight of the thrown T-handle (the `thrown_wrench` example's
//! throw) with DOP853, with and without projection, beside RKMK4 at matched error. The
//! operation count of the generated right-hand side and the work of each flight are printed
//! first.

use criterion::{Criterion, criterion_group, criterion_main};
use nalgebra::{Quaternion, UnitQuaternion, Vector3};
use precess::free::{
    FreeDynamics, FreeFlight, FreeLie, FreeScene, FreeState, FreeSystem, Projection,
};
use precess::ode::{AdaptiveConfig, Dop853Pair, FixedStepConfig, System};
use precess::prelude::*;
use precess::rigid::{RigidState, Rkmk4};
use precess_core::codegen::Program;
use precess_core::sym::Arena;
use std::hint::black_box;

/// A T-handle under gravity, with a thruster on the end of its bar and drag: the generated
/// right-hand side reads the attitude for the thrust and its torque.
#[derive(RigidBody)]
#[rigid(
    cylinder(mass = 0.3, radius = 0.01, length = 0.2, axis = x, at = [0.0, 0.0, 0.1]),
    cylinder(mass = 0.2, radius = 0.01, length = 0.2, axis = z, at = [0.0, 0.0, 0.0]),
)]
#[free(gravity = 9.81, body_force(force = [0.0, 0.5, 0.0], at = [0.1, 0.0, 0.1]), drag = 0.02)]
struct Rocket;

/// The thrown T-handle: gravity alone.
#[derive(RigidBody)]
#[rigid(
    cylinder(mass = 0.3, radius = 0.01, length = 0.2, axis = x, at = [0.0, 0.0, 0.1]),
    cylinder(mass = 0.2, radius = 0.01, length = 0.2, axis = z, at = [0.0, 0.0, 0.0]),
)]
#[free(gravity = 9.81)]
struct THandle;

/// The same rocket written by hand, as a user would with nalgebra: moments and centre of
/// mass taken from the derived body once.
struct HandWritten {
    mass: f64,
    moments: Vector3<f64>,
    lever: Vector3<f64>,
}

impl System<13> for HandWritten {
    #[inline]
    fn rhs(&self, _t: f64, y: &[f64; 13], d: &mut [f64; 13]) {
        let v = Vector3::new(y[3], y[4], y[5]);
        let q = Quaternion::new(y[6], y[7], y[8], y[9]);
        let w = Vector3::new(y[10], y[11], y[12]);
        let r = UnitQuaternion::new_normalize(q);
        let thrust = Vector3::new(0.0, 0.5, 0.0);
        let f = r * thrust + Vector3::new(0.0, 0.0, -9.81 * self.mass) - 0.02 * v;
        let tau = self.lever.cross(&thrust);
        let i = self.moments;
        let wd = Vector3::new(
            ((i.y - i.z) * w.y * w.z + tau.x) / i.x,
            ((i.z - i.x) * w.z * w.x + tau.y) / i.y,
            ((i.x - i.y) * w.x * w.y + tau.z) / i.z,
        );
        let qd = q * Quaternion::new(0.0, w.x, w.y, w.z) * 0.5;
        d[..3].copy_from_slice(v.as_slice());
        d[3..6].copy_from_slice((f / self.mass).as_slice());
        d[6..10].copy_from_slice(&[qd.w, qd.i, qd.j, qd.k]);
        d[10..].copy_from_slice(wd.as_slice());
    }
}

fn throw() -> FreeState {
    FreeState {
        position: Vector3::new(0.0, 0.0, 1.5),
        velocity: Vector3::new(0.8, 0.0, 10.0),
        attitude: UnitQuaternion::identity(),
        omega_principal: Vector3::new(50.0, 2.0, 3.0),
    }
}

fn rhs(c: &mut Criterion) {
    let hand = HandWritten {
        mass: Rocket.mass(),
        moments: Rocket.principal_cm().moments,
        lever: Vector3::new(0.1, 0.0, 0.1) - Rocket.center_of_mass(),
    };
    let y = FreeState {
        velocity: Vector3::new(1.0, 2.0, 3.0),
        attitude: UnitQuaternion::from_euler_angles(0.3, 0.2, 0.1),
        omega_principal: Vector3::new(5.0, 0.3, 0.2),
        ..FreeState::at_rest()
    }
    .to_array();
    let (mut a, mut b) = ([0.0; 13], [0.0; 13]);
    Rocket.free_rhs(0.0, &y, &mut a);
    hand.rhs(0.0, &y, &mut b);
    for k in 0..13 {
        assert!(
            (a[k] - b[k]).abs() <= 1e-12 * (1.0 + b[k].abs()),
            "component {k}"
        );
    }
    // The operation count of the same scene lowered by precess-core.
    let mut arena = Arena::new();
    let m = arena.float(Rocket.mass()).unwrap_or_else(|_| arena.one());
    let moments = Rocket.principal_cm().moments;
    let ms = [0, 1, 2].map(|k| arena.float(moments[k]).unwrap_or_else(|_| arena.one()));
    let scene = FreeScene::new(&mut arena, m, ms);
    if let Ok(d) = scene.derive(&mut arena) {
        println!(
            "torque-free rhs: {:?}",
            Program::lower(&arena, &d.rhs).op_count()
        );
    }
    let mut g = c.benchmark_group("free_rhs");
    g.bench_function("generated", |bench| {
        let mut d = [0.0; 13];
        bench.iter(|| {
            Rocket.free_rhs(0.0, black_box(&y), &mut d);
            black_box(d)
        })
    });
    g.bench_function("hand_written", |bench| {
        let mut d = [0.0; 13];
        bench.iter(|| {
            hand.rhs(0.0, black_box(&y), &mut d);
            black_box(d)
        })
    });
    g.finish();
}

fn flight(c: &mut Criterion) {
    let s0 = throw();
    let t_end = 2.0 * s0.velocity.z / 9.81;
    let exact = THandle.exact(0.0, &s0).expect("gravity alone");
    let want = exact.at(t_end).expect("finite");
    let error = |s: &FreeState| s.attitude.angle_to(&want.attitude);
    let tol = 1e-10;
    let run_at = |tol: f64, projection: Projection| {
        let cfg = AdaptiveConfig::with_tol(tol, tol);
        let mut f = FreeFlight::<_, Dop853Pair>::with_projection(
            FreeSystem(&THandle),
            0.0,
            &s0,
            cfg,
            projection,
        )
        .expect("valid start");
        f.advance_to(t_end).expect("integrates");
        (f.state().expect("finite"), f.stats())
    };
    let run = |projection: Projection| run_at(tol, projection);
    // The unprojected run at the tolerance that matches the projected one's error.
    let matched = 1e-12;
    let rkmk = |h: f64| {
        let mut m = Rkmk4::new(
            FreeLie(&THandle),
            0.0,
            RigidState::from(s0),
            FixedStepConfig::with_step(h),
        )
        .expect("valid start");
        m.advance_to(t_end).expect("integrates");
        (FreeState::from(*m.state()), m.stats())
    };
    for projection in [Projection::EveryStep, Projection::Never] {
        let (s, stats) = run(projection);
        println!(
            "DOP853 rtol {tol:e} {projection:?}: attitude error {:.1e} rad, {stats:?}",
            error(&s)
        );
    }
    for tight in [1e-11, matched] {
        let (s, stats) = run_at(tight, Projection::Never);
        println!(
            "DOP853 rtol {tight:e} Never: attitude error {:.1e} rad, {stats:?}",
            error(&s)
        );
    }
    for h in [2e-4, 1e-4] {
        let (s, stats) = rkmk(h);
        println!(
            "RKMK4 h {h:e}: attitude error {:.1e} rad, {stats:?}",
            error(&s)
        );
    }
    let mut g = c.benchmark_group("free_flight");
    g.sample_size(10);
    g.bench_function("dop853_projected", |bench| {
        bench.iter(|| black_box(run(Projection::EveryStep)))
    });
    g.bench_function("dop853_unprojected", |bench| {
        bench.iter(|| black_box(run(Projection::Never)))
    });
    g.bench_function("dop853_unprojected_matched", |bench| {
        bench.iter(|| black_box(run_at(matched, Projection::Never)))
    });
    g.bench_function("rkmk4_h1e-4", |bench| bench.iter(|| black_box(rkmk(1e-4))));
    g.finish();
}

criterion_group!(benches, rhs, flight);
criterion_main!(benches);
