//! Which tippe tops turn over, and how fast: an ensemble of tops over a grid of viscous
//! friction × initial spin, run over every core by `Ensemble::integrate`, against the
//! inversion threshold of `contact::theory::TippeTop`.
//!
//! ```sh
//! cargo run --release --example tippe_sweep                 # 100 × 100 = 10⁴ tops (under a minute on 2 cores)
//! cargo run --release --example tippe_sweep -- --grid 40x30 # 40 frictions × 30 spins
//! cargo run --release --example tippe_sweep -- --out DIR    # the figure to DIR
//! ```
//!
//! Every run is the top of `tippe_top` (`common/tippe.rs`: R = 2 cm, α = 0.3,
//! I₁/I₃ = 0.875) started 0.1 rad off upright, its friction coefficient c and spin n taken
//! from the grid, as a `ContactRun` in the one run loop. A thin wrapper stepper watches
//! cos θ = γ₃ of the symmetry axis after each step: the first step that ends with the axis
//! below the horizontal has the crossing located on the step's dense output (bisection to
//! adjacent doubles), and the wrapper halts there, so `Ensemble::integrate` stops that run
//! (as it stops a run whose contact halted: a lift-off, say). The inversion time is that
//! crossing.
//!
//! Theory (`TippeTop`): the top inverts only inside 1 − α < I₁/I₃ < 1 + α (met here), and only
//! if the inverted state, which Jellett's λ fixes, has less energy than the start: from
//! upright, n > n_min = (1 + α)√(M g R / I₃); from the tilted start, the same condition
//! E(start) > E′(λ) solved for n (both sides are quadratic in n). That is necessary, and the
//! table sets each friction row's least inverting spin against it. Rauch-Wojciechowski &
//! Rutstam (2014) give a threshold on λ above which the inclination's effective potential has
//! a single minimum that moves from θ ≈ 0 to θ ≈ π, λ_thres = √(M g R³ I₃ α)(1 + α)² /
//! √(1 + α − I₁/I₃), proved for 1 − α² < I₁/I₃ < 1 (this top's 0.875 is just outside); as a
//! spin it lies well above the measured threshold, so here it is sufficient, not sharp.
//! λ itself is conserved by any contact force on a sphere: its largest drift over every run
//! is the integration's error.

mod common;
#[path = "common/tippe.rs"]
mod tippe;

use std::error::Error;
use std::path::PathBuf;
use std::time::Instant;

use common::Table;
use precess::contact::{
    ContactDynamics, ContactError, ContactMode, ContactOutcome, ContactRun, Phase, STATE_LEN,
};
use precess::ensemble::{Ensemble, EnsembleProgress, rayon};
use precess::ode::{AdaptiveConfig, HybridState, OdeError, Stats, Stepper};
use precess::plot::{self, ColourBar, Map, MapAxis};
use tippe::{Top, axis_up};

/// The friction coefficients c [kg/s], evenly spaced (the tippe_top example's 0.1 inside).
const FRICTION: (f64, f64) = (0.02, 0.2);
/// The initial spins n [rad/s], evenly spaced across the thresholds.
const SPIN: (f64, f64) = (20.0, 200.0);
/// The initial tilt of the symmetry axis [rad].
const TILT: f64 = 0.1;
/// How long a top that does not turn over is followed [s].
const T_END: f64 = 25.0;
/// The integrator's tolerance (relative and absolute).
const TOL: f64 = 1e-9;

/// A tippe top's run that ends once the top has turned over: the contact's run loop, with the
/// first time the symmetry axis points below the horizontal.
struct UntilInverted<'a> {
    run: ContactRun<'a, Top>,
    /// When the axis first passed the horizontal (γ₃ = 0), once it has.
    inverted: Option<f64>,
}

