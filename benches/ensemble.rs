//! Many at once: runs per second of whole ensembles (`precess::ensemble`), on one core (a
//! rayon pool of one thread) and on all of them, at several tolerances, with each ensemble's
//! error against a closed form beside it:
//!
//! - (a) the heavy top of `examples/heavy_top.rs` (`SpinningTop`: the generated angle form
//!   and its generated Taylor recurrences) released at rest 20° from the vertical spinning at
//!   150 rad/s, to 10¼ nutation periods, run i turned by ψ0 = 2π i / N about its figure axis —
//!   a symmetry, so every run has the same exact cos θ(t) (`HeavyTopMotion::cos_theta_at`) but
//!   its own arithmetic; the error is the largest over the runs;
//! - (b) the torque-free body I = (3, 5, 9) (`FreeBody`, Taylor) from
//!   m0 = (0, 2, 0.01 (1 + i / N)) to T = 200; the error is the largest over the runs against
//!   `FreeBodyExact`.
//!
//! Beside them, the same problems in the form heyoka integrates, as equations through
//! `taylor_system!`: "top (EP)" is (a) in Euler–Poisson form, "free (eq)" is (b).
//!
//! `cargo bench -p precess-benches --bench ensemble` prints the table (best of 3 whole ensembles of
//! `PRECESS_ENSEMBLE_RUNS` runs, 1000 unless set; "loop" is the same runs in a plain loop on
//! one thread, without the ensemble) and then times the tol 1e-12 ensembles with
//! criterion. `scripts/heyoka_ensemble.py` runs heyoka's ensembles on the same problems and
//! tolerances; docs/performance.md ("Many at once") sets them side by side. Rows
//! "k×L lanes" step the same runs L at a time in batch lanes (`Ensemble::lanes`) on k
//! threads: the generated recurrences of `SpinningTop`, `EulerPoisson` and `FreeEquations`
//! on `Lanes<L>`, bit-identical to their scalar rows.
//! `PRECESS_ORDER_RULE=jorba-zou` runs every Taylor row under `OrderRule::JorbaZou`, heyoka's
//! rule, instead of the default order of least work (docs/performance.md, "The order of
//! least work").

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{Criterion, Throughput};
use precess::ensemble::Ensemble;
use precess::ensemble::rayon::{ThreadPool, ThreadPoolBuilder};
use precess::exact::FreeBodyExact;
use precess::ode::OdeError;
use precess::prelude::*;
use precess::taylor::Taylor;
use precess::taylor::batch::TaylorLanes;
use precess::top::HeavyTopTheory;
use precess_testkit::systems::{FreeBody, SpinningTop};

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

/// Run i of (a): cos θ at `t_end`.
fn heavy_top(i: usize, n: usize, t_end: f64, tol: f64) -> Result<f64, OdeError> {
    let psi0 = std::f64::consts::TAU * i as f64 / n as f64;
    let y0 = [0.0, THETA0_DEG.to_radians(), psi0, 0.0, 0.0, SPIN];
    let mut ode = Taylor::new(SpinningTop, 0.0, y0, taylor_config(tol))?;
    while ode.t() < t_end {
        ode.step(t_end)?;
    }
    Ok(ode.y()[1].cos())
}

/// Run i of (a)'s integrator at its start, for the lanes ([`Ensemble::lanes`]), which step
/// it as `heavy_top` does, to the same bits.
fn heavy_top_start(i: usize, n: usize, tol: f64) -> Result<Taylor<SpinningTop, 6>, OdeError> {
    let psi0 = std::f64::consts::TAU * i as f64 / n as f64;
    let y0 = [0.0, THETA0_DEG.to_radians(), psi0, 0.0, 0.0, SPIN];
    Taylor::new(SpinningTop, 0.0, y0, taylor_config(tol))
}

/// One row of (a) stepped `L` runs at a time in batch lanes on `threads` threads, from the
/// starts `start` (the angle form or the Euler–Poisson one), `cos_theta` reading cos θ from
/// a run's end state; `label` names the form in the table.
fn heavy_top_lanes_row<S: TaylorLanes<6, L>, const L: usize>(
    label: &str,
    start: impl Fn(usize) -> Result<Taylor<S, 6>, OdeError> + Sync,
    cos_theta: fn(&[f64; 6]) -> f64,
    (n, threads): (usize, usize),
    (t_end, cos_end, tol): (f64, f64, f64),
) {
    let (secs, results) = best_of_3(|| {
        pool(threads).install(|| {
            Ensemble::new(0..n)
                .lanes::<L>()
                .integrate(t_end, &start, |_, ode| cos_theta(ode.y()))
        })
    });
    let err = results
        .outputs()
        .map(|(_, c)| (c - cos_end).abs())
        .fold(0.0, f64::max);
    assert_eq!(results.failures(), 0);
    println!(
        "{label:<9} {tol:>7.0e} {:<10} {err:>9.2e} {:>10.0}",
        format!("{threads}×{L} lanes"),
        n as f64 / secs
    );
}

