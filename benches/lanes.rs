//! Batch lanes against scalar runs, on one core: trajectories per second of (a) the heavy top
//! in Euler–Poisson form over 10¼ nutation periods and (b) the torque-free body (3, 5, 9) to
//! T = 200, at the same tolerance, each with its error against the closed form (the lanes
//! end on the scalar runs' bits, so the errors are the same by construction; the table
//! checks it).
//!
//! `cargo bench -p precess-benches --bench lanes` prints the table (best of 3 passes over
//! `PRECESS_LANES_RUNS` runs, 1024 unless set, timed by the thread's own processor time;
//! `PRECESS_LANES_TABLE=0` skips it) and then times the tol 1e-12 passes with criterion.
//! `PRECESS_ORDER_RULE=jorba-zou` runs every Taylor row under `OrderRule::JorbaZou`, heyoka's
//! rule, instead of the default order of least work (docs/performance.md, "The order of
//! least work").
//! Built as is, the lanes run the AVX-512, AVX2 or baseline copy of the batch's loop that
//! the processor has (`pulp::Arch::dispatch`, docs/lanes.md); the scalar runs are compiled
//! for the target (SSE2 by default). docs/lanes.md has the numbers and the disassembly (the
//! lanes' loop is in `pulp::x86::v4::V4::vectorize::imp…` in the bench binary).

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{Criterion, Throughput};
use precess::exact::FreeBodyExact;
use precess::prelude::*;
use precess::taylor::batch::{BatchTaylor, TaylorLanes};
use precess::taylor::{Taylor, TaylorConfig, TaylorSystem};
use precess::top::HeavyTopTheory;
use precess_testkit::systems::SpinningTop;

#[path = "common/peer_problems.rs"]
mod peer_problems;
#[path = "common/tolerance.rs"]
mod tolerance;
use peer_problems::{EulerPoisson, FreeEquations};
use tolerance::taylor_config;

const FREE_I: [f64; 3] = [3.0, 5.0, 9.0];
const THETA0_DEG: f64 = 20.0;
const SPIN: f64 = 150.0;

/// The heavy top's span, 10¼ exact nutation periods, and its exact cos θ there.
fn heavy_top_reference() -> (f64, f64) {
    let top = SpinningTop;
    let moments = top.principal().moments;
    let mgl = top.mass() * 9.81 * top.center_of_mass().z;
    let theory = HeavyTopTheory::new(moments[0], moments[2], mgl).unwrap();
    let motion = theory
        .motion_from_angles(&[0.0, THETA0_DEG.to_radians(), 0.0], &[0.0, 0.0, SPIN])
        .unwrap();
    let t_end = 10.25 * motion.nutation_period();
    (t_end, motion.cos_theta_at(t_end).unwrap())
}

/// Run i of n of the heavy top: the start rotated by ψ₀ = 2πi/n about the vertical.
fn top_y0(i: usize, n: usize) -> [f64; 6] {
    let psi0 = std::f64::consts::TAU * i as f64 / n as f64;
    let (s, c) = THETA0_DEG.to_radians().sin_cos();
    [0.0, 0.0, SPIN, s * psi0.sin(), s * psi0.cos(), c]
}

/// Run i of n of the free body.
fn free_y0(i: usize, n: usize) -> [f64; 3] {
    [0.0, 2.0, 0.01 * (1.0 + i as f64 / n as f64)]
}

/// The end states of n scalar runs.
fn scalar_pass<S: TaylorSystem<N> + Copy, const N: usize>(
    sys: S,
    y0: impl Fn(usize) -> [f64; N],
    n: usize,
    t_end: f64,
    tol: f64,
) -> Vec<[f64; N]> {
    scalar_pass_with(sys, y0, n, t_end, taylor_config(tol))
}

