//! Named settings of the steppers, with documented defaults: the adaptive driver's and the
//! one fixed-step configuration shared by RK4 and the Lie-group RKMK4.

use super::error::{OdeError, check_stop};
#[cfg(doc)]
use super::pairs::ControllerGains;

/// Settings of the adaptive driver. Every field has a documented default
/// (`AdaptiveConfig::default()`), so callers override only what they mean.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AdaptiveConfig {
    /// Relative tolerance (default 1e-6). The local error of component i is held below
    /// `atol + rtol · max(|yᵢ|, |yᵢ_new|)` in the root-mean-square sense.
    pub rtol: f64,
    /// Absolute tolerance (default 1e-9).
    pub atol: f64,
    /// First step; `None` (default) uses Hairer's estimate, which costs one evaluation.
    pub h0: Option<f64>,
    /// Largest step (default +∞).
    pub h_max: f64,
    /// Safety factor on the proposed step (default 0.9).
    pub safety: f64,
    /// Smallest ratio h_new/h after a step; `None` (default) takes the pair's
    /// ([`ControllerGains`]: 0.2 for DOPRI5 and Vern9, 0.333 for DOP853).
    pub fac_min: Option<f64>,
    /// Largest ratio h_new/h after a step; `None` (default) takes the pair's (10 for DOPRI5
    /// and Vern9, 6 for DOP853).
    pub fac_max: Option<f64>,
    /// Integral gain of the PI controller, Hairer's β, in [0, 0.2] (0 is the I controller):
    /// h_new = h · safety · err^(−α) · err_prev^β with α = 1/(q+1) − w β, w the pair's
    /// `beta_weight`. `None` (default) takes the pair's: 0.04 for DOPRI5 and Vern9, 0 for
    /// DOP853, as Hairer's codes do.
    pub beta: Option<f64>,
    /// Largest number of step attempts towards one stop before
    /// [`OdeError::MaxStepsExceeded`] (default 100 000). The budget is per run: it counts
    /// the attempts towards the same stop time (one `advance_to`, a [`Run`](super::Run) to
    /// its end, an interval of [`solve`](super::solve) between stops) and starts again at a
    /// restart or a new stop, as CVODE's `mxstep` does, so a reused integrator never runs
    /// out of it; [`Stats`](super::Stats) keeps the whole count.
    pub max_steps: u64,
}

impl Default for AdaptiveConfig {
    fn default() -> Self {
        Self {
            rtol: 1e-6,
            atol: 1e-9,
            h0: None,
            h_max: f64::INFINITY,
            safety: 0.9,
            fac_min: None,
            fac_max: None,
            beta: None,
            max_steps: 100_000,
        }
    }
}

impl AdaptiveConfig {
    /// The default configuration with the given tolerances.
    ///
    /// ```
    /// let c = precess_core::ode::AdaptiveConfig::with_tol(1e-10, 1e-12);
    /// approx::assert_relative_eq!(c.rtol, 1e-10);
    /// ```
    pub fn with_tol(rtol: f64, atol: f64) -> Self {
        Self {
            rtol,
            atol,
            ..Self::default()
        }
    }

    /// Checks every field.
    ///
    /// # Errors
    /// [`OdeError::InvalidTolerance`], [`OdeError::InvalidStep`] or
    /// [`OdeError::InvalidParameter`] for the first field out of range.
    pub fn validate(&self) -> Result<(), OdeError> {
        check_tolerances(self.rtol, self.atol, self.h0, self.h_max)?;
        let checks = [
            (
                "safety",
                self.safety,
                self.safety > 0.0 && self.safety <= 1.0,
            ),
            (
                "fac_min",
                self.fac_min.unwrap_or(0.5),
                self.fac_min.is_none_or(|f| f > 0.0 && f < 1.0),
            ),
            (
                "fac_max",
                self.fac_max.unwrap_or(2.0),
                self.fac_max.is_none_or(|f| f > 1.0 && f.is_finite()),
            ),
            (
                "beta",
                self.beta.unwrap_or(0.0),
                self.beta.is_none_or(|b| (0.0..=0.2).contains(&b)),
            ),
        ];
        for (name, value, ok) in checks {
            if !ok {
                return Err(OdeError::InvalidParameter { name, value });
            }
        }
        Ok(())
    }
}