impl Stepper for UntilInverted<'_> {
    type State = HybridState<ContactMode, [f64; STATE_LEN]>;

    fn t(&self) -> f64 {
        Stepper::t(&self.run)
    }

    fn state(&self) -> &Self::State {
        Stepper::state(&self.run)
    }

    fn stats(&self) -> Stats {
        Stepper::stats(&self.run)
    }

    /// The run loop's step; at its end, γ₃ below zero for the first time is located on the
    /// step's solution (γ₃ > 0 at the step's start, < 0 at its end).
    fn step(&mut self, t_limit: f64) -> Result<(), OdeError> {
        self.run.step(t_limit)?;
        if self.inverted.is_none() && axis_up(self.run.state()) < 0.0 {
            let (mut up, mut down) = (self.run.step_start(), Stepper::t(&self.run));
            loop {
                let mid = up + 0.5 * (down - up);
                if mid <= up || mid >= down {
                    break;
                }
                if axis_up(&self.run.state_at(mid)?.x) < 0.0 {
                    down = mid;
                } else {
                    up = mid;
                }
            }
            self.inverted = Some(down);
        }
        Ok(())
    }

    fn step_start(&self) -> f64 {
        self.run.step_start()
    }

    fn state_at(&mut self, t: f64) -> Result<Self::State, OdeError> {
        self.run.state_at(t)
    }

    fn restart(&mut self, t: f64, state: Self::State) -> Result<(), OdeError> {
        self.inverted = None;
        self.run.restart(t, state)
    }

    /// Halted when the top has turned over, or when its contact halted the run.
    fn halted(&self) -> bool {
        self.inverted.is_some() || self.run.halted()
    }
}

/// What one run keeps.
#[derive(Debug, Clone, Copy)]
struct Row {
    /// The inversion time [s], if the axis passed the horizontal within [`T_END`].
    inverted: Option<f64>,
    /// |λ/λ₀ − 1| where the run ended.
    lambda_drift: f64,
    /// The contact's own outcome, if it halted the run (lift-off, Painlevé, …).
    halt: Option<ContactOutcome>,
}

/// The grid: `nc` frictions (rows) × `nn` spins (columns); run `i` is row i / nn, column
/// i % nn.
#[derive(Debug, Clone, Copy)]
struct Sweep {
    nc: usize,
    nn: usize,
}

/// The k-th of `n` values evenly spaced over `range` (cell centres).
fn centre(range: (f64, f64), n: usize, k: usize) -> f64 {
    range.0 + (range.1 - range.0) * (k as f64 + 0.5) / n as f64
}

impl Sweep {
    fn friction(&self, row: usize) -> f64 {
        centre(FRICTION, self.nc, row)
    }

    fn spin(&self, column: usize) -> f64 {
        centre(SPIN, self.nn, column)
    }
}

/// What the command line asked for.
struct Args {
    dir: PathBuf,
    sweep: Sweep,
}

fn args() -> Result<Args, Box<dyn Error>> {
    let mut out = Args {
        dir: PathBuf::from(precess::plot::DEFAULT_DIR),
        sweep: Sweep { nc: 100, nn: 100 },
    };
    let mut it = std::env::args().skip(1);
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "--grid" => {
                let g = it.next().ok_or("--grid needs FRICTIONSxSPINS")?;
                let bad = || format!("--grid {g}: expected two counts ≥ 2 as 40x30");
                let (a, b) = g.split_once('x').ok_or_else(bad)?;
                let (nc, nn): (usize, usize) =
                    (a.parse().map_err(|_| bad())?, b.parse().map_err(|_| bad())?);
                if nc < 2 || nn < 2 {
                    return Err(bad().into());
                }
                out.sweep = Sweep { nc, nn };
            }
            "--out" => out.dir = it.next().ok_or("--out needs a directory")?.into(),
            other => return Err(format!("unknown argument {other}").into()),
        }
    }
    std::fs::create_dir_all(&out.dir)?;
    Ok(out)
}

/// The median of `values` (NaN for none).
fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    match values.len() {
        0 => f64::NAN,
        n if n % 2 == 1 => values[n / 2],
        n => 0.5 * (values[n / 2 - 1] + values[n / 2]),
    }
}

