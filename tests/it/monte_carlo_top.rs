//! The physics `examples/monte_carlo_top.rs` relies on, through its own code
//! (`common/monte_carlo.rs`, compiled optimised as the testkit's `monte_carlo`): the flow
//! map of the run-time variational equations is the derived top's flow and its central
//! differences; for a small P₀ the sample moments of an ensemble of Gaussian starts agree
//! with the nominal state and Φ P₀ Φᵀ within their sampling errors; for a wide P₀ they do
//! not.

use precess::ensemble::Ensemble;
use precess::nalgebra::DMatrix;
use precess::ode::Dop853;
use precess::prelude::*;
use precess_testkit::monte_carlo::{
    self, Moments, UncertainTop, X0, covariance, flow_maps, mahalanobis2, tolerances,
};

const TIMES: [f64; 3] = [1.0, 4.0, 12.0];

/// The derived top's compiled flow from `x0` to `t`.
fn flow(x0: [f64; 6], t: f64) -> [f64; 6] {
    let chart = TopChart::declared(&UncertainTop);
    let mut ode = Dop853::new(&chart, 0.0, x0, tolerances()).unwrap();
    ode.advance_to(t).unwrap();
    *ode.y()
}

/// x(t) and Φ(t) of the run-time variational equations against the derived top's compiled
/// flow and its central differences (h = 10⁻⁶ in each initial entry).
#[test]
fn the_flow_map_is_the_derived_tops_flow() {
    let maps = flow_maps(&TIMES).unwrap();
    let h = 1e-6;
    for (&t, map) in TIMES.iter().zip(&maps) {
        let x = flow(X0, t);
        let gap = (0..6)
            .map(|i| (x[i] - map.state[i]).abs())
            .fold(0.0, f64::max);
        let mut fd = DMatrix::zeros(6, 6);
        for j in 0..6 {
            let (mut up, mut down) = (X0, X0);
            up[j] += h;
            down[j] -= h;
            let (yu, yd) = (flow(up, t), flow(down, t));
            for i in 0..6 {
                fd[(i, j)] = (yu[i] - yd[i]) / (2.0 * h);
            }
        }
        let err = (&map.transition - &fd).amax() / map.transition.amax();
        eprintln!(
            "t = {t}: |x − x_derived| = {gap:e}, |Φ − differences| / |Φ| = {err:e} (max |Φ| = {:.3})",
            map.transition.amax()
        );
        assert!(gap < 1e-9, "{gap:e}");
        assert!(err < 1e-6, "{err:e}");
    }
}

/// The sampler: 2 · 10⁵ starts drawn as the example draws them have the mean X0 and the
/// covariance P₀ within 4.5 sampling errors in each of the 6 means and 21 distinct entries
/// (sampling errors of 0.3 % of a variance: a sampler 2 % off its variance fails).
#[test]
fn the_starts_are_drawn_from_p0() {
    let p0 = covariance(1e-4, 1e-3);
    let chol = p0.clone().cholesky().unwrap().l();
    let n = 200_000;
    let starts: Vec<[f64; 6]> = (0..n).map(|i| monte_carlo::start(3, i, &chol)).collect();
    let m = Moments::of(starts.iter(), &X0);
    let mut worst: f64 = 0.0;
    for i in 0..6 {
        worst = worst.max(((m.mean[i] - X0[i]) / m.mean_error(&p0, i)).abs());
        for j in i..6 {
            let z = (m.cov[(i, j)] - p0[(i, j)]) / m.covariance_error(&p0, i, j);
            worst = worst.max(z.abs());
        }
    }
    eprintln!("{n} starts: largest |z| of the means and covariance entries {worst:.2}");
    assert!(worst < 4.5, "{worst}");
}

