//! Embedded Runge–Kutta pairs: one trial step, its error norm and its dense output.
//!
//! Every method has one file in the same layout: its published tableau as private constants,
//! then its [`Tableau`] (`dopri5.rs`, `dop853.rs`, `vern9.rs`). [`EmbeddedPair`]'s provided
//! methods are the one skeleton that steps them all (its steps in `skeleton.rs`): the
//! stages, the propagated solution, the error estimate and the dense output are the same
//! steps over different data.

mod dop853;
mod dopri5;
mod skeleton;
mod tableau;
mod vern9;

pub use dop853::Dop853Pair;
pub use dopri5::Dopri5Pair;
pub use tableau::{DenseOutput, ErrorEstimate, Tableau};
pub use vern9::Vern9Pair;

use super::error::OdeError;
use super::system::{System, non_finite};
use skeleton::{error_norm, failed_stage, hermite, polynomial, stages, weighted};

/// Stage storage shared by all pairs (DOP853 needs 16 with its dense-output stages,
/// Verner 9(8) 16, f at the new point and 4 interpolation stages).
pub type Stages<const N: usize> = [[f64; N]; 21];

/// Coefficients of the dense-output polynomial of the last step.
pub type DenseCoeffs<const N: usize> = [[f64; N]; 9];

/// Defaults of the PI step-size controller for one pair, as in Hairer's codes (HNW I §II.4,
/// and the `dopri5.f` / `dop853.f` sources): h_new = h · safety · err^(−α) · err_prev^β with
/// α = 1/(q+1) − `beta_weight` · β, and h_new/h held in [`fac_min`, `fac_max`].
///
/// | pair | β | `beta_weight` | `fac_min` | `fac_max` |
/// |---|---|---|---|---|
/// | DOPRI5 (`dopri5.f`) | 0.04 | 0.75 | 0.2 | 10 |
/// | DOP853 (`dop853.f`) | 0 | 0.2 | 0.333 | 6 |
/// | Vern9 (no reference code: DOPRI5's, which measured better than DOP853's here) | 0.04 | 0.75 | 0.2 | 10 |
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ControllerGains {
    /// Hairer's β, the weight of the previous error (0: the I controller).
    pub beta: f64,
    /// The factor of β in α = 1/(q+1) − `beta_weight` · β.
    pub beta_weight: f64,
    /// Smallest ratio h_new/h.
    pub fac_min: f64,
    /// Largest ratio h_new/h.
    pub fac_max: f64,
}

/// An explicit embedded Runge–Kutta pair with FSAL and a continuous extension.
///
/// A pair is its published [`Tableau`]: the provided methods are the one stepping skeleton
/// every pair shares (the stages, the propagated solution, the error estimate, the dense
/// output), and the constants below are read from the tableau. Implementations hold no data:
/// the driver [`Adaptive`](super::Adaptive) owns the stages.
///
/// ```
/// use precess_core::ode::{Dopri5Pair, EmbeddedPair};
/// assert_eq!(Dopri5Pair::NAME, Dopri5Pair::TABLEAU.name);
/// assert_eq!((Dopri5Pair::ORDER, Dopri5Pair::FSAL), (5, 6));
/// ```
pub trait EmbeddedPair {
    /// The pair's published data.
    const TABLEAU: Tableau;
    /// Human-readable name, e.g. `"DOP853"`.
    const NAME: &'static str = Self::TABLEAU.name;
    /// Order of the propagated solution.
    const ORDER: u32 = Self::TABLEAU.order;
    /// Exponent of the error in the step-size controller, 1/(q + 1) for an estimate of order q
    /// (Hairer's choice: 1/5 for DOPRI5, 1/8 for DOP853).
    const ERR_EXPONENT: f64 = Self::TABLEAU.err_exponent;
    /// Index of the stage that holds `f(t + h, y_new)` after an accepted step.
    const FSAL: usize = Self::TABLEAU.fsal;
    /// The step-size controller's defaults for this pair, used where
    /// [`AdaptiveConfig`](super::AdaptiveConfig) leaves them `None`.
    const GAINS: ControllerGains = Self::TABLEAU.gains;

