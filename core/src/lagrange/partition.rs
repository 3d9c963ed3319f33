//! Coordinate partitioning at run time: after a step, the dependent coordinates of a closed
//! loop are solved from `φ(q) = 0` by Newton's method with the symbolic Jacobian block
//! `A_D = ∂φ/∂q_D`, the independent coordinates and the free speeds left as the stepper
//! made them. The dependent rates need no correction: the model computes them from the
//! constraints at every evaluation.

use nalgebra::{DMatrix, DVector};

use super::error::LagrangeError;
use super::model::ConstrainedModel;
use crate::ode::Stepper;

/// The most Newton iterations [`ConstrainedModel::close_loop`] takes.
pub const MAX_NEWTON: usize = 20;

/// A block whose determinant is below this fraction of the product of its rows' norms is
/// taken as singular (the loop is folded flat, or the dependent choice fails there).
pub const SINGULAR_BLOCK: f64 = 1e-12;

/// The largest position residual max |φ_k| a partitioned run accepts at its start. Past it the
/// initial state is not on the loop up to the rounding of its set-up but a wrong state, and
/// Newton would move it silently (perhaps onto the other assembly branch); the run refuses
/// it instead. Residuals have the constraints' units (lengths for a linkage).
pub const START_RESIDUAL: f64 = 1e-9;

impl ConstrainedModel {
    /// The position residuals φ(q, t), one per constraint, or `None` unless every
    /// constraint is holonomic.
    ///
    /// # Errors
    /// [`LagrangeError::StateLength`], [`LagrangeError::NonFiniteState`].
    pub fn position_residuals(
        &self,
        t: f64,
        state: &[f64],
    ) -> Result<Option<Vec<f64>>, LagrangeError> {
        self.check(state)?;
        let Some(p) = &self.positions else {
            return Ok(None);
        };
        let m = self.dependent.len();
        let mut out = vec![0.0; m + m * m];
        self.run(p, t, state, &mut out);
        out.truncate(m);
        Ok(Some(out))
    }

    /// Solves `φ(q, t) = 0` for the dependent coordinates by Newton's method from their
    /// values in `state`, until `max |φ| ≤ tolerance` or a Newton step is at rounding level
    /// (φ then sits on its rounding floor); returns the iterations taken (0 when the state
    /// already closes). Does nothing, returning 0, unless every constraint is
    /// holonomic.
    ///
    /// # Errors
    /// [`LagrangeError::StateLength`], [`LagrangeError::NonFiniteState`];
    /// [`LagrangeError::SingularAtState`] where `|det A_D|` is below [`SINGULAR_BLOCK`]
    /// times the product of its rows' norms; [`LagrangeError::LoopNotClosed`] naming the
    /// residual left after [`MAX_NEWTON`] iterations or when an iteration no longer
    /// reduces it. `state` is left unchanged on error.
    pub fn close_loop(
        &self,
        t: f64,
        state: &mut [f64],
        tolerance: f64,
    ) -> Result<usize, LagrangeError> {
        self.check(state)?;
        let Some(p) = &self.positions else {
            return Ok(0);
        };
        let m = self.dependent.len();
        let mut trial = state.to_vec();
        let mut out = vec![0.0; m + m * m];
        let mut last = f64::INFINITY;
        // The size of the last Newton step against its coordinates: a step at rounding
        // level means φ sits on its rounding floor, closed as far as f64 can tell.
        let mut step_at_rounding = false;
        let mut iteration = 0;
        loop {
            self.run(p, t, &trial, &mut out);
            let residual = out[..m].iter().fold(0.0_f64, |r, v| r.max(v.abs()));
            if residual <= tolerance || step_at_rounding {
                state.copy_from_slice(&trial);
                return Ok(iteration);
            }
            if iteration == MAX_NEWTON
                || residual.partial_cmp(&last) != Some(std::cmp::Ordering::Less)
            {
                return Err(LagrangeError::LoopNotClosed {
                    residual,
                    iterations: iteration,
                    tolerance,
                });
            }
            last = residual;
            let block = DMatrix::from_row_slice(m, m, &out[m..]);
            let determinant = block.determinant();
            let scale: f64 = block.row_iter().map(|r| r.norm()).product();
            if determinant.abs().partial_cmp(&(SINGULAR_BLOCK * scale))
                != Some(std::cmp::Ordering::Greater)
            {
                return Err(LagrangeError::SingularAtState { determinant, scale });
            }
            let phi = DVector::from_column_slice(&out[..m]);
            let Some(step) = block.lu().solve(&phi) else {
                return Err(LagrangeError::SingularAtState { determinant, scale });
            };
            step_at_rounding = true;
            for (j, &d) in self.dependent.iter().enumerate() {
                step_at_rounding &= step[j].abs() <= 4.0 * f64::EPSILON * trial[d].abs().max(1.0);
                trial[d] -= step[j];
            }
            iteration += 1;
        }
    }