/// Run i of (a) in Euler–Poisson form at its start, for the lanes.
fn heavy_top_ep_start(i: usize, n: usize, tol: f64) -> Result<Taylor<EulerPoisson, 6>, OdeError> {
    let psi0 = std::f64::consts::TAU * i as f64 / n as f64;
    let (s, c) = THETA0_DEG.to_radians().sin_cos();
    let y0 = [0.0, 0.0, SPIN, s * psi0.sin(), s * psi0.cos(), c];
    Taylor::new(EulerPoisson, 0.0, y0, taylor_config(tol))
}

/// One row of (b) through `FreeEquations`, `L` runs at a time in lanes on `threads` threads.
fn free_equations_lanes_row<const L: usize>(n: usize, threads: usize, tol: f64) {
    let (secs, results) = best_of_3(|| {
        pool(threads).install(|| {
            Ensemble::new(0..n).lanes::<L>().integrate(
                200.0,
                |i| Taylor::new(FreeEquations, 0.0, free_m0(i, n), taylor_config(tol)),
                |_, ode| *ode.y(),
            )
        })
    });
    assert_eq!(results.failures(), 0);
    println!(
        "{:<9} {tol:>7.0e} {:<10} {:>9} {:>10.0}",
        "free (eq)",
        format!("{threads}×{L} lanes"),
        "",
        n as f64 / secs
    );
}

/// Run i of (a) in Euler–Poisson form (`EulerPoisson`): γ3 = cos θ at `t_end`.
fn heavy_top_ep(i: usize, n: usize, t_end: f64, tol: f64) -> Result<f64, OdeError> {
    let psi0 = std::f64::consts::TAU * i as f64 / n as f64;
    let (s, c) = THETA0_DEG.to_radians().sin_cos();
    let y0 = [0.0, 0.0, SPIN, s * psi0.sin(), s * psi0.cos(), c];
    let mut ode = Taylor::new(EulerPoisson, 0.0, y0, taylor_config(tol))?;
    while ode.t() < t_end {
        ode.step(t_end)?;
    }
    Ok(ode.y()[5])
}

/// Run i of (b) through the equations of `taylor_system!` (`FreeEquations`): m(200).
fn free_equations(i: usize, n: usize, tol: f64) -> Result<[f64; 3], OdeError> {
    let cfg = taylor_config(tol);
    let mut ode = Taylor::new(FreeEquations, 0.0, free_m0(i, n), cfg)?;
    while ode.t() < 200.0 {
        ode.step(200.0)?;
    }
    Ok(*ode.y())
}

/// Run i of (b)'s initial state.
fn free_m0(i: usize, n: usize) -> [f64; 3] {
    [0.0, 2.0, 0.01 * (1.0 + i as f64 / n as f64)]
}

/// Run i of (b): m(200).
fn free_body(i: usize, n: usize, tol: f64) -> Result<[f64; 3], OdeError> {
    let cfg = taylor_config(tol);
    let mut ode = Taylor::new(FreeBody(FREE_I), 0.0, free_m0(i, n), cfg)?;
    while ode.t() < 200.0 {
        ode.step(200.0)?;
    }
    Ok(*ode.y())
}

fn pool(threads: usize) -> ThreadPool {
    ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap()
}

/// The best of 3 times of `f` in seconds, and its last result.
fn best_of_3<T>(mut f: impl FnMut() -> T) -> (f64, T) {
    let mut best = f64::INFINITY;
    let mut out = f();
    for _ in 0..3 {
        let start = Instant::now();
        out = f();
        best = best.min(start.elapsed().as_secs_f64());
    }
    (best, out)
}

