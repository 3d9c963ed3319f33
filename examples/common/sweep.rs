//! The sleeping-top sweep of `examples/sleeping_sweep.rs`, kept apart so that the shard test
//! (`tests/it/ensemble_shards.rs`) runs the same code: one run per spin, rows written as CSV
//! with their global index, shards of an index range, and the threshold located from the rows.
//!
//! Each run starts θ0 = 1e-6 rad from the vertical at rest in the tilt, spinning at ω3. Linear
//! theory: the tilt ξ = θ e^{iφ} obeys I1 ξ̈ − i L ξ̇ − M g l ξ = 0 (L = I3 ω3). Below the
//! threshold it grows at σ = √(4 I1 M g l − L²) / (2 I1), so σ² is linear in ω3² and its zero
//! is the threshold ω3² = 4 M g l I1 / I3²; above it the tilt stays of order θ0. A run
//! measures σ from the times the tilt crosses 1e-3 and 1e-2 rad (where θ ∝ sinh σt to 1e-5
//! and the nonlinear terms are 1e-4 of the linear ones) and stops there; a run that never
//! reaches 1e-2 rad keeps its largest tilt only.

#![allow(dead_code)] // the example and the test each use the part they need

use std::error::Error;

use precess::ode::AdaptiveConfig;
use precess::prelude::*;

/// I1 = 1, I3 = ½ about the pivot, M g l = 1: threshold ω3 = √(4 · 1 · 1) / ½ = 4.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 1.0)]
pub struct SweepTop;

/// The initial tilt from the vertical [rad].
pub const THETA0: f64 = 1e-6;
/// The tilt at which the growth is first timed [rad].
pub const GROWN: f64 = 1e-3;
/// The tilt at which a run counts as fallen and stops [rad].
pub const FALLEN: f64 = 1e-2;
/// The interval at which the tilt is sampled [s].
pub const SAMPLE: f64 = 0.25;

/// A sweep: `runs` spins spaced evenly over [`lo`, `hi`], each run to `t_end` unless fallen.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sweep {
    /// The lowest spin [rad/s].
    pub lo: f64,
    /// The highest spin [rad/s].
    pub hi: f64,
    /// The number of runs in the whole sweep (every shard's `runs` is the same).
    pub runs: usize,
    /// How long a run that does not fall is followed [s].
    pub t_end: f64,
}

/// What one run keeps: its global index, its spin, the largest tilt reached and the growth
/// rate of the tilt (`None` if it never reached [`FALLEN`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Row {
    /// The run's index in the whole sweep.
    pub index: usize,
    /// ω3 [rad/s].
    pub omega3: f64,
    /// The largest tilt from the vertical [rad].
    pub largest_tilt: f64,
    /// σ [1/s], from the crossings of [`GROWN`] and [`FALLEN`].
    pub growth_rate: Option<f64>,
}

/// The CSV header of [`write_csv`].
pub const HEADER: &str = "index,omega3,largest_tilt,growth_rate";

impl Sweep {
    /// The spin of run `index`: `lo` to `hi` in `runs − 1` equal steps.
    pub fn omega3(&self, index: usize) -> f64 {
        let span = self.runs.saturating_sub(1).max(1) as f64;
        self.lo + (self.hi - self.lo) * index as f64 / span
    }

    /// Run `index`: the tilt followed from θ0 every [`SAMPLE`] s.
    pub fn run(&self, index: usize) -> Result<Row, TopError> {
        let omega3 = self.omega3(index);
        let r0 = *Rotation3::from_axis_angle(&Vector3::x_axis(), THETA0).matrix();
        let w0 = Vector3::new(0.0, 0.0, omega3);
        let config = ChartConfig {
            stepper: AdaptiveConfig::with_tol(1e-11, 1e-14),
            ..ChartConfig::default()
        };
        let mut top = ChartedTop::new(TopChart::both(&SweepTop), 0.0, &r0, &w0, config)?;
        let (mut largest, mut before) = (THETA0, (0.0, THETA0));
        let mut grown_at = None;
        let mut t = 0.0;
        while t < self.t_end {
            t = (t + SAMPLE).min(self.t_end);
            top.advance_to(t)?;
            // The figure axis in space is R's third column.
            let r = top.rotation();
            let tilt = r[(0, 2)].hypot(r[(1, 2)]).atan2(r[(2, 2)]);
            largest = largest.max(tilt);
            if grown_at.is_none() && tilt >= GROWN {
                grown_at = Some(crossing(before, (t, tilt), GROWN));
            }
            if let Some(t_grown) = grown_at
                && tilt >= FALLEN
            {
                let t_fallen = crossing(before, (t, tilt), FALLEN);
                let sigma = (FALLEN / GROWN).ln() / (t_fallen - t_grown);
                return Ok(Row {
                    index,
                    omega3,
                    largest_tilt: largest,
                    growth_rate: Some(sigma),
                });
            }
            before = (t, tilt);
        }
        Ok(Row {
            index,
            omega3,
            largest_tilt: largest,
            growth_rate: None,
        })
    }
}