    /// Computes stages 2… from `k[0] = f(t, y)`, writes the solution to `y_new` and returns
    /// the scaled RMS error norm (≤ 1 means accept) and the number of `f` evaluations.
    /// Stage times are capped at `t_hi`: a step that ends on a stop time evaluates its last
    /// stages just before it, on the side of a switch that the step belongs to.
    /// `step` is (t, h, t_hi), `tol` is (rtol, atol).
    fn try_step<S: System<N>, const N: usize>(
        sys: &S,
        (t, h, t_hi): (f64, f64, f64),
        y: &[f64; N],
        k: &mut Stages<N>,
        y_new: &mut [f64; N],
        tol: (f64, f64),
    ) -> (f64, u64) {
        let (a, c) = (Self::TABLEAU.a, Self::TABLEAU.c);
        stages(sys, (t, h, t_hi), y, (a, c), 1..Self::TABLEAU.trial, k);
        // The increment Σ bⱼ kⱼ, made once: the solution and the estimate both read it.
        let increment = weighted(Self::TABLEAU.b, k);
        for ((yn, yi), s) in y_new.iter_mut().zip(y).zip(&increment) {
            *yn = yi + h * s;
        }
        let mut evals = Self::TABLEAU.trial as u64 - 1;
        if Self::TABLEAU.fsal_in_trial {
            sys.rhs((t + h).min(t_hi), y_new, &mut k[Self::TABLEAU.fsal]);
            evals += 1;
        }
        let err = error_norm(Self::TABLEAU.error, h, &increment, (y, y_new), k, tol);
        (err, evals)
    }

    /// The error of a trial step ([`EmbeddedPair::try_step`] with the same arguments) whose
    /// result is not finite: the system's explanation
    /// ([`System::explain_non_finite`]) at the first stage whose f is not finite, else
    /// [`OdeError::NonFiniteState`] at the step's start `t`. Off the stepping path: called
    /// once, when the step has failed.
    fn explain_trial<S: System<N>, const N: usize>(
        sys: &S,
        (t, h, t_hi): (f64, f64, f64),
        y: &[f64; N],
        k: &Stages<N>,
        y_new: &[f64; N],
    ) -> OdeError {
        let tableau = (Self::TABLEAU.a, Self::TABLEAU.c);
        if let Some((ts, ys)) = failed_stage((t, h, t_hi), y, tableau, Self::TABLEAU.trial, k) {
            return non_finite(sys, t, (ts, &ys));
        }
        let fsal = &k[Self::TABLEAU.fsal];
        if Self::TABLEAU.fsal_in_trial && fsal.iter().any(|v| !v.is_finite()) {
            return non_finite(sys, t, ((t + h).min(t_hi), y_new));
        }
        OdeError::NonFiniteState { t }
    }

    /// Makes `k[FSAL] = f(min(t + h, t_hi), y_new)` available after acceptance; returns
    /// evaluations.
    fn finish<S: System<N>, const N: usize>(
        sys: &S,
        t_new: f64,
        y_new: &[f64; N],
        k: &mut Stages<N>,
    ) -> u64 {
        if Self::TABLEAU.fsal_in_trial {
            return 0;
        }
        sys.rhs(t_new, y_new, &mut k[Self::TABLEAU.fsal]);
        1
    }

    /// Builds the dense-output coefficients of the accepted step `y → y_new`; returns evaluations.
    fn dense_prepare<S: System<N>, const N: usize>(
        sys: &S,
        t: f64,
        h: f64,
        y: &[f64; N],
        y_new: &[f64; N],
        k: &mut Stages<N>,
        d: &mut DenseCoeffs<N>,
    ) -> u64 {
        let (a, c, fsal) = (Self::TABLEAU.a, Self::TABLEAU.c, Self::TABLEAU.fsal);
        // The dense stages belong to the accepted step, which is over: no stop time caps them.
        stages(sys, (t, h, f64::INFINITY), y, (a, c), fsal + 1..a.len(), k);
        match Self::TABLEAU.dense {
            DenseOutput::Hermite(rows) => hermite(h, (y, y_new), k, fsal, rows, d),
            DenseOutput::Polynomial(p) => polynomial(h, y, k, p, d),
        }
        (a.len() - fsal - 1) as u64
    }

    /// Evaluates the dense output at θ = (t − t₀)/h ∈ [0, 1].
    fn dense_eval<const N: usize>(d: &DenseCoeffs<N>, theta: f64, out: &mut [f64; N]) {
        // Horner's scheme from the last coefficient down; Hermite's form alternates θ and
        // 1 − θ as its factors (odd coefficients take 1 − θ).
        let (len, alternating) = match Self::TABLEAU.dense {
            DenseOutput::Hermite(rows) => (4 + rows.len(), true),
            DenseOutput::Polynomial(_) => (9, false),
        };
        let th1 = 1.0 - theta;
        for (i, o) in out.iter_mut().enumerate() {
            let mut acc = d[len - 1][i];
            for j in (0..len - 1).rev() {
                let f = if alternating && j % 2 == 1 {
                    th1
                } else {
                    theta
                };
                acc = d[j][i] + f * acc;
            }
            *o = acc;
        }
    }
}