    /// det A_D over the product of its rows' norms at `state` (A_D = ∂φ/∂q_D, the block
    /// Newton solves with), or `None` unless every constraint is holonomic.
    fn normalised_block_determinant(&self, t: f64, state: &[f64]) -> Option<f64> {
        let p = self.positions.as_ref()?;
        let m = self.dependent.len();
        let mut out = vec![0.0; m + m * m];
        self.run(p, t, state, &mut out);
        let block = DMatrix::from_row_slice(m, m, &out[m..]);
        let scale: f64 = block.row_iter().map(|r| r.norm()).product();
        Some(block.determinant() / scale)
    }

    /// Advances `stepper` to `t_end`, closing the loop at its start and after every accepted
    /// step ([`ConstrainedModel::close_loop`] with `tolerance`) and restarting the stepper at
    /// the corrected state; returns the Newton iterations spent.
    ///
    /// A step over which det A_D changes sign has carried the independent coordinates
    /// through a dead point (a four-bar's crank at a limit position): the run stops there
    /// with [`LagrangeError::DeadPoint`], the stepper left at the step's start, rather than
    /// go on with dependent coordinates the free ones no longer determine.
    ///
    /// # Errors
    /// [`LagrangeError::DeadPoint`] as above;
    /// [`LagrangeError::StartOffLoop`] when the stepper's state is off the loop by more than
    /// [`START_RESIDUAL`] (close it first, on the branch you mean, with
    /// [`ConstrainedModel::close_loop`]); [`LagrangeError::Ode`] for the stepper's failures;
    /// the errors of [`ConstrainedModel::close_loop`].
    pub fn advance_partitioned<S, const N: usize>(
        &self,
        stepper: &mut S,
        t_end: f64,
        tolerance: f64,
    ) -> Result<usize, LagrangeError>
    where
        S: Stepper<State = [f64; N]>,
    {
        let (t0, mut y0) = (stepper.t(), *stepper.state());
        if let Some(residuals) = self.position_residuals(t0, &y0)? {
            let residual = residuals.iter().fold(0.0_f64, |m, r| m.max(r.abs()));
            if residual.is_nan() || residual > START_RESIDUAL {
                return Err(LagrangeError::StartOffLoop {
                    residual,
                    allowed: START_RESIDUAL,
                });
            }
        }
        let mut newton = self.close_loop(t0, &mut y0, tolerance)?;
        if newton > 0 {
            stepper.restart(t0, y0)?;
        }
        let mut det = self.normalised_block_determinant(t0, &y0);
        while stepper.t() < t_end {
            let (t_start, y_start) = (stepper.t(), *stepper.state());
            stepper.step(t_end)?;
            let t = stepper.t();
            let mut y = *stepper.state();
            let now = self.normalised_block_determinant(t, &y);
            if let (Some(before), Some(after)) = (det, now)
                && before * after < 0.0
            {
                stepper.restart(t_start, y_start)?;
                return Err(LagrangeError::DeadPoint {
                    t_start,
                    t_end: t,
                    before,
                    after,
                });
            }
            det = now;
            newton += self.close_loop(t, &mut y, tolerance)?;
            stepper.restart(t, y)?;
        }
        Ok(newton)
    }
}
