//! An uncertain start of a heavy top propagated two ways, side by side: 10⁵ runs drawn from a
//! Gaussian of covariance P₀ on the angles and rates, spread over every core by the
//! ensemble, and the linearised flow map P(t) = Φ(t) P₀ Φ(t)ᵀ from the variational equations
//! of one run.
//!
//! ```sh
//! cargo run --release --example monte_carlo_top [plot directory]
//! cargo run --release --example monte_carlo_top -- --runs 20000   # a smaller cloud
//! ```
//!
//! The top (I = 1, 1.2, 0.5 about the pivot, centre of mass on the figure axis at 1,
//! M g = 1) starts tilted θ = 1 rad and spinning at ψ̇ = 8 rad/s (`common/monte_carlo.rs`).
//! The runs use the derived top's compiled equations, the flow map the interpreted
//! variational equations of the same top built at run time: two independent routes.
//!
//! For a small P₀ (σ = 10⁻⁴ rad on the angles, 10⁻³ rad/s on the rates) the flow is linear
//! across the cloud: the sample mean is the nominal state and the sample covariance is
//! Φ P₀ Φᵀ, both within the sampling error (σ/√N for a mean, √((P_ii P_jj + P_ij²)/N) for a
//! covariance entry), and 86.5 % of the cloud lies inside the 2σ ellipse, as for any
//! Gaussian in two dimensions. For a P₀ thirty times wider the cloud outgrows the linear
//! region: it bends around the nominal orbit (the precession rate depends on the start), the
//! mean drifts off the nominal state by many sampling errors, and the ellipses no longer
//! hold the cloud.

mod common;
#[path = "common/maps.rs"]
mod maps;
#[path = "common/monte_carlo.rs"]
mod monte_carlo;

use std::error::Error;
use std::path::PathBuf;
use std::time::Instant;

use maps::{CloudGroup, cloud, ellipse};
use monte_carlo::{Moments, NAMES, covariance, flow_maps, mahalanobis2};
use precess::ensemble::{Ensemble, EnsembleProgress, rayon};
use precess::nalgebra::DMatrix;
use precess::variational::FlowMap;

/// The times the cloud is looked at: within the first nutation, after a few, after many.
const TIMES: [f64; 3] = [1.0, 4.0, 12.0];
/// The generator's seed: the same clouds on every run of the example.
const SEED: u64 = 25;
/// The (φ, θ) plane the figures and the ellipse counts use.
const PLANE: (usize, usize) = (0, 1);
/// The fraction of a two-dimensional Gaussian inside its 2σ ellipse: 1 − e^{−2}.
const INSIDE_2SIGMA: f64 = 0.864_664_716_763_387_3;

/// A row of the side-by-side table.
struct Row {
    quantity: String,
    sampled: f64,
    linear: f64,
    /// The standard error of the sampled value.
    error: f64,
}

fn print(title: &str, rows: &[Row]) {
    let width = rows
        .iter()
        .map(|r| r.quantity.chars().count())
        .max()
        .unwrap_or(8);
    println!("\n{title}");
    println!(
        "  {:<width$}  {:>16}  {:>16}  {:>10}  {:>10}  {:>8}",
        "quantity", "Monte Carlo", "linearised", "rel. diff", "σ_N (rel.)", "diff/σ_N"
    );
    for r in rows {
        let scale = r.linear.abs().max(f64::MIN_POSITIVE);
        println!(
            "  {:<width$}  {:>16.9e}  {:>16.9e}  {:>10.2e}  {:>10.2e}  {:>8.2}",
            r.quantity,
            r.sampled,
            r.linear,
            (r.sampled - r.linear).abs() / scale,
            r.error / scale,
            (r.sampled - r.linear) / r.error
        );
    }
}