fn main() -> Result<(), Box<dyn Error>> {
    let args = args()?;
    let sweep = args.sweep;
    let tops: Vec<Top> = (0..sweep.nc)
        .map(|row| Top {
            viscous: sweep.friction(row),
        })
        .collect();
    let runs = sweep.nc * sweep.nn;
    let mut cfg = AdaptiveConfig::with_tol(TOL, TOL);
    cfg.max_steps = 10_000_000;

    let bar = indicatif::ProgressBar::new(runs as u64);
    let report = |p: EnsembleProgress| bar.set_position(p.done as u64);
    let clock = Instant::now();
    let results = Ensemble::new(0..runs).progress(&report).integrate(
        T_END,
        |i| {
            let top = &tops[i / sweep.nn];
            let y0 = tippe::start(TILT, sweep.spin(i % sweep.nn));
            let run = ContactRun::new(top, top.law().first_phase(), 0.0, y0, cfg)?;
            Ok::<_, ContactError>(UntilInverted {
                run,
                inverted: None,
            })
        },
        |i, s| {
            let top = &tops[i / sweep.nn];
            let lambda0 = top.jellett(&tippe::start(TILT, sweep.spin(i % sweep.nn)));
            Row {
                inverted: s.inverted,
                lambda_drift: (top.jellett(s.state()) / lambda0 - 1.0).abs(),
                halt: s.run.run().halt().copied(),
            }
        },
    );
    let seconds = clock.elapsed().as_secs_f64();
    bar.finish_and_clear();
    println!(
        "Tippe top sweep: {} frictions c ∈ [{}, {}] kg/s × {} spins n ∈ [{}, {}] rad/s, \
         tilt {TILT} rad, followed up to {T_END} s (DOP853, tol {TOL:e})",
        sweep.nc, FRICTION.0, FRICTION.1, sweep.nn, SPIN.0, SPIN.1
    );
    println!(
        "  {runs} runs in {seconds:.1} s on {} thread(s): {:.1} runs/s",
        rayon::current_num_threads(),
        runs as f64 / seconds
    );
    for e in results.errors().take(5) {
        eprintln!("  {e}");
    }
    if results.failures() > 0 {
        eprintln!("  {} runs failed; the rest are kept", results.failures());
    }
    let row_of = |i: usize| results.get(i).and_then(|r| r.as_ref().ok());
    let halted: Vec<(usize, ContactOutcome)> = (0..runs)
        .filter_map(|i| row_of(i).and_then(|r| r.halt).map(|h| (i, h)))
        .collect();
    if !halted.is_empty() {
        println!("  {} runs stopped by the contact itself:", halted.len());
        for (i, h) in halted.iter().take(5) {
            let (c, n) = (sweep.friction(i / sweep.nn), sweep.spin(i % sweep.nn));
            println!("    c = {c:.4}, n = {n:.1}: {h:?}");
        }
    }

    // The theory's thresholds as spins. At the start (the centre of mass at rest) the energy
    // is ½ I₃ n² + M g h and λ is linear in n, so the energy condition E(start) > E′(λ) of
    // `TippeTop::inverted_energy` is E − E′ = A n² + B > 0: n > √(−B/A), the least spin at
    // which friction could take the top over (necessary; `min_inversion_spin` of the upright
    // start, tilted here). Rauch-Wojciechowski & Rutstam's λ_thres gives a spin above which
    // it must.
    let theory = tippe::theory();
    let body = &tops[0];
    let gap = |n: f64| {
        let y = tippe::start(TILT, n);
        body.energy(Phase::Sliding, &y) - theory.inverted_energy(body.jellett(&y))
    };
    let (b, a) = (gap(0.0), gap(1.0) - gap(0.0));
    let n_energy = (-b / a).sqrt();
    let lambda_per_spin = body.jellett(&tippe::start(TILT, 1.0));
    let n_thres = theory
        .jellett_threshold()
        .map(|l| l / lambda_per_spin)
        .ok_or("no Jellett threshold for this top")?;
    println!(
        "  theory (TippeTop): 1 − α < I₁/I₃ < 1 + α: {}; the energy allows the inversion above \
         n = {n_energy:.3} rad/s ({:.3} upright); λ_thres of Rauch-Wojciechowski & Rutstam \
         at n = {n_thres:.3} rad/s",
        theory.inverts(),
        theory.min_inversion_spin()
    );

    // Per friction row: the inverted fraction, the median inversion time, and the least
    // spin that turned over (the midpoint between it and the spin below, which did not).
    println!(
        "\n  {:>10}  {:>9}  {:>14}  {:>12}  {:>16}",
        "c (kg/s)", "inverted", "median t (s)", "c × median", "least n (rad/s)"
    );
    let mut table = Table::default();
    let (mut map, mut worst_lambda) = (vec![f64::NAN; runs], 0.0_f64);
    let (mut lowest, mut highest) = (f64::INFINITY, f64::NEG_INFINITY);
    let show = sweep.nc.div_ceil(10).max(1);
    for row in 0..sweep.nc {
        let c = sweep.friction(row);
        let mut times = Vec::new();
        let mut least = None;
        for col in 0..sweep.nn {
            let i = row * sweep.nn + col;
            let Some(r) = row_of(i) else { continue };
            worst_lambda = worst_lambda.max(r.lambda_drift);
            if let Some(t) = r.inverted {
                map[i] = t;
                times.push(t);
                if least.is_none() && col > 0 {
                    least = Some(0.5 * (sweep.spin(col - 1) + sweep.spin(col)));
                }
            }
        }
        if let Some(n) = least {
            (lowest, highest) = (lowest.min(n), highest.max(n));
        }
        let count = times.len();
        let med = median(&mut times);
        if row % show == 0 || row + 1 == sweep.nc {
            println!(
                "  {c:>10.4}  {:>8.1}%  {med:>14.4}  {:>12.4}  {:>16}",
                100.0 * count as f64 / sweep.nn as f64,
                c * med,
                least.map_or("—".to_owned(), |n: f64| format!("{n:.2}"))
            );
            if let Some(n) = least {
                table.row(
                    format!("least spin that turned over, c = {c:.4} (rad/s)"),
                    n,
                    n_energy,
                );
            }
        }
    }
    table.row("max |λ/λ₀ − 1| over every run", worst_lambda, 0.0);
    let cell = (SPIN.1 - SPIN.0) / sweep.nn as f64;
    table.print(&format!(
        "Against the energy condition n > {n_energy:.3} rad/s (necessary; a grid cell is \
         {cell:.2} rad/s, {:.1e} of it)",
        cell / n_energy
    ));
    println!(
        "  the least inverting spin of every row lies in [{lowest:.2}, {highest:.2}] rad/s: \
         {:.1} cells above the energy bound, below λ_thres's {n_thres:.3}",
        (lowest - n_energy) / cell
    );

    let hi = map
        .iter()
        .copied()
        .filter(|t| t.is_finite())
        .fold(0.0, f64::max);
    // From 0, so that the colour reads the time itself (unless no top turned over).
    let colour = ColourBar::new("inversion time", "s");
    let figure = Map {
        title: "Tippe top: time to turn over (grey: not within 25 s)".into(),
        x: MapAxis::linear("initial spin n", "rad/s", SPIN),
        y: MapAxis::linear("viscous friction c", "kg/s", FRICTION),
        colour: if hi > 0.0 {
            colour.range(0.0, hi)
        } else {
            colour
        },
    };
    // Row j of the runs is friction j, lowest first, as the map's rows run.
    let rows: Vec<&[f64]> = map.chunks(sweep.nn).collect();
    let path = plot::map(args.dir.join("tippe_sweep.svg"), &figure, &rows)?;
    println!("\nfigure: {}", path.display());
    Ok(())
}
