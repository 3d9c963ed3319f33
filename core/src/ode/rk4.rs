//! The classical fixed-step Runge–Kutta method of order 4.

use super::config::FixedStepConfig;
use super::error::{OdeError, check_finite, check_span};
use super::fixed::{StepGrid, check_inside, fixed_step_clock, restart_switchable, two_sum};
use super::stepper::{Stepper, state_accessors};
use super::system::{Stats, System, all_finite, non_finite};

/// Steps between two checks of RK4's state (the first bad step is then found by replaying
/// the block).
const CHECK_BLOCK: u64 = 8;

/// Classical RK4: y₁ = y₀ + h (k₁ + 2k₂ + 2k₃ + k₄)/6, four evaluations per step, global
/// error O(h⁴); the update is summed with compensation unless
/// [`FixedStepConfig::compensated`] is off, so round-off does not grow as h shrinks.
///
/// ```
/// use precess_core::ode::{FixedStepConfig, FnSystem, Rk4};
/// let sys = FnSystem(|_t: f64, y: &[f64; 1], d: &mut [f64; 1]| d[0] = y[0]);
/// let mut rk = Rk4::new(sys, 0.0, [1.0], FixedStepConfig::with_step(1e-3))?;
/// rk.advance_to(1.0)?;
/// approx::assert_relative_eq!(rk.y()[0], 1f64.exp(), max_relative = 1e-12);
/// # Ok::<(), precess_core::ode::OdeError>(())
/// ```
#[derive(Debug, Clone)]
pub struct Rk4<S, const N: usize> {
    sys: S,
    cfg: FixedStepConfig,
    t: f64,
    y: [f64; N],
    /// The low-order bits of y that compensated summation carries (0 when plain).
    y_lo: [f64; N],
    stats: Stats,
    /// The last step of [`Stepper::step`] (start, state, stage-time cap), for the partial
    /// steps of [`Stepper::state_at`]; after [`Rk4::advance_to`] it is the current state.
    t_prev: f64,
    y_prev: [f64; N],
    y_prev_lo: [f64; N],
    t_hi: f64,
    grid: Option<StepGrid>,
}

impl<S: System<N>, const N: usize> Rk4<S, N> {
    /// Starts at `(t0, y0)`.
    ///
    /// # Errors
    /// [`OdeError::InvalidStep`] for `h ≤ 0` or non-finite, [`OdeError::NonFiniteTime`] or
    /// [`OdeError::NonFiniteInitialState`] for a non-finite `t0` or `y0`, the system's own
    /// refusal of its parameters ([`System::check_parameters`]).
    pub fn new(sys: S, t0: f64, y0: [f64; N], cfg: FixedStepConfig) -> Result<Self, OdeError> {
        cfg.validate()?;
        check_span(t0, t0)?;
        check_finite(&y0)?;
        sys.check_parameters()?;
        Ok(Self {
            sys,
            cfg,
            t: t0,
            y: y0,
            y_lo: [0.0; N],
            stats: Stats::default(),
            t_prev: t0,
            y_prev: y0,
            y_prev_lo: [0.0; N],
            t_hi: f64::INFINITY,
            grid: None,
        })
    }

    state_accessors!(N);

    /// The increment h (k₁ + 2k₂ + 2k₃ + k₄)/6 of one step of size `h` from `(t, y)` (no
    /// checks; the caller guarantees h > 0); stage times are capped at `t_hi` so a step ending
    /// on a stop samples a switch from its own side.
    #[inline]
    fn increment(sys: &S, t: f64, y: &[f64; N], h: f64, t_hi: f64) -> [f64; N] {
        let (mut k1, mut k2, mut k3, mut k4, mut ys) =
            ([0.0; N], [0.0; N], [0.0; N], [0.0; N], [0.0; N]);
        sys.rhs(t, y, &mut k1);
        for i in 0..N {
            ys[i] = y[i] + 0.5 * h * k1[i];
        }
        sys.rhs((t + 0.5 * h).min(t_hi), &ys, &mut k2);
        for i in 0..N {
            ys[i] = y[i] + 0.5 * h * k2[i];
        }
        sys.rhs((t + 0.5 * h).min(t_hi), &ys, &mut k3);
        for i in 0..N {
            ys[i] = y[i] + h * k3[i];
        }
        sys.rhs((t + h).min(t_hi), &ys, &mut k4);
        let mut dy = [0.0; N];
        for i in 0..N {
            dy[i] = h / 6.0 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
        }
        dy
    }

