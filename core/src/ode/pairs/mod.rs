//! Embedded Runge–Kutta pairs: one trial step, its error norm and its dense output.
//!
//! Every method has one file in the same layout: its published tableau as private constants,
//! then its [`Tableau`] (`dopri5.rs`, `dop853.rs`, `vern9.rs`). One skeleton
//! (`skeleton.rs`) makes every [`Tabulated`] pair an [`EmbeddedPair`]: the stages, the
//! propagated solution, the error estimate and the dense output are the same steps over
//! different data.

mod dop853;
mod dopri5;
mod skeleton;
mod tableau;
mod vern9;

pub use dop853::Dop853Pair;
pub use dopri5::Dopri5Pair;
pub use tableau::{DenseOutput, ErrorEstimate, Tableau, Tabulated};
pub use vern9::Vern9Pair;

use super::system::System;

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
/// Implementations hold no data: the driver [`Adaptive`](super::Adaptive) owns the stages.
/// Every [`Tabulated`] pair implements it through the one skeleton; a pair whose steps
/// its [`Tableau`] cannot describe implements it by hand.
pub trait EmbeddedPair {
    /// Human-readable name, e.g. `"DOP853"`.
    const NAME: &'static str;
    /// Order of the propagated solution.
    const ORDER: u32;
    /// Exponent of the error in the step-size controller, 1/(q + 1) for an estimate of order q
    /// (Hairer's choice: 1/5 for DOPRI5, 1/8 for DOP853).
    const ERR_EXPONENT: f64;
    /// Index of the stage that holds `f(t + h, y_new)` after an accepted step.
    const FSAL: usize;
    /// The step-size controller's defaults for this pair, used where
    /// [`AdaptiveConfig`](super::AdaptiveConfig) leaves them `None`.
    const GAINS: ControllerGains;

    /// Computes stages 2… from `k[0] = f(t, y)`, writes the solution to `y_new` and returns
    /// the scaled RMS error norm (≤ 1 means accept) and the number of `f` evaluations.
    /// Stage times are capped at `t_hi`: a step that ends on a stop time evaluates its last
    /// stages just before it, on the side of a switch that the step belongs to.
    /// `step` is (t, h, t_hi), `tol` is (rtol, atol).
    fn try_step<S: System<N>, const N: usize>(
        sys: &S,
        step: (f64, f64, f64),
        y: &[f64; N],
        k: &mut Stages<N>,
        y_new: &mut [f64; N],
        tol: (f64, f64),
    ) -> (f64, u64);

    /// Makes `k[FSAL] = f(min(t + h, t_hi), y_new)` available after acceptance; returns
    /// evaluations.
    fn finish<S: System<N>, const N: usize>(
        sys: &S,
        t_new: f64,
        y_new: &[f64; N],
        k: &mut Stages<N>,
    ) -> u64;

    /// Builds the dense-output coefficients of the accepted step `y → y_new`; returns evaluations.
    fn dense_prepare<S: System<N>, const N: usize>(
        sys: &S,
        t: f64,
        h: f64,
        y: &[f64; N],
        y_new: &[f64; N],
        k: &mut Stages<N>,
        d: &mut DenseCoeffs<N>,
    ) -> u64;

    /// Evaluates the dense output at θ = (t − t₀)/h ∈ [0, 1].
    fn dense_eval<const N: usize>(d: &DenseCoeffs<N>, theta: f64, out: &mut [f64; N]);
}
