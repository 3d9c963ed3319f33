//! The uncertain heavy top of `examples/monte_carlo_top.rs`, kept apart so that the physics
//! test (`tests/it/monte_carlo_top.rs`) runs the same code: Gaussian starts drawn from a
//! seeded generator, each run by the derived top's compiled equations, the sample moments,
//! and the linearised flow map Φ P₀ Φᵀ from the variational equations of the same top built
//! at run time — two independent routes to the same covariance.
//!
//! The state is the top's ZXZ chart, (φ, θ, ψ, φ̇, θ̇, ψ̇): precession, tilt and spin angles
//! and their rates.

#![allow(dead_code)] // the example and the test each use the part they need

use std::error::Error;

use precess::nalgebra::{DMatrix, DVector};
use precess::ode::{AdaptiveConfig, Dop853, OdeError};
use precess::prelude::*;
use precess::sym::Arena;
use precess::top::TopScene;
use precess::variational::{FlowMap, VariationalEquations, VariationalSystem};
use precess_testkit::rng::Rng;

/// A slightly asymmetric heavy top: I = 1, 1.2, 0.5 about the pivot, centre of mass on the
/// figure axis at 1, M g = 1.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.2, 0.5), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 1.0)]
pub struct UncertainTop;

/// The nominal start: tilted 1 rad, spinning at 8 rad/s, no precession or nutation rate.
pub const X0: [f64; 6] = [0.0, 1.0, 0.0, 0.0, 0.0, 8.0];

/// The names of the state's entries, for tables.
pub const NAMES: [&str; 6] = ["φ", "θ", "ψ", "φ̇", "θ̇", "ψ̇"];

/// The integrator of every run and of the flow map: DOP853 at 10⁻¹², far below the spread
/// of the smallest cloud.
pub fn tolerances() -> AdaptiveConfig {
    AdaptiveConfig::with_tol(1e-12, 1e-12)
}

/// A diagonal covariance: standard deviation `angle` on the three angles \[rad\] and `rate`
/// on the three rates [rad/s].
pub fn covariance(angle: f64, rate: f64) -> DMatrix<f64> {
    let d = [angle, angle, angle, rate, rate, rate].map(|s| s * s);
    DMatrix::from_diagonal(&DVector::from_column_slice(&d))
}

/// The linearised flow map of the nominal start at each of `times` (increasing), from the
/// variational equations of the same top as a run-time `TopScene` (Φ 6 × 6, N = 42).
///
/// # Errors
/// From the derivation, the variational system, the integrator and [`FlowMap::new`].
pub fn flow_maps(times: &[f64]) -> Result<Vec<FlowMap>, Box<dyn Error>> {
    let mut a = Arena::new();
    let z = a.zero();
    let diag = [a.float(1.0)?, a.float(1.2)?, a.float(0.5)?];
    let mut scene = TopScene::free(&mut a, [[diag[0], z, z], [z, diag[1], z], [z, z, diag[2]]]);
    scene.center = [z, z, a.one()];
    scene.gravity = Some(a.one());
    let derivation = scene.derive(&mut a)?;
    let eq = VariationalEquations::from_top(&mut a, &derivation, 6, &[])?;
    let system = VariationalSystem::<42>::new(&a, &eq, &[])?;
    let mut ode = Dop853::new(&system, 0.0, system.initial_state(&X0)?, tolerances())?;
    let mut maps = Vec::with_capacity(times.len());
    for &t in times {
        ode.advance_to(t)?;
        maps.push(FlowMap::new(system.layout(), ode.y())?);
    }
    Ok(maps)
}

