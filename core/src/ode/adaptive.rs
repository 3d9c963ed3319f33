//! The adaptive driver: stop times, dense output, statistics; the step size comes from
//! [`PiController`], the settings from [`AdaptiveConfig`].

use core::marker::PhantomData;

use super::config::AdaptiveConfig;
use super::controller::PiController;
use super::error::{OdeError, check_finite, check_span, check_stop};
use super::pairs::{DenseCoeffs, EmbeddedPair, Stages};
use super::stepper::state_accessors;
use super::system::{Stats, System, all_finite, non_finite};

/// An adaptive integrator using the embedded pair `P` on a system `S` of dimension `N`.
///
/// Owns its stage storage, so stepping never allocates. The drivers of the concrete pairs
/// are [`Dopri5`](super::Dopri5), [`Dop853`](super::Dop853) and [`Vern9`](super::Vern9).
///
/// ```
/// use precess_core::ode::{AdaptiveConfig, Dop853, FnSystem};
/// let sys = FnSystem(|_t: f64, y: &[f64; 1], d: &mut [f64; 1]| d[0] = -y[0]);
/// let mut ode = Dop853::new(sys, 0.0, [1.0], AdaptiveConfig::with_tol(1e-12, 1e-14))?;
/// ode.advance_to(1.0)?;
/// approx::assert_relative_eq!(ode.y()[0], (-1.0f64).exp(), max_relative = 1e-11);
/// # Ok::<(), precess_core::ode::OdeError>(())
/// ```
#[derive(Debug, Clone)]
pub struct Adaptive<S, P, const N: usize> {
    sys: S,
    cfg: AdaptiveConfig,
    t: f64,
    y: [f64; N],
    h: f64,
    k: Stages<N>,
    t_prev: f64,
    y_prev: [f64; N],
    dense: DenseCoeffs<N>,
    dense_ready: bool,
    control: PiController,
    /// The last step landed on a stop: re-evaluate f before the next step.
    refresh: bool,
    stats: Stats,
    /// Step attempts towards `target`, the stop of the current run: the budget
    /// [`AdaptiveConfig::max_steps`] counts these, not the integrator's whole life.
    attempts: u64,
    target: f64,
    pair: PhantomData<P>,
}

impl<S: System<N>, P: EmbeddedPair, const N: usize> Adaptive<S, P, N> {
    /// Starts at `(t0, y0)`; validates everything before any work.
    ///
    /// # Errors
    /// Invalid configuration, a non-finite `t0` or a non-finite `y0`, and the system's own
    /// refusal of its parameters ([`System::check_parameters`]).
    pub fn new(sys: S, t0: f64, y0: [f64; N], cfg: AdaptiveConfig) -> Result<Self, OdeError> {
        cfg.validate()?;
        check_span(t0, t0)?;
        check_finite(&y0)?;
        sys.check_parameters()?;
        let mut k = [[0.0; N]; 21];
        sys.rhs(t0, &y0, &mut k[0]);
        let mut me = Self {
            sys,
            cfg,
            t: t0,
            y: y0,
            h: 0.0,
            k,
            t_prev: t0,
            y_prev: y0,
            dense: [[0.0; N]; 9],
            dense_ready: false,
            control: PiController::new::<P>(&cfg),
            refresh: false,
            stats: Stats {
                rhs_evals: 1,
                ..Stats::default()
            },
            attempts: 0,
            target: f64::NAN,
            pair: PhantomData,
        };
        if !all_finite(&me.k[0]) {
            return Err(non_finite(&me.sys, t0, (t0, &y0)));
        }
        me.h = match cfg.h0 {
            Some(h) => h.min(cfg.h_max),
            None => me.initial_step(),
        };
        Ok(me)
    }

    /// Hairer's starting-step heuristic (HNW I, §II.4): match h^(p+1)·‖f''‖ to 0.01.
    fn initial_step(&mut self) -> f64 {
        let (rtol, atol) = (self.cfg.rtol, self.cfg.atol);
        let rms = |v: &dyn Fn(usize) -> f64| {
            let s: f64 = (0..N).map(|i| v(i) * v(i)).sum();
            (s / N.max(1) as f64).sqrt()
        };
        let sk = |i: usize| atol + rtol * self.y[i].abs();
        let dnf = rms(&|i| self.k[0][i] / sk(i));
        let dny = rms(&|i| self.y[i] / sk(i));
        let mut h = if dnf <= 1e-5 || dny <= 1e-5 {
            1e-6
        } else {
            0.01 * dny / dnf
        };
        h = h.min(self.cfg.h_max);
        let mut y1 = [0.0; N];
        for ((o, y), f) in y1.iter_mut().zip(&self.y).zip(&self.k[0]) {
            *o = y + h * f;
        }
        let mut f1 = [0.0; N];
        self.sys.rhs(self.t + h, &y1, &mut f1);
        self.stats.rhs_evals += 1;
        let der2 = rms(&|i| (f1[i] - self.k[0][i]) / sk(i)) / h;
        let der12 = der2.abs().max(dnf);
        let h1 = if der12 <= 1e-15 || !der12.is_finite() {
            (h * 1e-3).max(1e-6)
        } else {
            (0.01 / der12).powf(1.0 / P::ORDER as f64)
        };
        (100.0 * h).min(h1).min(self.cfg.h_max)
    }

