//! The step-size controller of the adaptive driver, on its own so that its coefficients can
//! change without touching the stepping loop.

use super::config::AdaptiveConfig;
use super::pairs::EmbeddedPair;

/// Hairer's PI step-size controller (HNW II, §IV.2; DOPRI5/DOP853's "Lund stabilisation"):
/// after a step with scaled error `err`,
/// h_new = h · safety · err^(−α) · err_prev^β, α = 1/(q+1) − w β (w = 0.75 for DOPRI5 and
/// 0.2 for DOP853, as in `dopri5.f` and `dop853.f`; β and the bounds default to the pair's
/// [`ControllerGains`](super::ControllerGains)),
/// with h_new/h held in [fac_min, fac_max], at most h_max, and not above h right after a
/// rejection. A rejected step is retried with the I controller alone,
/// h_new = h · min(safety · err^(−α), … ≥ fac_min).
///
/// It keeps ln err_prev (err_prev at least 1e-4, so one very accurate step does not inflate
/// the next) and whether the last attempt was rejected.
///
/// ```
/// use precess_core::ode::{AdaptiveConfig, Dop853Pair, Dopri5Pair, PiController};
/// let mut pi = PiController::new::<Dopri5Pair>(&AdaptiveConfig::default());
/// // An error of exactly 1 (just acceptable) shrinks the step by the safety factor, less the
/// // integral term's err_prev^β with err_prev = 1e-4 at the start (DOPRI5: β = 0.04).
/// let h = pi.accepted(1.0, 1.0);
/// approx::assert_relative_eq!(h, 0.9 * 1e-4f64.powf(0.04), max_relative = 1e-15);
/// // A large error cuts the step by at most fac_min = 0.2.
/// approx::assert_relative_eq!(pi.rejected(1.0, 1e6), 0.2);
///
/// // DOP853 as dop853.f: β = 0, so h_new = h · 0.9 · err^(−1/8), within [0.333, 6].
/// let mut pi = PiController::new::<Dop853Pair>(&AdaptiveConfig::default());
/// approx::assert_relative_eq!(pi.accepted(1.0, 1e-3), 0.9 * 1e-3f64.powf(-0.125), max_relative = 1e-15);
/// approx::assert_relative_eq!(pi.accepted(1.0, 1e-12), 6.0);
/// approx::assert_relative_eq!(pi.rejected(1.0, 1e6), 0.333);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PiController {
    /// α = 1/(q+1) − w β.
    alpha: f64,
    beta: f64,
    safety: f64,
    fac_min: f64,
    fac_max: f64,
    h_max: f64,
    /// ln of the last accepted error (at least 1e-4).
    ln_err_prev: f64,
    rejected_last: bool,
}

impl PiController {
    /// The controller of pair `P` (error exponent 1/(q+1): 0.2 for DOPRI5, 0.125 for DOP853,
    /// 1/9 for Vern9), with the gains and bounds `cfg` sets and the pair's
    /// [`ControllerGains`](super::ControllerGains) for those it leaves `None` (`cfg` assumed
    /// validated).
    pub fn new<P: EmbeddedPair>(cfg: &AdaptiveConfig) -> Self {
        let gains = P::GAINS;
        let beta = cfg.beta.unwrap_or(gains.beta);
        Self {
            alpha: P::ERR_EXPONENT - gains.beta_weight * beta,
            beta,
            safety: cfg.safety,
            fac_min: cfg.fac_min.unwrap_or(gains.fac_min),
            fac_max: cfg.fac_max.unwrap_or(gains.fac_max),
            h_max: cfg.h_max,
            ln_err_prev: 1e-4f64.ln(),
            rejected_last: false,
        }
    }

    /// The next step after accepting a step `h` with error `err` ≤ 1.
    pub fn accepted(&mut self, h: f64, err: f64) -> f64 {
        // err^α / err_prev^β through one ln and one exp (ln err_prev is kept).
        let fac = ((self.alpha * err.ln() - self.beta * self.ln_err_prev).exp() / self.safety)
            .clamp(1.0 / self.fac_max, 1.0 / self.fac_min);
        let mut h_new = (h / fac).min(self.h_max);
        if self.rejected_last {
            h_new = h_new.min(h);
        }
        self.ln_err_prev = err.max(1e-4).ln();
        self.rejected_last = false;
        h_new
    }

    /// The step to retry with after rejecting a step `h` with error `err` > 1.
    pub fn rejected(&mut self, h: f64, err: f64) -> f64 {
        self.rejected_last = true;
        h / ((self.alpha * err.ln()).exp() / self.safety).min(1.0 / self.fac_min)
    }
}