fn main() -> Result<(), Box<dyn Error>> {
    let mut dir = PathBuf::from("target/precess-plots");
    let mut runs = 100_000;
    let mut it = std::env::args().skip(1);
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "--runs" => {
                let n = it.next().ok_or("--runs needs a number of runs")?;
                runs = n
                    .parse()
                    .ok()
                    .filter(|&r| r >= 2)
                    .ok_or_else(|| format!("--runs {n}: expected a count of at least 2"))?;
            }
            _ => dir = PathBuf::from(arg),
        }
    }
    std::fs::create_dir_all(&dir)?;

    let start = Instant::now();
    let maps = flow_maps(&TIMES)?;
    println!(
        "linearised flow map at t = {TIMES:?}: one run of the variational equations (N = 42) in {:.3} s",
        start.elapsed().as_secs_f64()
    );
    for (label, file, angle, rate) in [
        ("small", "monte_carlo_top.svg", 1e-4, 1e-3),
        ("large", "monte_carlo_top_large.svg", 3e-2, 3e-1),
    ] {
        let p0 = covariance(angle, rate);
        let chol = p0
            .clone()
            .cholesky()
            .ok_or("P₀ is not positive definite")?
            .l();
        let bar = indicatif::ProgressBar::new(runs as u64);
        let report = |p: EnsembleProgress| bar.set_position(p.done as u64);
        let start = Instant::now();
        let results = Ensemble::new(0..runs)
            .progress(&report)
            .run(|i| monte_carlo::run(SEED, i, &chol, &TIMES));
        let seconds = start.elapsed().as_secs_f64();
        bar.finish_and_clear();
        println!(
            "\n{label} P₀ (σ = {angle} rad on the angles, {rate} rad/s on the rates): {runs} runs to \
             t = {} in {seconds:.2} s on {} thread(s): {:.0} runs/s",
            TIMES[TIMES.len() - 1],
            rayon::current_num_threads(),
            runs as f64 / seconds
        );
        for e in results.errors().take(5) {
            eprintln!("  {e}");
        }
        if results.failures() > 0 {
            eprintln!("  {} runs failed; the rest are kept", results.failures());
        }
        let clouds: Vec<&Vec<[f64; 6]>> = results.outputs().map(|(_, c)| c).collect();
        let mut rows = Vec::new();
        let mut groups = Vec::new();
        for (k, (&t, map)) in TIMES.iter().zip(&maps).enumerate() {
            let p = map.covariance(&p0)?;
            let samples: Vec<[f64; 6]> = clouds.iter().map(|c| c[k]).collect();
            let m = Moments::of(samples.iter(), &map.state);
            rows.extend(table_rows(t, &m, map, &p));
            let inside = samples
                .iter()
                .filter(|x| {
                    let d = (
                        x[PLANE.0] - map.state[PLANE.0],
                        x[PLANE.1] - map.state[PLANE.1],
                    );
                    mahalanobis2(&p, PLANE, d) <= 4.0
                })
                .count() as f64
                / samples.len() as f64;
            rows.push(Row {
                quantity: format!("t = {t}: fraction inside the 2σ ellipse of (φ, θ)"),
                sampled: inside,
                linear: INSIDE_2SIGMA,
                error: (INSIDE_2SIGMA * (1.0 - INSIDE_2SIGMA) / samples.len() as f64).sqrt(),
            });
            groups.push(group(t, &samples, map, &p));
        }
        print(
            &format!(
                "{label} P₀, {} runs: sample moments against the linearised flow map Φ P₀ Φᵀ",
                clouds.len()
            ),
            &rows,
        );
        let title = format!(
            "A heavy top's uncertain start ({label} P₀): {} runs against the linearised ellipses",
            clouds.len()
        );
        let path = cloud(
            &dir.join(file),
            &title,
            ("φ − φ̄(t), precession [rad]", "θ − θ̄(t), tilt [rad]"),
            &groups,
        )?;
        println!("  figure: {}", path.display());
    }
    Ok(())
}

/// The means of φ and θ and a few covariance entries at time `t`, sampled against linearised.
fn table_rows(t: f64, m: &Moments, map: &FlowMap, p: &DMatrix<f64>) -> Vec<Row> {
    let mut rows = Vec::new();
    for i in [0, 1] {
        rows.push(Row {
            quantity: format!("t = {t}: mean {}", NAMES[i]),
            sampled: m.mean[i],
            linear: map.state[i],
            error: m.mean_error(p, i),
        });
    }
    for (i, j) in [(0, 0), (1, 1), (0, 1), (4, 4), (2, 5)] {
        rows.push(Row {
            quantity: format!("t = {t}: cov({}, {})", NAMES[i], NAMES[j]),
            sampled: m.cov[(i, j)],
            linear: p[(i, j)],
            error: m.covariance_error(p, i, j),
        });
    }
    rows
}

/// The cloud at one time in the (φ, θ) plane about the nominal state (at most 600 dots:
/// more only blacken the figure), with the linearised 1σ and 2σ ellipses.
fn group(t: f64, samples: &[[f64; 6]], map: &FlowMap, p: &DMatrix<f64>) -> CloudGroup {
    let (i, j) = PLANE;
    let stride = samples.len().div_ceil(600).max(1);
    let dots: Vec<(f64, f64)> = samples
        .iter()
        .step_by(stride)
        .map(|x| (x[i] - map.state[i], x[j] - map.state[j]))
        .collect();
    let block = [[p[(i, i)], p[(i, j)]], [p[(j, i)], p[(j, j)]]];
    CloudGroup {
        label: format!("t = {t}: {} of the runs, 1σ and 2σ", dots.len()),
        dots,
        curves: vec![
            ellipse((0.0, 0.0), block, 1.0),
            ellipse((0.0, 0.0), block, 2.0),
        ],
    }
}