    state_accessors!(N);

    /// Step size the controller will try next.
    pub fn h(&self) -> f64 {
        self.h
    }

    /// The system being integrated.
    pub fn system(&self) -> &S {
        &self.sys
    }

    /// Start of the last accepted step (equal to [`Self::t`] before the first step, after
    /// [`Self::modify_system`] and after a restart): dense output covers `[last_step_start, t]`.
    pub fn last_step_start(&self) -> f64 {
        self.t_prev
    }

    /// [`System::check_parameters`] of the driver's system, for a restart.
    pub(super) fn check_system(&self) -> Result<(), OdeError> {
        self.sys.check_parameters()
    }

    /// Puts the driver at `(t, y)` for [`Stepper::restart`](super::Stepper::restart) (the
    /// caller checks the values): the next step re-evaluates f there, the dense output of the
    /// step before is dropped, the step size and the controller's memory are kept.
    pub(super) fn reset_state(&mut self, t: f64, y: [f64; N]) {
        self.t = t;
        self.y = y;
        self.t_prev = t;
        self.y_prev = y;
        self.dense_ready = false;
        self.refresh = true;
        (self.attempts, self.target) = (0, f64::NAN);
    }

    /// Changes the system between steps (a torque switched on or off at a stop time) and
    /// re-evaluates f(t, y) for the next step (one evaluation); the dense output of the
    /// step before is dropped, since it belonged to the old system.
    ///
    /// ```
    /// use precess_core::ode::{AdaptiveConfig, Dop853, System};
    /// struct Switch { on: bool }
    /// impl System<1> for Switch {
    ///     fn rhs(&self, _t: f64, _y: &[f64; 1], d: &mut [f64; 1]) { d[0] = if self.on { 1.0 } else { 0.0 } }
    /// }
    /// let mut ode = Dop853::new(Switch { on: true }, 0.0, [0.0], AdaptiveConfig::default())?;
    /// ode.advance_to(1.0)?;
    /// ode.modify_system(|s| s.on = false);
    /// ode.advance_to(2.0)?;
    /// approx::assert_relative_eq!(ode.y()[0], 1.0, epsilon = 1e-14);
    /// # Ok::<(), precess_core::ode::OdeError>(())
    /// ```
    pub fn modify_system(&mut self, f: impl FnOnce(&mut S)) {
        f(&mut self.sys);
        self.refresh = self.stats.steps > 0;
        if !self.refresh {
            self.sys.rhs(self.t, &self.y, &mut self.k[0]);
            self.stats.rhs_evals += 1;
        }
        self.t_prev = self.t;
        self.y_prev = self.y;
        self.dense_ready = false;
    }

    /// Starts again from `(t0, y0)` with the same system and settings, as [`Adaptive::new`]
    /// would (f evaluated afresh, the first step size chosen again, the controller's memory
    /// cleared), while the statistics keep counting: for a state moved to another chart of
    /// the same motion, say, after [`Adaptive::modify_system`] has switched the chart.
    /// [`Stepper::restart`](super::Stepper::restart) differs in keeping the step size and
    /// the controller's memory, for a run continued after an event.
    ///
    /// # Errors
    /// [`OdeError::NonFiniteTime`] or [`OdeError::NonFiniteInitialState`] for non-finite
    /// input, [`OdeError::NonFiniteState`] if f is not finite there, the system's
    /// [`System::check_parameters`] (a system changed by [`Adaptive::modify_system`] is checked
    /// again here); the integrator is left as it was on error.
    pub fn reinitialise(&mut self, t0: f64, y0: [f64; N]) -> Result<(), OdeError> {
        check_span(t0, t0)?;
        check_finite(&y0)?;
        self.sys.check_parameters()?;
        let mut f0 = [0.0; N];
        self.sys.rhs(t0, &y0, &mut f0);
        self.stats.rhs_evals += 1;
        if !all_finite(&f0) {
            return Err(non_finite(&self.sys, t0, (t0, &y0)));
        }
        // The next step takes f(t, y) from the FSAL stage once a step has been taken.
        self.k[0] = f0;
        self.k[P::FSAL] = f0;
        (self.t, self.y, self.t_prev, self.y_prev) = (t0, y0, t0, y0);
        self.dense_ready = false;
        self.refresh = false;
        (self.attempts, self.target) = (0, f64::NAN);
        self.control = PiController::new::<P>(&self.cfg);
        self.h = match self.cfg.h0 {
            Some(h) => h.min(self.cfg.h_max),
            None => self.initial_step(),
        };
        Ok(())
    }

