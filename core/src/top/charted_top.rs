//! Getting through gimbal lock: two angle charts of one top and a driver that switches
//! between them.
//!
//! Euler angles are singular where `det B(q) = 0` (sin θ = 0 for ZXZ, cos pitch = 0 for ZYX):
//! the mass matrix loses rank and q̈ blows up. The ZXZ and ZYX charts are never singular at
//! the same attitude (ZXZ fails when the body z axis is vertical, ZYX when the body x axis
//! is), so [`ChartedTop`] integrates in one chart and, between steps, moves the state to the
//! other chart whenever `|det B|` falls below [`ChartConfig::switch_below`] and the other chart
//! is better conditioned. The state is mapped exactly through the attitude R and the body
//! angular velocity ω, which both charts share.

use nalgebra::{Matrix3, Vector3};

use super::angle_chart::AngleChart;
use super::error::ChartError;
use crate::ode::{AdaptiveConfig, Dop853, Stats};
use crate::rigid::{AngleSequence, angles_from_rotation};

/// When to switch charts, and the integrator settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChartConfig {
    /// Switch when `|det B(q)|` of the current chart falls below this (default 0.3, i.e.
    /// θ within 17° of the vertical for ZXZ).
    pub switch_below: f64,
    /// The adaptive stepper's configuration (default: DOP853 at rtol = atol = 1e-10).
    pub stepper: AdaptiveConfig,
}

impl Default for ChartConfig {
    fn default() -> Self {
        ChartConfig {
            switch_below: 0.3,
            stepper: AdaptiveConfig::with_tol(1e-10, 1e-10),
        }
    }
}

/// A top integrated in whichever of two angle charts is regular, with DOP853.
pub struct ChartedTop<'m, C> {
    charts: [&'m C; 2],
    active: usize,
    ode: Dop853<&'m C, 6>,
    config: ChartConfig,
    switches: usize,
    /// Work done in the charts left behind.
    finished: Stats,
}

impl<'m, C: AngleChart> ChartedTop<'m, C> {
    /// Starts from an attitude `r` (body to space) and a body angular velocity `omega`, in
    /// the better-conditioned of the two charts.
    ///
    /// # Errors
    /// [`ChartError::SameSequence`] if both models use one sequence; [`ChartError::Singular`]
    /// if neither chart can represent the state; the stepper's errors for bad settings or a
    /// non-finite state.
    pub fn new(
        charts: [&'m C; 2],
        t0: f64,
        r: &Matrix3<f64>,
        omega: &Vector3<f64>,
        config: ChartConfig,
    ) -> Result<Self, ChartError> {
        if charts[0].sequence() == charts[1].sequence() {
            return Err(ChartError::SameSequence(charts[0].sequence()));
        }
        let states = [0, 1].map(|k| state_in(charts[k], r, omega));
        let dets = [states[0].1, states[1].1];
        let active = if dets[0] >= dets[1] { 0 } else { 1 };
        let (state, _) = states[active];
        let state = state.ok_or(ChartError::Singular {
            primary: dets[0],
            secondary: dets[1],
        })?;
        let ode = Dop853::new(charts[active], t0, state, config.stepper)?;
        Ok(ChartedTop {
            charts,
            active,
            ode,
            config,
            switches: 0,
            finished: Stats::default(),
        })
    }

    /// Integrates to `t_end`, switching charts between steps as needed.
    ///
    /// # Errors
    /// The stepper's errors ([`OdeError`]), or [`ChartError::Singular`].
    pub fn advance_to(&mut self, t_end: f64) -> Result<(), ChartError> {
        while self.ode.t() < t_end {
            self.ode.step(t_end)?;
            self.maybe_switch()?;
        }
        Ok(())
    }

    fn maybe_switch(&mut self) -> Result<(), ChartError> {
        let y = *self.ode.y();
        let here = self.charts[self.active];
        // |det B(q)| is zero exactly at the chart's singularity.
        let det_here = here.rate_matrix_at(&y).determinant().abs();
        if det_here >= self.config.switch_below {
            return Ok(());
        }
        let other = 1 - self.active;
        let r = here.rotation_at(&y);
        let w = here.omega_at(&y);
        let (state, det_other) = state_in(self.charts[other], &r, &w);
        match state {
            Some(s) if det_other > det_here => {
                let t = self.ode.t();
                let done = self.ode.stats();
                self.finished.steps += done.steps;
                self.finished.rejections += done.rejections;
                self.finished.rhs_evals += done.rhs_evals;
                self.ode = Dop853::new(self.charts[other], t, s, self.config.stepper)?;
                self.active = other;
                self.switches += 1;
                Ok(())
            }
            _ => Ok(()),
        }
    }

    /// Current time.
    pub fn t(&self) -> f64 {
        self.ode.t()
    }

    /// The state `[q, q̇]` in the active chart.
    pub fn state(&self) -> &[f64; 6] {
        self.ode.y()
    }

    /// The active chart's angle sequence.
    pub fn sequence(&self) -> AngleSequence {
        self.charts[self.active].sequence()
    }

    /// The attitude R, body to space.
    pub fn rotation(&self) -> Matrix3<f64> {
        self.charts[self.active].rotation_at(self.ode.y())
    }

    /// The body angular velocity ω.
    pub fn omega(&self) -> Vector3<f64> {
        self.charts[self.active].omega_at(self.ode.y())
    }

    /// The energy T + V.
    pub fn energy(&self) -> f64 {
        self.charts[self.active].energy_at(self.ode.y())
    }

    /// The work done so far, over every chart.
    pub fn stats(&self) -> Stats {
        let now = self.ode.stats();
        Stats {
            steps: self.finished.steps + now.steps,
            rejections: self.finished.rejections + now.rejections,
            rhs_evals: self.finished.rhs_evals + now.rhs_evals,
        }
    }

    /// How many times the driver changed chart.
    pub fn switches(&self) -> usize {
        self.switches
    }
}

/// The state of attitude `r` and body rate `omega` in `model`'s chart: the angles from R, the
/// rates from solving B(q) q̇ = ω; `None` where B is singular. Also returns |det B|.
fn state_in<C: AngleChart>(
    model: &C,
    r: &Matrix3<f64>,
    omega: &Vector3<f64>,
) -> (Option<[f64; 6]>, f64) {
    let q = angles_from_rotation(model.sequence(), r);
    let probe = [q[0], q[1], q[2], 0.0, 0.0, 0.0];
    let b = model.rate_matrix_at(&probe);
    let det = b.determinant().abs();
    let rates = b
        .lu()
        .solve(omega)
        .filter(|v| v.iter().all(|x| x.is_finite()));
    let state = rates.map(|qd| [q[0], q[1], q[2], qd[0], qd[1], qd[2]]);
    (state, det)
}