fn table(n: usize, cores: usize, t_end: f64, cos_end: f64) {
    let free_exact: Vec<[f64; 3]> = (0..n)
        .map(|i| {
            FreeBodyExact::new(FREE_I, free_m0(i, n))
                .unwrap()
                .m_at(200.0)
                .unwrap()
                .into()
        })
        .collect();
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!(
        "{n} runs per ensemble, {cores} cores, load {}",
        load.split_whitespace().next().unwrap_or("?")
    );
    println!("heavy top: T = 10¼ periods = {t_end:.17e}, exact cos θ(T) = {cos_end:.17e}");
    println!(
        "{:<9} {:>7} {:<10} {:>9} {:>10}",
        "problem", "tol", "threads", "error", "runs/s"
    );
    for tol in [1e-10, 1e-12, 1e-14] {
        for threads in [1, cores] {
            let (secs, results) = best_of_3(|| {
                pool(threads).install(|| Ensemble::new(0..n).run(|i| heavy_top(i, n, t_end, tol)))
            });
            let err = results
                .outputs()
                .map(|(_, c)| (c - cos_end).abs())
                .fold(0.0, f64::max);
            assert_eq!(results.failures(), 0);
            println!(
                "{:<9} {tol:>7.0e} {threads:<10} {err:>9.2e} {:>10.0}",
                "heavy top",
                n as f64 / secs
            );
        }
        // The same runs in batch lanes: 4 doubles fill an AVX2 register, 8 an AVX-512 one.
        for threads in [1, cores] {
            let angles = |i| heavy_top_start(i, n, tol);
            let at = (t_end, cos_end, tol);
            heavy_top_lanes_row::<_, 4>("heavy top", angles, |y| y[1].cos(), (n, threads), at);
            heavy_top_lanes_row::<_, 8>("heavy top", angles, |y| y[1].cos(), (n, threads), at);
        }
        // The same runs in a plain loop, without the ensemble: what the ensemble costs.
        let (secs, _) = best_of_3(|| {
            (0..n)
                .map(|i| heavy_top(i, n, t_end, tol).unwrap())
                .fold(0.0, |a, c| a + c)
        });
        println!(
            "{:<9} {tol:>7.0e} {:<10} {:>9} {:>10.0}",
            "heavy top",
            "loop",
            "",
            n as f64 / secs
        );
        let (secs, _) = best_of_3(|| {
            (0..n)
                .map(|i| free_body(i, n, tol).unwrap()[0])
                .fold(0.0, |a, c| a + c)
        });
        println!(
            "{:<9} {tol:>7.0e} {:<10} {:>9} {:>10.0}",
            "free body",
            "loop",
            "",
            n as f64 / secs
        );
        for threads in [1, cores] {
            let (secs, results) = best_of_3(|| {
                pool(threads)
                    .install(|| Ensemble::new(0..n).run(|i| heavy_top_ep(i, n, t_end, tol)))
            });
            let err = results
                .outputs()
                .map(|(_, c)| (c - cos_end).abs())
                .fold(0.0, f64::max);
            assert_eq!(results.failures(), 0);
            println!(
                "{:<9} {tol:>7.0e} {threads:<10} {err:>9.2e} {:>10.0}",
                "top (EP)",
                n as f64 / secs
            );
        }
        for threads in [1, cores] {
            let ep = |i| heavy_top_ep_start(i, n, tol);
            let at = (t_end, cos_end, tol);
            heavy_top_lanes_row::<_, 4>("top (EP)", ep, |y| y[5], (n, threads), at);
            heavy_top_lanes_row::<_, 8>("top (EP)", ep, |y| y[5], (n, threads), at);
        }
        for threads in [1, cores] {
            let (secs, results) = best_of_3(|| {
                pool(threads).install(|| Ensemble::new(0..n).run(|i| free_equations(i, n, tol)))
            });
            let run0 = results
                .get(0)
                .and_then(|r| r.as_ref().ok())
                .map(|m| m.iter().zip(free_exact[0]).map(|(a, b)| (a - b).abs()))
                .map_or(f64::NAN, |e| e.fold(0.0, f64::max));
            assert_eq!(results.failures(), 0);
            println!(
                "{:<9} {tol:>7.0e} {threads:<10} {:>9} {:>10.0}   (run 0's error {run0:.2e})",
                "free (eq)",
                "",
                n as f64 / secs
            );
        }
        for threads in [1, cores] {
            free_equations_lanes_row::<4>(n, threads, tol);
            free_equations_lanes_row::<8>(n, threads, tol);
        }
        for threads in [1, cores] {
            let (secs, results) = best_of_3(|| {
                pool(threads).install(|| Ensemble::new(0..n).run(|i| free_body(i, n, tol)))
            });
            let err = results
                .outputs()
                .flat_map(|(i, m)| m.iter().zip(free_exact[i]).map(|(a, b)| (a - b).abs()))
                .fold(0.0, f64::max);
            let run0 = results
                .get(0)
                .and_then(|r| r.as_ref().ok())
                .map(|m| m.iter().zip(free_exact[0]).map(|(a, b)| (a - b).abs()))
                .map_or(f64::NAN, |e| e.fold(0.0, f64::max));
            assert_eq!(results.failures(), 0);
            println!(
                "{:<9} {tol:>7.0e} {threads:<10} {err:>9.2e} {:>10.0}   (run 0's error {run0:.2e})",
                "free body",
                n as f64 / secs
            );
        }
    }
}

fn main() {
    let n: usize = std::env::var("PRECESS_ENSEMBLE_RUNS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1000);
    let cores = std::thread::available_parallelism().map_or(1, |c| c.get());
    let (t_end, cos_end) = heavy_top_reference();
    if std::env::var("PRECESS_ENSEMBLE_TABLE").as_deref() != Ok("0") {
        table(n, cores, t_end, cos_end);
    }
    let mut c = Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3))
        .configure_from_args();
    let mut g = c.benchmark_group("ensemble");
    g.throughput(Throughput::Elements(n as u64));
    for threads in [1, cores] {
        let p = pool(threads);
        g.bench_function(format!("heavy top tol 1e-12, {threads} threads"), |b| {
            b.iter(|| p.install(|| Ensemble::new(0..n).run(|i| heavy_top(i, n, t_end, 1e-12))))
        });
        g.bench_function(format!("free body tol 1e-12, {threads} threads"), |b| {
            b.iter(|| p.install(|| Ensemble::new(0..n).run(|i| free_body(black_box(i), n, 1e-12))))
        });
    }
    g.finish();
    c.final_summary();
}