    /// Takes one accepted step that does not pass `t_limit` (it lands on it exactly when close).
    ///
    /// # Errors
    /// [`OdeError::NonFiniteTime`] for a NaN or infinite `t_limit`,
    /// [`OdeError::StopBeforeCurrent`] if `t_limit < t`, [`OdeError::StepSizeUnderflow`],
    /// [`OdeError::NonFiniteState`], [`OdeError::MaxStepsExceeded`] after
    /// [`AdaptiveConfig::max_steps`] attempts towards the same `t_limit` (a restart or
    /// another limit starts the count again).
    pub fn step(&mut self, t_limit: f64) -> Result<(), OdeError> {
        check_stop(self.t, t_limit)?;
        if t_limit == self.t {
            return Ok(());
        }
        if t_limit != self.target {
            (self.attempts, self.target) = (0, t_limit);
        }
        if self.refresh {
            // The last step ended on a stop: f there was taken from the left; the new step
            // needs it from the right.
            self.sys.rhs(self.t, &self.y, &mut self.k[0]);
            self.stats.rhs_evals += 1;
            self.refresh = false;
        } else if self.stats.steps > 0 {
            self.k[0] = self.k[P::FSAL];
        }
        let mut y_new = [0.0; N];
        loop {
            self.attempts += 1;
            if self.attempts > self.cfg.max_steps {
                return Err(OdeError::MaxStepsExceeded {
                    t: self.t,
                    max_steps: self.cfg.max_steps,
                });
            }
            // Land exactly on the limit when it is within 1 % of a step (as DOPRI5 does).
            let clamped = self.t + 1.01 * self.h >= t_limit;
            let h = if clamped { t_limit - self.t } else { self.h };
            let t_hi = if clamped {
                t_limit.next_down()
            } else {
                f64::INFINITY
            };
            if self.t + h == self.t || h <= 4.0 * f64::EPSILON * self.t.abs() {
                return Err(OdeError::StepSizeUnderflow { t: self.t, h });
            }
            let (err, evals) = P::try_step(
                &self.sys,
                (self.t, h, t_hi),
                &self.y,
                &mut self.k,
                &mut y_new,
                (self.cfg.rtol, self.cfg.atol),
            );
            self.stats.rhs_evals += evals;
            if err.is_nan() || !all_finite(&y_new) {
                let step = (self.t, h, t_hi);
                return Err(P::explain_trial(&self.sys, step, &self.y, &self.k, &y_new));
            }
            if err <= 1.0 {
                let mut h_new = self.control.accepted(h, err);
                if clamped {
                    // A short landing step says little about the natural step size.
                    h_new = h_new.max(self.h);
                }
                let t_new = (self.t + h).min(t_hi);
                self.stats.rhs_evals += P::finish(&self.sys, t_new, &y_new, &mut self.k);
                self.refresh = clamped;
                self.stats.steps += 1;
                self.t_prev = self.t;
                self.y_prev = self.y;
                self.t = if clamped { t_limit } else { self.t + h };
                self.y = y_new;
                self.h = h_new;
                self.dense_ready = false;
                return Ok(());
            }
            self.stats.rejections += 1;
            self.h = self.control.rejected(h, err);
        }
    }

    /// Steps until `t == t_stop` exactly; no step crosses `t_stop`.
    ///
    /// # Errors
    /// As [`Self::step`]: a NaN or infinite `t_stop` is [`OdeError::NonFiniteTime`] before
    /// any work.
    pub fn advance_to(&mut self, t_stop: f64) -> Result<(), OdeError> {
        check_stop(self.t, t_stop)?;
        while self.t < t_stop {
            self.step(t_stop)?;
        }
        Ok(())
    }

    /// The dense output at `t` inside the last accepted step `[t_prev, t_now]`.
    ///
    /// The first call after a step builds the interpolant (DOP853: 3 evaluations).
    ///
    /// # Errors
    /// [`OdeError::NonFiniteTime`], [`OdeError::OutsideLastStep`].
    pub fn dense_at(&mut self, t: f64) -> Result<[f64; N], OdeError> {
        if !t.is_finite() {
            return Err(OdeError::NonFiniteTime { t });
        }
        if !(t >= self.t_prev && t <= self.t) {
            return Err(OdeError::OutsideLastStep {
                t,
                t_prev: self.t_prev,
                t_now: self.t,
            });
        }
        if t == self.t {
            return Ok(self.y);
        }
        let h = self.t - self.t_prev;
        if !self.dense_ready {
            self.stats.rhs_evals += P::dense_prepare(
                &self.sys,
                self.t_prev,
                h,
                &self.y_prev,
                &self.y,
                &mut self.k,
                &mut self.dense,
            );
            self.dense_ready = true;
        }
        let mut out = [0.0; N];
        P::dense_eval(&self.dense, (t - self.t_prev) / h, &mut out);
        Ok(out)
    }
}