/// The scalar runs without the defect check (`TaylorConfig::defect_check`), Jorba and Zou's
/// rule alone, as heyoka runs it: its rate beside the checked one is the check's price, and
/// its bits are the checked runs' when no step was taken again.
fn unchecked_pass<S: TaylorSystem<N> + Copy, const N: usize>(
    sys: S,
    y0: impl Fn(usize) -> [f64; N],
    n: usize,
    t_end: f64,
    tol: f64,
) -> Vec<[f64; N]> {
    let cfg = TaylorConfig {
        defect_check: false,
        ..taylor_config(tol)
    };
    scalar_pass_with(sys, y0, n, t_end, cfg)
}

fn scalar_pass_with<S: TaylorSystem<N> + Copy, const N: usize>(
    sys: S,
    y0: impl Fn(usize) -> [f64; N],
    n: usize,
    t_end: f64,
    cfg: TaylorConfig,
) -> Vec<[f64; N]> {
    (0..n)
        .map(|i| {
            let mut ode = Taylor::new(sys, 0.0, y0(i), cfg).unwrap();
            ode.advance_to(t_end).unwrap();
            *ode.y()
        })
        .collect()
}

/// The same n runs in batches of L lanes (n a multiple of L).
fn lane_pass<S: TaylorLanes<N, L> + Copy, const N: usize, const L: usize>(
    sys: S,
    y0: impl Fn(usize) -> [f64; N],
    n: usize,
    t_end: f64,
    tol: f64,
) -> Vec<[f64; N]> {
    let cfg = taylor_config(tol);
    let mut out = Vec::with_capacity(n);
    for start in (0..n).step_by(L) {
        let starts = core::array::from_fn(|l| y0(start + l));
        let mut batch = BatchTaylor::new([sys; L], [0.0; L], starts, cfg);
        for end in batch.advance_to([t_end; L]) {
            out.push(end.unwrap().y);
        }
    }
    out
}

/// The time this thread has run on a processor, in seconds (the first field of Linux's
/// `/proc/thread-self/schedstat`, in nanoseconds), or the wall clock's where that file is
/// missing. On a machine shared with other builds the wall time counts the waits for a core
/// as well; the thread's own time does not, so the ratios of one table stay comparable.
fn thread_seconds(wall: Instant) -> f64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<u64>().ok())
        .map_or_else(|| wall.elapsed().as_secs_f64(), |ns| ns as f64 * 1e-9)
}

/// The best of 3 times of `f` in seconds (the thread's own time, [`thread_seconds`]), and
/// its last result.
fn best_of_3<T>(mut f: impl FnMut() -> T) -> (f64, T) {
    let mut best = f64::INFINITY;
    let mut out = f();
    let wall = Instant::now();
    for _ in 0..3 {
        let start = thread_seconds(wall);
        out = f();
        best = best.min(thread_seconds(wall) - start);
    }
    (best, out)
}

fn row<const N: usize>(
    name: &str,
    tol: f64,
    mode: &str,
    n: usize,
    (secs, ends): (f64, Vec<[f64; N]>),
    error: impl Fn(usize, &[f64; N]) -> f64,
    scalar: &[[f64; N]],
) {
    let err = ends
        .iter()
        .enumerate()
        .map(|(i, y)| error(i, y))
        .fold(0.0, f64::max);
    let same = ends
        .iter()
        .zip(scalar)
        .all(|(a, b)| a.map(f64::to_bits) == b.map(f64::to_bits));
    println!(
        "{name:<10} {tol:>7.0e} {mode:<8} {err:>9.2e} {:>10.0}   {}",
        n as f64 / secs,
        if same { "= scalar bits" } else { "DIFFERS" }
    );
}