    /// The error of the step of size `h` from `(t, y)` whose result was not finite: its
    /// stages taken again, the system's explanation ([`System::explain_non_finite`]) at the
    /// first whose f is not finite, else [`OdeError::NonFiniteState`] at `t`. Off the
    /// stepping path: called once, when the step has failed.
    fn explain_step(&self, t: f64, y: &[f64; N], h: f64, t_hi: f64) -> OdeError {
        // (c, a) of each stage: it is evaluated at t + c h and y + a h k_prev.
        let tableau = [(0.0, 0.0), (0.5, 0.5), (0.5, 0.5), (1.0, 1.0)];
        let mut k = [0.0; N];
        for (c, a) in tableau {
            let ts = (t + c * h).min(t_hi);
            let ys: [f64; N] = std::array::from_fn(|i| y[i] + a * h * k[i]);
            let mut f = [0.0; N];
            self.sys.rhs(ts, &ys, &mut f);
            if !all_finite(&f) {
                return non_finite(&self.sys, t, (ts, &ys));
            }
            k = f;
        }
        OdeError::NonFiniteState { t }
    }

    /// One step from `(t, y)` with the low-order bits `lo` of y, returned as the new
    /// `(y, lo)` rather than stored so that a non-finite result can leave the state as it
    /// was. Compensated, y + lo + Δ is summed by TwoSum and its rounding error kept in the new
    /// lo (the stages see y alone: their error is multiplied by h); plain, lo stays 0.
    #[inline]
    fn step_from(
        &self,
        t: f64,
        y: &[f64; N],
        lo: &[f64; N],
        h: f64,
        t_hi: f64,
    ) -> ([f64; N], [f64; N]) {
        let dy = Self::increment(&self.sys, t, y, h, t_hi);
        let (mut y_new, mut lo_new) = ([0.0; N], [0.0; N]);
        if self.cfg.compensated {
            for i in 0..N {
                (y_new[i], lo_new[i]) = two_sum(y[i], dy[i] + lo[i]);
            }
        } else {
            for i in 0..N {
                y_new[i] = y[i] + dy[i];
            }
        }
        (y_new, lo_new)
    }

    /// Advances to exactly `t_stop` in equal steps no longer than the configured `h`.
    ///
    /// # Errors
    /// Before any work: [`OdeError::NonFiniteTime`] for a NaN or infinite `t_stop`,
    /// [`OdeError::StopBeforeCurrent`], [`OdeError::TooManySteps`] beyond
    /// [`FixedStepConfig::max_steps`]. While stepping: [`OdeError::NonFiniteState`] at the
    /// first step whose result is not finite, naming its start time; the integrator then
    /// stays at the last finite state.
    pub fn advance_to(&mut self, t_stop: f64) -> Result<(), OdeError> {
        let Some((n, h)) = self.cfg.plan(self.t, t_stop)? else {
            return Ok(());
        };
        let t0 = self.t;
        let t_hi = t_stop.next_down();
        // The loop runs on locals; the integrator is updated once at the end or on error.
        let (mut t, mut y, mut lo) = (t0, self.y, self.y_lo);
        let mut done = 0;
        while done < n {
            // The state is checked after each block of a few steps: a non-finite component
            // stays non-finite (∞ + finite = ∞, anything with NaN is NaN), so a blow-up is
            // caught within the block at a fraction of a per-step check's cost.
            let len = CHECK_BLOCK.min(n - done);
            let (t_start, y_start, lo_start) = (t, y, lo);
            for i in done + 1..=done + len {
                (y, lo) = self.step_from(t, &y, &lo, h, t_hi);
                t = t0 + i as f64 * h;
            }
            if !all_finite(&y) {
                // Replay the block (the same arithmetic) to stop at its first bad step.
                (t, y, lo) = (t_start, y_start, lo_start);
                for i in done + 1..=done + len {
                    let (y_new, lo_new) = self.step_from(t, &y, &lo, h, t_hi);
                    if !all_finite(&y_new) {
                        self.t = t;
                        self.y = y;
                        self.y_lo = lo;
                        self.stats.steps += i - 1;
                        self.stats.rhs_evals += 4 * (len + i);
                        self.forget_last_step();
                        return Err(self.explain_step(t, &y, h, t_hi));
                    }
                    (y, lo) = (y_new, lo_new);
                    t = t0 + i as f64 * h;
                }
            }
            done += len;
        }
        self.y = y;
        self.y_lo = lo;
        self.t = t_stop;
        self.stats.steps += n;
        self.stats.rhs_evals += 4 * n;
        self.forget_last_step();
        Ok(())
    }

