//! The sleeping-top threshold found by an ensemble over every core: 10⁴ spins ω3 around the
//! threshold, one run each, and the threshold located from the sweep against
//! ω3² = 4 M g l I1 / I3² (`HeavyTopTheory::sleeping_threshold`).
//!
//! ```sh
//! cargo run --release --example sleeping_sweep [plot directory]
//! cargo run --release --example sleeping_sweep -- --runs 2000          # a smaller sweep
//! cargo run --release --example sleeping_sweep -- --shard 3/16 out/    # shard 3 of 16 only
//! cargo run --release --example sleeping_sweep -- --merge out/*.csv    # the shards together
//! ```
//!
//! Each run starts 1e-6 rad from the vertical and follows the tilt (`common/sweep.rs`). Below
//! the threshold the tilt grows at σ = √(4 I1 M g l − I3² ω3²) / (2 I1); the runs measure σ,
//! and the zero of the least-squares line of σ² against ω3² is the threshold. Falling alone
//! locates it too, biased low by the runs too near it to fall within their time.
//!
//! `--shard k/n` (0 ≤ k < n) runs only the k-th of n consecutive index ranges and writes its
//! rows, each with its global index, to `sleeping_sweep.shard-k-of-n.csv`; `--merge` reads
//! such files (in any order), and finds the same threshold, to the bit, as the whole sweep.
//! docs/ensembles.md spreads the shards over a Slurm job array, Ray or Kubernetes.

mod common;
#[path = "common/shards.rs"]
mod shards;
#[path = "common/sweep.rs"]
mod sweep;

use std::error::Error;
use std::path::PathBuf;
use std::time::Instant;

use common::{Axes, Series, Table, plot_in};
use precess::ensemble::{Ensemble, EnsembleProgress, rayon};
use precess::prelude::*;
use precess::top::{HeavyTopTheory, SleepingTop};
use shards::{parse_shard, shard};
use sweep::{FALLEN, Row, SweepTop, THETA0, read_csv, write_csv};

/// The sweep: 10⁴ spins from 3 to 5 rad/s about the threshold 4, each run at most 300 s.
const SWEEP: sweep::Sweep = sweep::Sweep {
    lo: 3.0,
    hi: 5.0,
    runs: 10_000,
    t_end: 300.0,
};

/// What the command line asked for.
struct Args {
    dir: PathBuf,
    runs: usize,
    shard: Option<(usize, usize)>,
    merge: Vec<PathBuf>,
}

fn args() -> Result<Args, Box<dyn Error>> {
    let mut out = Args {
        dir: PathBuf::from("target/precess-plots"),
        runs: SWEEP.runs,
        shard: None,
        merge: Vec::new(),
    };
    let (mut merging, mut positional) = (false, Vec::new());
    let mut it = std::env::args().skip(1);
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "--runs" => {
                let n = it.next().ok_or("--runs needs a number of runs")?;
                out.runs = n.parse().map_err(|_| format!("--runs {n}: not a count"))?;
            }
            "--shard" => {
                let s = it.next().ok_or("--shard needs k/n")?;
                out.shard = Some(parse_shard(&s)?);
            }
            "--merge" => merging = true,
            "--out" => out.dir = it.next().ok_or("--out needs a directory")?.into(),
            _ => positional.push(PathBuf::from(arg)),
        }
    }
    if merging {
        if positional.is_empty() {
            return Err("--merge needs the shards' CSV files".into());
        }
        out.merge = positional;
    } else if let Some(dir) = positional.first() {
        out.dir = dir.clone();
    }
    std::fs::create_dir_all(&out.dir)?;
    Ok(out)
}

fn main() -> Result<(), Box<dyn Error>> {
    let args = args()?;
    let sweep = sweep::Sweep {
        runs: args.runs,
        ..SWEEP
    };
    if !args.merge.is_empty() {
        let mut text = String::new();
        for file in &args.merge {
            text.push_str(&std::fs::read_to_string(file)?);
        }
        let rows = read_csv(&text)?;
        println!("merged {} rows from {} files", rows.len(), args.merge.len());
        return analyse(&rows, &args);
    }

    let (runs, csv) = match args.shard {
        Some((k, n)) => (
            shard(k, n, sweep.runs),
            format!("sleeping_sweep.shard-{k}-of-{n}.csv"),
        ),
        None => (0..sweep.runs, "sleeping_sweep.csv".to_owned()),
    };
    let bar = indicatif::ProgressBar::new(runs.len() as u64);
    let report = |p: EnsembleProgress| bar.set_position(p.done as u64);
    let start = Instant::now();
    let results = Ensemble::new(runs.clone())
        .progress(&report)
        .run(|i| sweep.run(i));
    let seconds = start.elapsed().as_secs_f64();
    bar.finish_and_clear();
    println!(
        "{} runs ({}..{} of {}) in {seconds:.2} s on {} thread(s): {:.0} runs/s",
        runs.len(),
        runs.start,
        runs.end,
        sweep.runs,
        rayon::current_num_threads(),
        runs.len() as f64 / seconds
    );
    for e in results.errors().take(5) {
        eprintln!("  {e}");
    }
    if results.failures() > 0 {
        eprintln!("  {} runs failed; the rest are kept", results.failures());
    }
    let rows: Vec<Row> = results.outputs().map(|(_, r)| *r).collect();
    let path = args.dir.join(csv);
    std::fs::write(&path, write_csv(&rows))?;
    println!("  rows: {}", path.display());
    if args.shard.is_some() {
        println!("  merge the shards with: --merge <their CSV files>");
        return Ok(());
    }
    analyse(&rows, &args)
}

