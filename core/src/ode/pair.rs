//! Embedded Runge–Kutta pairs: one trial step, its error norm and its dense output.

use super::system::System;
use super::tableau::{
    DOP853_A, DOP853_BHH, DOP853_C, DOP853_D, DOP853_E5, DP5_A, DP5_C, DP5_D, DP5_E,
};

/// Stage storage shared by all pairs (DOP853 needs 16 with its dense-output stages,
/// Verner 9(8) 16, f at the new point and 4 interpolation stages).
pub type Stages<const N: usize> = [[f64; N]; 21];

/// Coefficients of the dense-output polynomial of the last step.
pub type DenseCoeffs<const N: usize> = [[f64; N]; 9];

/// An explicit embedded Runge–Kutta pair with FSAL and a continuous extension.
///
/// Implementations hold no data: the driver [`super::Adaptive`] owns the stages.
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
pub(crate) fn weighted<const N: usize>(w: &[f64], k: &Stages<N>) -> [f64; N] {
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
pub(crate) fn stage<S: System<N>, const N: usize>(
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
pub(crate) fn error_scale(y: f64, y_new: f64, (rtol, atol): (f64, f64)) -> f64 {
    atol + rtol * y.abs().max(y_new.abs())
}

/// The scaled local error norm of Hairer's codes, `√(mean((h eᵢ / skᵢ)²))` with skᵢ from
/// [`error_scale`], for an error estimate `e` (per unit step).
#[inline]
pub(crate) fn rms_error<const N: usize>(
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
        $( $crate::ode::pair::stage($sys, $step, $y, $tab, $s, $k); )+
    };
}
pub(crate) use stages;

/// Dormand–Prince 5(4) (DOPRI5): 6 evaluations per step, 4th-order dense output for free.
#[derive(Debug, Clone, Copy, Default)]
pub struct Dp54;

impl EmbeddedPair for Dp54 {
    const NAME: &'static str = "DOPRI5";
    const ORDER: u32 = 5;
    const ERR_EXPONENT: f64 = 0.2;
    const FSAL: usize = 6;

    fn try_step<S: System<N>, const N: usize>(
        sys: &S,
        (t, h, t_hi): (f64, f64, f64),
        y: &[f64; N],
        k: &mut Stages<N>,
        y_new: &mut [f64; N],
        (rtol, atol): (f64, f64),
    ) -> (f64, u64) {
        stages!(sys, (t, h, t_hi), y, (&DP5_A, &DP5_C), k; 1 2 3 4 5);
        stage_state(y, h, DP5_A[6], k, y_new);
        sys.rhs((t + h).min(t_hi), y_new, &mut k[6]);
        let e = weighted(&DP5_E, k);
        (rms_error(h, &e, y, y_new, (rtol, atol)), 6)
    }

    fn finish<S: System<N>, const N: usize>(
        _sys: &S,
        _t_new: f64,
        _y_new: &[f64; N],
        _k: &mut Stages<N>,
    ) -> u64 {
        0
    }

    fn dense_prepare<S: System<N>, const N: usize>(
        _sys: &S,
        _t: f64,
        h: f64,
        y: &[f64; N],
        y_new: &[f64; N],
        k: &mut Stages<N>,
        d: &mut DenseCoeffs<N>,
    ) -> u64 {
        for i in 0..N {
            let dy = y_new[i] - y[i];
            let bspl = h * k[0][i] - dy;
            d[0][i] = y[i];
            d[1][i] = dy;
            d[2][i] = bspl;
            d[3][i] = dy - h * k[6][i] - bspl;
            let mut s = 0.0;
            for (j, dj) in DP5_D.iter().enumerate() {
                s += dj * k[j][i];
            }
            d[4][i] = h * s;
        }
        0
    }

    fn dense_eval<const N: usize>(d: &DenseCoeffs<N>, theta: f64, out: &mut [f64; N]) {
        let th1 = 1.0 - theta;
        for (i, o) in out.iter_mut().enumerate() {
            *o = d[0][i] + theta * (d[1][i] + th1 * (d[2][i] + theta * (d[3][i] + th1 * d[4][i])));
        }
    }
}

/// Hairer's DOP853: an 8th-order pair with a 5th/3rd-order combined error estimate,
/// 12 evaluations per accepted step and a 7th-order dense output (3 more evaluations).
#[derive(Debug, Clone, Copy, Default)]
pub struct Dp853;

impl EmbeddedPair for Dp853 {
    const NAME: &'static str = "DOP853";
    const ORDER: u32 = 8;
    const ERR_EXPONENT: f64 = 0.125;
    const FSAL: usize = 12;

    fn try_step<S: System<N>, const N: usize>(
        sys: &S,
        (t, h, t_hi): (f64, f64, f64),
        y: &[f64; N],
        k: &mut Stages<N>,
        y_new: &mut [f64; N],
        (rtol, atol): (f64, f64),
    ) -> (f64, u64) {
        stages!(sys, (t, h, t_hi), y, (&DOP853_A, &DOP853_C), k; 1 2 3 4 5 6 7 8 9 10 11);
        stage_state(y, h, DOP853_A[12], k, y_new);
        // Hairer's estimate: err5² / √(err5² + 0.01 err3²) keeps the 8th-order step sizes
        // from being driven by a pessimistic 5th-order estimate.
        let (mut e3sum, mut e5sum) = (0.0, 0.0);
        let e5v = weighted(&DOP853_E5, k);
        let bk = weighted(DOP853_A[12], k);
        for i in 0..N {
            let e5 = e5v[i];
            let e3 = bk[i]
                - (DOP853_BHH[0] * k[0][i] + DOP853_BHH[1] * k[8][i] + DOP853_BHH[2] * k[11][i]);
            let sk = error_scale(y[i], y_new[i], (rtol, atol));
            e3sum += (e3 / sk) * (e3 / sk);
            e5sum += (e5 / sk) * (e5 / sk);
        }
        let mut deno = e5sum + 0.01 * e3sum;
        if deno <= 0.0 {
            deno = 1.0;
        }
        (h.abs() * e5sum * (1.0 / (N as f64 * deno)).sqrt(), 11)
    }

    fn finish<S: System<N>, const N: usize>(
        sys: &S,
        t_new: f64,
        y_new: &[f64; N],
        k: &mut Stages<N>,
    ) -> u64 {
        sys.rhs(t_new, y_new, &mut k[12]);
        1
    }

    fn dense_prepare<S: System<N>, const N: usize>(
        sys: &S,
        t: f64,
        h: f64,
        y: &[f64; N],
        y_new: &[f64; N],
        k: &mut Stages<N>,
        d: &mut DenseCoeffs<N>,
    ) -> u64 {
        stages!(sys, (t, h, f64::INFINITY), y, (&DOP853_A, &DOP853_C), k; 13 14 15);
        for i in 0..N {
            let dy = y_new[i] - y[i];
            let bspl = h * k[0][i] - dy;
            d[0][i] = y[i];
            d[1][i] = dy;
            d[2][i] = bspl;
            d[3][i] = dy - h * k[12][i] - bspl;
            for (r, row) in DOP853_D.iter().enumerate() {
                let mut s = 0.0;
                for (j, dj) in row.iter().enumerate() {
                    s += dj * k[j][i];
                }
                d[4 + r][i] = h * s;
            }
        }
        3
    }

    fn dense_eval<const N: usize>(d: &DenseCoeffs<N>, theta: f64, out: &mut [f64; N]) {
        let s = theta;
        let s1 = 1.0 - s;
        for (i, o) in out.iter_mut().enumerate() {
            let conpar = d[4][i] + s * (d[5][i] + s1 * (d[6][i] + s * d[7][i]));
            *o = d[0][i] + s * (d[1][i] + s1 * (d[2][i] + s * (d[3][i] + s1 * conpar)));
        }
    }
}
