//! Named settings of the adaptive driver, with documented defaults.

use super::error::OdeError;

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
    /// Smallest ratio h_new/h after a step (default 0.2).
    pub fac_min: f64,
    /// Largest ratio h_new/h after a step (default 10).
    pub fac_max: f64,
    /// Integral gain of the PI controller, Hairer's β (default 0.04; 0 gives the I controller):
    /// h_new = h · safety · err^(−α) · err_prev^β with α = 1/(q+1) − 0.75 β.
    pub beta: f64,
    /// Largest number of step attempts before [`OdeError::MaxStepsExceeded`] (default 100 000).
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
            fac_min: 0.2,
            fac_max: 10.0,
            beta: 0.04,
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
        let pos = |v: f64| v.is_finite() && v > 0.0;
        if !pos(self.rtol) || !pos(self.atol) {
            return Err(OdeError::InvalidTolerance {
                rtol: self.rtol,
                atol: self.atol,
            });
        }
        if let Some(h) = self.h0
            && !pos(h)
        {
            return Err(OdeError::InvalidStep { h });
        }
        if self.h_max.is_nan() || self.h_max <= 0.0 {
            return Err(OdeError::InvalidStep { h: self.h_max });
        }
        let checks = [
            (
                "safety",
                self.safety,
                self.safety > 0.0 && self.safety <= 1.0,
            ),
            (
                "fac_min",
                self.fac_min,
                self.fac_min > 0.0 && self.fac_min < 1.0,
            ),
            (
                "fac_max",
                self.fac_max,
                self.fac_max > 1.0 && self.fac_max.is_finite(),
            ),
            ("beta", self.beta, (0.0..=0.2).contains(&self.beta)),
        ];
        for (name, value, ok) in checks {
            if !ok {
                return Err(OdeError::InvalidParameter { name, value });
            }
        }
        Ok(())
    }
}