/// Settings of the fixed-step methods ([`Rk4`](super::Rk4) and the Lie-group
/// [`Rkmk4`](crate::rigid::Rkmk4)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FixedStepConfig {
    /// Largest step (default 1e-2). Each interval between stops is cut into the fewest equal
    /// steps no longer than this, so stop times are hit exactly.
    pub h: f64,
    /// Most steps one `advance_to` may take (default 10⁸, [`FixedStepConfig::MAX_STEPS`]). A
    /// call that needs more is refused with [`OdeError::TooManySteps`] before any work: a
    /// stop time or a step off by orders of magnitude fails at once instead of running for
    /// minutes. Like the adaptive driver's budget this is per run (here per call), and it is
    /// checked before stepping since the count is known in advance.
    pub max_steps: u64,
    /// Compensated summation of the state update (default `true`): RK4 carries the low-order
    /// bits that y + h·Σbᵢkᵢ rounds away beside the state and adds them back at the next
    /// step (TwoSum), so round-off grows like √n·h·ε instead of √n·ε and the error keeps
    /// falling with h. `false` is the plain update, kept to measure the difference.
    pub compensated: bool,
}

impl Default for FixedStepConfig {
    fn default() -> Self {
        Self {
            h: 1e-2,
            max_steps: Self::MAX_STEPS,
            compensated: true,
        }
    }
}

impl FixedStepConfig {
    /// The default of [`FixedStepConfig::max_steps`]: 10⁸ steps, a few seconds of a small
    /// system's RK4 and well beyond any span meant with a sensible step.
    pub const MAX_STEPS: u64 = 100_000_000;

    /// The default configuration with largest step `h`.
    ///
    /// ```
    /// let c = precess_core::ode::FixedStepConfig::with_step(1e-3);
    /// approx::assert_relative_eq!(c.h, 1e-3);
    /// assert_eq!(c.max_steps, 100_000_000);
    /// assert!(c.compensated);
    /// ```
    pub fn with_step(h: f64) -> Self {
        Self {
            h,
            ..Self::default()
        }
    }

    /// Checks the step.
    ///
    /// # Errors
    /// [`OdeError::InvalidStep`] for h ≤ 0 or non-finite.
    pub fn validate(&self) -> Result<(), OdeError> {
        if self.h.is_finite() && self.h > 0.0 {
            Ok(())
        } else {
            Err(OdeError::InvalidStep { h: self.h })
        }
    }

    /// The fewest equal steps no longer than `h` that take `t` exactly to `t_stop`, as
    /// (count, step); `None` when there is nothing to do.
    ///
    /// # Errors
    /// [`OdeError::NonFiniteTime`] for a NaN or infinite stop, [`OdeError::StopBeforeCurrent`],
    /// [`OdeError::TooManySteps`] beyond [`FixedStepConfig::max_steps`].
    pub(crate) fn plan(&self, t: f64, t_stop: f64) -> Result<Option<(u64, f64)>, OdeError> {
        check_stop(t, t_stop)?;
        let span = t_stop - t;
        if span == 0.0 {
            return Ok(None);
        }
        // The small slack keeps span = n·h from adding a step.
        let steps = ((span / self.h) * (1.0 - 1e-12)).ceil().max(1.0);
        if steps > self.max_steps as f64 {
            return Err(OdeError::TooManySteps {
                t,
                t_stop,
                h: self.h,
                steps,
                max_steps: self.max_steps,
            });
        }
        let n = steps as u64;
        Ok(Some((n, span / n as f64)))
    }
}

/// The checks every adaptive configuration shares (the pairs' and the Taylor integrator's):
/// finite positive tolerances, a finite positive step `h` if one is set, and a positive
/// `h_max` (infinite allowed).
///
/// # Errors
/// [`OdeError::InvalidTolerance`] for a tolerance, [`OdeError::InvalidStep`] for a step.
pub(crate) fn check_tolerances(
    rtol: f64,
    atol: f64,
    h: Option<f64>,
    h_max: f64,
) -> Result<(), OdeError> {
    let pos = |v: f64| v.is_finite() && v > 0.0;
    if !pos(rtol) || !pos(atol) {
        return Err(OdeError::InvalidTolerance { rtol, atol });
    }
    if let Some(h) = h
        && !pos(h)
    {
        return Err(OdeError::InvalidStep { h });
    }
    if h_max.is_nan() || h_max <= 0.0 {
        return Err(OdeError::InvalidStep { h: h_max });
    }
    Ok(())
}