/// The time the tilt crossed `level` between two samples, interpolating ln θ linearly (the
/// tilt grows exponentially, so ln θ is nearly a straight line over one sample).
fn crossing((t0, a): (f64, f64), (t1, b): (f64, f64), level: f64) -> f64 {
    let (la, lb) = (a.ln(), b.ln());
    if lb > la {
        t0 + (t1 - t0) * (level.ln() - la) / (lb - la)
    } else {
        t1
    }
}

/// The rows as CSV, header first. Numbers are written in Rust's shortest form that reads
/// back to the same bits, so a merged file gives the same threshold as the runs in memory;
/// a run that did not fall has an empty growth rate.
pub fn write_csv(rows: &[Row]) -> String {
    let mut out = String::from(HEADER);
    out.push('\n');
    for row in rows {
        let growth = row.growth_rate.map(|g| g.to_string()).unwrap_or_default();
        out.push_str(&format!(
            "{},{},{},{}\n",
            row.index, row.omega3, row.largest_tilt, growth
        ));
    }
    out
}

/// Reads rows written by [`write_csv`], from one file or several concatenated (each header
/// line is skipped), sorted by index.
///
/// # Errors
/// A line that is not four fields of the right kinds, or an index that appears twice.
pub fn read_csv(text: &str) -> Result<Vec<Row>, Box<dyn Error>> {
    let mut rows = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line == HEADER {
            continue;
        }
        let bad = || format!("line {}: expected `{HEADER}`, found `{line}`", n + 1);
        let fields: Vec<&str> = line.split(',').collect();
        let [index, omega3, largest, growth] = fields.as_slice() else {
            return Err(bad().into());
        };
        rows.push(Row {
            index: index.parse().map_err(|_| bad())?,
            omega3: omega3.parse().map_err(|_| bad())?,
            largest_tilt: largest.parse().map_err(|_| bad())?,
            growth_rate: if growth.is_empty() {
                None
            } else {
                Some(growth.parse().map_err(|_| bad())?)
            },
        });
    }
    rows.sort_by_key(|r| r.index);
    if let Some(pair) = rows.windows(2).find(|w| w[0].index == w[1].index) {
        return Err(format!("run {} appears twice", pair[0].index).into());
    }
    Ok(rows)
}

/// The threshold from the growth rates: the zero of the least-squares line σ² = a + b ω3²
/// over the runs that fell, ω3 = √(−a / b). `None` with fewer than two such runs or a line
/// that does not fall through zero at a positive ω3².
pub fn threshold_from_growth(rows: &[Row]) -> Option<f64> {
    let points: Vec<(f64, f64)> = rows
        .iter()
        .filter_map(|r| r.growth_rate.map(|s| (r.omega3 * r.omega3, s * s)))
        .collect();
    if points.len() < 2 {
        return None;
    }
    let n = points.len() as f64;
    let (mx, my) = points
        .iter()
        .fold((0.0, 0.0), |(x, y), p| (x + p.0 / n, y + p.1 / n));
    let (sxy, sxx) = points.iter().fold((0.0, 0.0), |(xy, xx), p| {
        (xy + (p.0 - mx) * (p.1 - my), xx + (p.0 - mx) * (p.0 - mx))
    });
    let slope = sxy / sxx;
    let zero = mx - my / slope;
    (slope < 0.0 && zero > 0.0).then(|| zero.sqrt())
}

/// The threshold from falling alone: midway between the fastest spin that fell and the next
/// spin of the sweep. Below the true threshold by about the spins too close to it to fall
/// within the run's time (σ T ≲ ln(FALLEN σ / (θ0 κ)), κ = L / (2 I1)).
pub fn threshold_from_falls(rows: &[Row]) -> Option<f64> {
    let last = rows.iter().rposition(|r| r.growth_rate.is_some())?;
    let next = rows.get(last + 1)?;
    Some(0.5 * (rows[last].omega3 + next.omega3))
}