/// The threshold and growth rates from the rows against theory, and the figure.
fn analyse(rows: &[Row], args: &Args) -> Result<(), Box<dyn Error>> {
    let theory = HeavyTopTheory::from_principal(SweepTop.principal().moments, 1.0)?;
    let threshold = theory.sleeping_threshold();
    let sigma = |omega3: f64| match theory.sleeping_top(omega3) {
        Ok(SleepingTop::Unstable { growth_rate, .. }) => growth_rate,
        _ => 0.0,
    };
    let missing = rows
        .last()
        .map_or(0, |last| last.index + 1 - rows.len().min(last.index + 1));
    if missing > 0 {
        println!("  {missing} runs are missing from the rows (failed or not merged)");
    }

    let mut table = Table::default();
    let fit = sweep::threshold_from_growth(rows).ok_or("too few runs fell to fit σ²")?;
    table.row("threshold ω3, zero of σ² fitted on ω3²", fit, threshold);
    if let Some(falls) = sweep::threshold_from_falls(rows) {
        table.row("threshold ω3, last spin that fell", falls, threshold);
    }
    for target in [3.0, 3.5, 3.9, 3.99] {
        let nearest = rows
            .iter()
            .filter(|r| r.growth_rate.is_some())
            .min_by(|a, b| {
                (a.omega3 - target)
                    .abs()
                    .total_cmp(&(b.omega3 - target).abs())
            });
        if let Some(Row {
            omega3,
            growth_rate: Some(g),
            ..
        }) = nearest
        {
            table.row(
                format!("growth rate σ at ω3 = {omega3:.4}"),
                *g,
                sigma(*omega3),
            );
        }
    }
    if let Some(top) = rows.last().filter(|r| r.growth_rate.is_none()) {
        let l = theory.i3() * top.omega3;
        let linear = THETA0 * l / (l * l - 4.0 * theory.i1() * theory.mgl()).sqrt();
        let label = format!("largest tilt at ω3 = {:.4} [rad]", top.omega3);
        table.row(label, top.largest_tilt, linear);
    }
    table.print(&format!(
        "Sleeping top over {} spins: I1 = 1, I3 = 0.5, M g l = 1 (theory: ω3² = 4 M g l I1 / I3²)",
        rows.len()
    ));
    println!(
        "  {} runs fell (tilt past {FALLEN} rad); the fall-only threshold is low by the spins \
         too near it to fall within a run",
        rows.iter().filter(|r| r.growth_rate.is_some()).count()
    );

    // At most 400 markers: an SVG of 10⁴ circles is slow to open and shows nothing more.
    let stride = rows.len().div_ceil(400).max(1);
    let measured: Vec<(f64, f64)> = rows
        .iter()
        .step_by(stride)
        .map(|r| (r.omega3, r.growth_rate.unwrap_or(0.0)))
        .collect();
    let (lo, hi) = rows.iter().fold((f64::MAX, f64::MIN), |(a, b), r| {
        (a.min(r.omega3), b.max(r.omega3))
    });
    let curve: Vec<(f64, f64)> = (0..=400)
        .map(|k| lo + (hi - lo) * k as f64 / 400.0)
        .map(|w| (w, sigma(w)))
        .collect();
    let top = curve.iter().map(|p| p.1).fold(0.0, f64::max);
    let path = plot_in(
        &args.dir,
        "sleeping_sweep.svg",
        &Axes {
            title: "Sleeping top: growth rate of the tilt over the sweep",
            x: "ω3 [rad/s]",
            y: "growth rate σ [1/s] (0: sleeps)",
            log_x: false,
            log_y: false,
        },
        &[
            Series::markers(
                match stride {
                    1 => "simulated".to_owned(),
                    _ => format!("simulated (every {stride}th run)"),
                },
                measured,
            ),
            Series::line("σ = √(4 I1 M g l − I3² ω3²) / (2 I1)", curve),
            Series::line(
                format!("threshold ω3 = {threshold}"),
                vec![(threshold, 0.0), (threshold, top)],
            ),
        ],
    )?;
    println!("  figure: {}", path.display());
    Ok(())
}