    /// After a move that is not one [`Stepper::step`]: no partial steps before `t`.
    fn forget_last_step(&mut self) {
        self.t_prev = self.t;
        self.y_prev = self.y;
        self.y_prev_lo = self.y_lo;
        self.grid = None;
    }
}

/// One RK4 step at a time on the grid of equal steps to the limit (as
/// [`Rk4::advance_to`] takes them); inside a step, the solution is RK4's own partial step
/// from the step's start.
impl<S: System<N>, const N: usize> Stepper for Rk4<S, N> {
    type State = [f64; N];

    fixed_step_clock!([f64; N]);

    fn step(&mut self, t_limit: f64) -> Result<(), OdeError> {
        let Some((h, t_new)) = StepGrid::next(&mut self.grid, &self.cfg, self.t, t_limit)? else {
            return Ok(());
        };
        let t_hi = t_limit.next_down();
        let (y_new, lo_new) = self.step_from(self.t, &self.y, &self.y_lo, h, t_hi);
        self.stats.rhs_evals += 4;
        if !all_finite(&y_new) {
            return Err(self.explain_step(self.t, &self.y, h, t_hi));
        }
        StepGrid::advance(&mut self.grid);
        (self.t_prev, self.y_prev, self.y_prev_lo, self.t_hi) = (self.t, self.y, self.y_lo, t_hi);
        (self.t, self.y, self.y_lo) = (t_new, y_new, lo_new);
        self.stats.steps += 1;
        Ok(())
    }

    fn state_at(&mut self, t: f64) -> Result<[f64; N], OdeError> {
        check_inside(t, self.t_prev, self.t)?;
        if t == self.t {
            return Ok(self.y);
        }
        if t == self.t_prev {
            return Ok(self.y_prev);
        }
        let (y, _) = self.step_from(
            self.t_prev,
            &self.y_prev,
            &self.y_prev_lo,
            t - self.t_prev,
            self.t_hi,
        );
        self.stats.rhs_evals += 4;
        if all_finite(&y) {
            Ok(y)
        } else {
            let h = t - self.t_prev;
            Err(self.explain_step(self.t_prev, &self.y_prev, h, self.t_hi))
        }
    }

    fn restart(&mut self, t: f64, state: [f64; N]) -> Result<(), OdeError> {
        check_span(t, t)?;
        check_finite(&state)?;
        self.sys.check_parameters()?;
        (self.t, self.y, self.y_lo) = (t, state, [0.0; N]);
        self.forget_last_step();
        Ok(())
    }
}

// The state checked to be finite, then the system changed.
restart_switchable!([S: System<N>, const N: usize] Rk4<S, N>, sys: S, |s| &mut s.sys, |_, y| {
    check_finite(y)
});