/// The start of run `index`: X0 + L z with z standard normal and L the Cholesky factor of
/// P₀. Each run draws from its own stream, seeded by `seed` and its index alone, so the
/// cloud is the same on any number of threads and in any shard.
pub fn start(seed: u64, index: usize, chol: &DMatrix<f64>) -> [f64; 6] {
    // The run's stream starts at a scrambled state: streams seeded seed + k would be the
    // same sequence shifted by k draws.
    let mut rng = Rng::new(Rng::new(seed ^ (index as u64).rotate_left(32)).next_u64());
    let mut z = [0.0; 6];
    for pair in z.chunks_mut(2) {
        // Box–Muller: two uniforms to two independent standard normals.
        let u1 = 1.0 - rng.uniform(0.0, 1.0); // in (0, 1], so its log is finite
        let u2 = rng.uniform(0.0, 1.0);
        let r = (-2.0 * u1.ln()).sqrt();
        let a = std::f64::consts::TAU * u2;
        pair[0] = r * a.cos();
        pair[1] = r * a.sin();
    }
    let dx = chol * DVector::from_column_slice(&z);
    std::array::from_fn(|i| X0[i] + dx[i])
}

/// Run `index`: its start integrated by the derived top's ZXZ chart, the state at each of
/// `times` (increasing).
///
/// # Errors
/// The integrator's, for a run that fails.
pub fn run(
    seed: u64,
    index: usize,
    chol: &DMatrix<f64>,
    times: &[f64],
) -> Result<Vec<[f64; 6]>, OdeError> {
    let chart = TopChart::declared(&UncertainTop);
    let mut ode = Dop853::new(&chart, 0.0, start(seed, index, chol), tolerances())?;
    times
        .iter()
        .map(|&t| {
            ode.advance_to(t)?;
            Ok(*ode.y())
        })
        .collect()
}

/// Sample mean and covariance (divided by n − 1) of states, summed about a first guess so
/// that large means cost no precision.
#[derive(Debug, Clone, PartialEq)]
pub struct Moments {
    /// The number of samples.
    pub n: usize,
    /// The sample mean.
    pub mean: DVector<f64>,
    /// The sample covariance.
    pub cov: DMatrix<f64>,
}

impl Moments {
    /// The moments of `samples` (at least two); `centre` is a guess of the mean (the
    /// nominal state) that the sums are taken about.
    pub fn of<'a>(samples: impl Iterator<Item = &'a [f64; 6]>, centre: &[f64]) -> Moments {
        let mut n = 0usize;
        let mut s1 = DVector::zeros(6);
        let mut s2 = DMatrix::zeros(6, 6);
        for x in samples {
            let d = DVector::from_fn(6, |i, _| x[i] - centre[i]);
            s2 += &d * d.transpose();
            s1 += d;
            n += 1;
        }
        let nf = n as f64;
        let m = &s1 / nf;
        let cov = (s2 - &m * m.transpose() * nf) / (nf - 1.0).max(1.0);
        Moments {
            n,
            mean: DVector::from_fn(6, |i, _| centre[i] + m[i]),
            cov,
        }
    }

    /// The standard error of the sample covariance entry (i, j) of a Gaussian of
    /// covariance `p`: √((P_ii P_jj + P_ij²) / n).
    pub fn covariance_error(&self, p: &DMatrix<f64>, i: usize, j: usize) -> f64 {
        ((p[(i, i)] * p[(j, j)] + p[(i, j)] * p[(i, j)]) / self.n as f64).sqrt()
    }

    /// The standard error of the sample mean of entry i: √(P_ii / n).
    pub fn mean_error(&self, p: &DMatrix<f64>, i: usize) -> f64 {
        (p[(i, i)] / self.n as f64).sqrt()
    }
}

/// δᵀ P⁻¹ δ for the 2 × 2 block (i, j) of `p`: the squared Mahalanobis distance, ≤ k² inside
/// the k-σ ellipse. Infinite for a singular block.
pub fn mahalanobis2(p: &DMatrix<f64>, (i, j): (usize, usize), d: (f64, f64)) -> f64 {
    let (a, b, c) = (p[(i, i)], p[(i, j)], p[(j, j)]);
    let det = a * c - b * b;
    if det <= 0.0 {
        return f64::INFINITY;
    }
    (c * d.0 * d.0 - 2.0 * b * d.0 * d.1 + a * d.1 * d.1) / det
}