fn table(n: usize, t_end: f64, cos_end: f64) {
    let free_exact: Vec<[f64; 3]> = (0..n)
        .map(|i| {
            let m = FreeBodyExact::new(FREE_I, free_y0(i, n)).unwrap();
            m.m_at(200.0).unwrap().into()
        })
        .collect();
    let free_err = |i: usize, y: &[f64; 3]| {
        (0..3)
            .map(|k| (y[k] - free_exact[i][k]).abs())
            .fold(0.0, f64::max)
    };
    let top_err = |_: usize, y: &[f64; 6]| (y[5] - cos_end).abs();
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!(
        "{n} runs per pass, one thread (its own time), load {}",
        load.split_whitespace().next().unwrap_or("?")
    );
    println!(
        "{:<10} {:>7} {:<8} {:>9} {:>10}",
        "problem", "tol", "mode", "error", "runs/s"
    );
    let top0 = |i| top_y0(i, n);
    let free0 = |i| free_y0(i, n);
    for tol in [1e-10, 1e-12, 1e-14] {
        let s = best_of_3(|| scalar_pass(EulerPoisson, top0, n, t_end, tol));
        let reference = s.1.clone();
        row("heavy top", tol, "scalar", n, s, top_err, &reference);
        let u = best_of_3(|| unchecked_pass(EulerPoisson, top0, n, t_end, tol));
        row("heavy top", tol, "no check", n, u, top_err, &reference);
        let l4 = best_of_3(|| lane_pass::<_, 6, 4>(EulerPoisson, top0, n, t_end, tol));
        row("heavy top", tol, "lanes 4", n, l4, top_err, &reference);
        let l8 = best_of_3(|| lane_pass::<_, 6, 8>(EulerPoisson, top0, n, t_end, tol));
        row("heavy top", tol, "lanes 8", n, l8, top_err, &reference);
        let s = best_of_3(|| scalar_pass(FreeEquations, free0, n, 200.0, tol));
        let reference = s.1.clone();
        row("free body", tol, "scalar", n, s, free_err, &reference);
        let u = best_of_3(|| unchecked_pass(FreeEquations, free0, n, 200.0, tol));
        row("free body", tol, "no check", n, u, free_err, &reference);
        let l4 = best_of_3(|| lane_pass::<_, 3, 4>(FreeEquations, free0, n, 200.0, tol));
        row("free body", tol, "lanes 4", n, l4, free_err, &reference);
        let l8 = best_of_3(|| lane_pass::<_, 3, 8>(FreeEquations, free0, n, 200.0, tol));
        row("free body", tol, "lanes 8", n, l8, free_err, &reference);
    }
}

fn main() {
    let n: usize = std::env::var("PRECESS_LANES_RUNS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1024usize)
        .next_multiple_of(8);
    let (t_end, cos_end) = heavy_top_reference();
    if std::env::var("PRECESS_LANES_TABLE").as_deref() != Ok("0") {
        table(n, t_end, cos_end);
    }
    let mut c = Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3))
        .configure_from_args();
    let runs = 64;
    let mut g = c.benchmark_group("lanes");
    g.throughput(Throughput::Elements(runs as u64));
    let top0 = |i| top_y0(i, runs);
    let free0 = |i| free_y0(i, runs);
    g.bench_function("heavy top scalar", |b| {
        b.iter(|| black_box(scalar_pass(EulerPoisson, top0, runs, t_end, 1e-12)))
    });
    g.bench_function("heavy top lanes 4", |b| {
        b.iter(|| black_box(lane_pass::<_, 6, 4>(EulerPoisson, top0, runs, t_end, 1e-12)))
    });
    g.bench_function("heavy top lanes 8", |b| {
        b.iter(|| black_box(lane_pass::<_, 6, 8>(EulerPoisson, top0, runs, t_end, 1e-12)))
    });
    g.bench_function("free body scalar", |b| {
        b.iter(|| black_box(scalar_pass(FreeEquations, free0, runs, 200.0, 1e-12)))
    });
    g.bench_function("free body lanes 4", |b| {
        b.iter(|| {
            black_box(lane_pass::<_, 3, 4>(
                FreeEquations,
                free0,
                runs,
                200.0,
                1e-12,
            ))
        })
    });
    g.bench_function("free body lanes 8", |b| {
        b.iter(|| {
            black_box(lane_pass::<_, 3, 8>(
                FreeEquations,
                free0,
                runs,
                200.0,
                1e-12,
            ))
        })
    });
    g.finish();
    c.final_summary();
}
