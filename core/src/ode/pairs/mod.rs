//! Embedded Runge–Kutta pairs: one trial step, its error norm and its dense output.
//!
//! Every method has one file in the same layout: its published tableau as private constants,
//! then its [`EmbeddedPair`] implementation (`dopri5.rs`, `dop853.rs`, `vern9.rs`). The
//! helpers every pair uses (stage evaluation, weighted sums, the error norm) live here.

mod dop853;
mod dopri5;
mod vern9;

pub use dop853::Dop853Pair;
pub use dopri5::Dopri5Pair;
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

/// `out = y + h Σ a_j k_j` over the row `a`.
#[inline(always)]
fn stage_state<const N: usize>(y: &[f64; N], h: f64, a: &[f64], k: &Stages<N>, out: &mut [f64; N]) {
    out.copy_from_slice(&weighted(a, k));
    for (o, yi) in out.iter_mut().zip(y) {
        *o = yi + h * *o;
    }
}

/// Σ_j w_j k_j, stage by stage (contiguous in N) and skipping the tableaux' many zeros.
#[inline(always)]
fn weighted<const N: usize>(w: &[f64], k: &Stages<N>) -> [f64; N] {
    let mut acc = [0.0; N];
    for (wj, kj) in w.iter().zip(k) {
        if *wj != 0.0 {
            for (a, v) in acc.iter_mut().zip(kj) {
                *a += wj * v;
            }
        }
    }
    acc
}

/// Evaluates stage `s` of the tableau `(a, c)` into `k`, for a step `(t, h)` whose stage
/// times are capped at `t_hi`.
#[inline(always)]
fn stage<S: System<N>, const N: usize>(
    sys: &S,
    (t, h, t_hi): (f64, f64, f64),
    y: &[f64; N],
    (a, c): (&[&[f64]], &[f64]),
    s: usize,
    k: &mut Stages<N>,
) {
    let mut ys = [0.0; N];
    stage_state(y, h, a[s], k, &mut ys);
    sys.rhs((t + c[s] * h).min(t_hi), &ys, &mut k[s]);
}

/// The tolerance scale of one component, `atol + rtol·max(|y|, |y_new|)`.
#[inline]
fn error_scale(y: f64, y_new: f64, (rtol, atol): (f64, f64)) -> f64 {
    atol + rtol * y.abs().max(y_new.abs())
}

/// The scaled local error norm of Hairer's codes, `√(mean((h eᵢ / skᵢ)²))` with skᵢ from
/// [`error_scale`], for an error estimate `e` (per unit step).
#[inline]
fn rms_error<const N: usize>(
    h: f64,
    e: &[f64; N],
    y: &[f64; N],
    y_new: &[f64; N],
    tol: (f64, f64),
) -> f64 {
    let mut acc = 0.0;
    for i in 0..N {
        let r = h * e[i] / error_scale(y[i], y_new[i], tol);
        acc += r * r;
    }
    (acc / N as f64).sqrt()
}

/// Stages listed one by one with literal indices: once inlined, each row of the constant
/// tableau is known, so its zeros and loop bounds fold away at compile time.
macro_rules! stages {
    ($sys:expr, $step:expr, $y:expr, $tab:expr, $k:expr; $($s:literal)+) => {
        $( $crate::ode::pairs::stage($sys, $step, $y, $tab, $s, $k); )+
    };
}
use stages;