/// The clouds of `runs` Gaussian starts of covariance `p0` at [`TIMES`], through the
/// ensemble, as the example draws them.
fn clouds(p0: &DMatrix<f64>, runs: usize, seed: u64) -> Vec<Vec<[f64; 6]>> {
    let chol = p0.clone().cholesky().unwrap().l();
    let results = Ensemble::new(0..runs).run(|i| monte_carlo::run(seed, i, &chol, &TIMES));
    assert_eq!(results.failures(), 0);
    results.into_iter().map(Result::unwrap).collect()
}

/// Small P₀ (σ = 10⁻⁴ rad, 10⁻³ rad/s): at each time, every one of the 21 distinct sample
/// covariance entries and the six sample means, in units of its sampling error
/// (√((P_ii P_jj + P_ij²)/N), √(P_ii/N)), is within 4.5 of Φ P₀ Φᵀ and the nominal state,
/// and the mean square of those 81 z-scores is near 1 (a chi-square over their count; the
/// entries are correlated, so the bound is loose: 2.5). A wrong Φ, a transposed product, a
/// wrong time or a sampler off its covariance moves the covariances by many errors.
#[test]
fn a_small_clouds_moments_are_the_linearised_ones() {
    let p0 = covariance(1e-4, 1e-3);
    let runs = 1500;
    let clouds = clouds(&p0, runs, 7);
    let maps = flow_maps(&TIMES).unwrap();
    let (mut worst, mut sum_sq, mut count): (f64, f64, usize) = (0.0, 0.0, 0);
    for (k, map) in maps.iter().enumerate() {
        let p = map.covariance(&p0).unwrap();
        let m = Moments::of(clouds.iter().map(|c| &c[k]), &map.state);
        for i in 0..6 {
            let z = (m.mean[i] - map.state[i]) / m.mean_error(&p, i);
            worst = worst.max(z.abs());
            sum_sq += z * z;
            count += 1;
            for j in i..6 {
                let z = (m.cov[(i, j)] - p[(i, j)]) / m.covariance_error(&p, i, j);
                worst = worst.max(z.abs());
                sum_sq += z * z;
                count += 1;
            }
        }
    }
    let mean_sq = sum_sq / count as f64;
    eprintln!(
        "small cloud, {runs} runs: {count} z-scores, largest |z| {worst:.2}, mean z² {mean_sq:.2}"
    );
    assert!(worst < 4.5, "{worst}");
    assert!(mean_sq < 2.5, "{mean_sq}");
}

/// Wide P₀ (σ = 0.03 rad, 0.3 rad/s): by t = 12 the cloud has bent around the nominal orbit,
/// so the fraction inside the linearised 2σ ellipse of (φ, θ) is no longer 1 − e⁻² and the
/// mean of φ is off the nominal state, each by more than five sampling errors.
#[test]
fn a_wide_cloud_leaves_the_linear_region() {
    let p0 = covariance(3e-2, 3e-1);
    let runs = 2000;
    let clouds = clouds(&p0, runs, 7);
    let maps = flow_maps(&TIMES).unwrap();
    let (k, map) = (2, &maps[2]);
    let p = map.covariance(&p0).unwrap();
    let inside = clouds
        .iter()
        .filter(|c| {
            let d = (c[k][0] - map.state[0], c[k][1] - map.state[1]);
            mahalanobis2(&p, (0, 1), d) <= 4.0
        })
        .count() as f64
        / runs as f64;
    let gaussian = 1.0 - (-2.0f64).exp();
    let z_inside = (inside - gaussian) / (gaussian * (1.0 - gaussian) / runs as f64).sqrt();
    let m = Moments::of(clouds.iter().map(|c| &c[k]), &map.state);
    let z_mean = (m.mean[0] - map.state[0]) / m.mean_error(&p, 0);
    eprintln!(
        "wide cloud at t = 12: {inside:.4} inside 2σ (Gaussian {gaussian:.4}, z = {z_inside:.1}), \
         mean φ z = {z_mean:.1}"
    );
    assert!(z_inside.abs() > 5.0, "{z_inside}");
    assert!(z_mean.abs() > 5.0, "{z_mean}");
}
