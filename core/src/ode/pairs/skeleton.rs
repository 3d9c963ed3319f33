//! The one stepping skeleton of the embedded pairs: any [`Tabulated`] pair is an
//! [`EmbeddedPair`] through it. A trial step makes the stages, the propagated solution and
//! the error estimate; an accepted step its stage at the new point; dense output its extra
//! stages and coefficients.
//!
//! Everything a pair is made of is a constant, so once the skeleton is inlined each row of A,
//! each stage's range test and each `match` on the estimate or the dense form is known at
//! compile time: the tableaux' zeros, the stages outside a range and the other pairs' arms
//! fold away, and each pair's machine code is what a hand-written step would be.

use std::ops::Range;

use super::tableau::{DenseOutput, ErrorEstimate, Tabulated};
use super::{ControllerGains, DenseCoeffs, EmbeddedPair, Stages};
use crate::ode::system::System;

impl<T: Tabulated> EmbeddedPair for T {
    const NAME: &'static str = T::TABLEAU.name;
    const ORDER: u32 = T::TABLEAU.order;
    const ERR_EXPONENT: f64 = T::TABLEAU.err_exponent;
    const FSAL: usize = T::TABLEAU.fsal;
    const GAINS: ControllerGains = T::TABLEAU.gains;

    fn try_step<S: System<N>, const N: usize>(
        sys: &S,
        (t, h, t_hi): (f64, f64, f64),
        y: &[f64; N],
        k: &mut Stages<N>,
        y_new: &mut [f64; N],
        tol: (f64, f64),
    ) -> (f64, u64) {
        let (a, c) = (T::TABLEAU.a, T::TABLEAU.c);
        stages(sys, (t, h, t_hi), y, (a, c), 1..T::TABLEAU.trial, k);
        // The increment Σ bⱼ kⱼ, made once: the solution and the estimate both read it.
        let increment = weighted(T::TABLEAU.b, k);
        for ((yn, yi), s) in y_new.iter_mut().zip(y).zip(&increment) {
            *yn = yi + h * s;
        }
        let mut evals = T::TABLEAU.trial as u64 - 1;
        if T::TABLEAU.fsal_in_trial {
            sys.rhs((t + h).min(t_hi), y_new, &mut k[T::TABLEAU.fsal]);
            evals += 1;
        }
        let err = error_norm(T::TABLEAU.error, h, &increment, (y, y_new), k, tol);
        (err, evals)
    }

    fn finish<S: System<N>, const N: usize>(
        sys: &S,
        t_new: f64,
        y_new: &[f64; N],
        k: &mut Stages<N>,
    ) -> u64 {
        if T::TABLEAU.fsal_in_trial {
            return 0;
        }
        sys.rhs(t_new, y_new, &mut k[T::TABLEAU.fsal]);
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
        let (a, c, fsal) = (T::TABLEAU.a, T::TABLEAU.c, T::TABLEAU.fsal);
        // The dense stages belong to the accepted step, which is over: no stop time caps them.
        stages(sys, (t, h, f64::INFINITY), y, (a, c), fsal + 1..a.len(), k);
        match T::TABLEAU.dense {
            DenseOutput::Hermite(rows) => hermite(h, (y, y_new), k, fsal, rows, d),
            DenseOutput::Polynomial(p) => polynomial(h, y, k, p, d),
        }
        (a.len() - fsal - 1) as u64
    }

    fn dense_eval<const N: usize>(d: &DenseCoeffs<N>, theta: f64, out: &mut [f64; N]) {
        // Horner's scheme from the last coefficient down; Hermite's form alternates θ and
        // 1 − θ as its factors (odd coefficients take 1 − θ).
        let (len, alternating) = match T::TABLEAU.dense {
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

/// Evaluates the stages in `range` in order, each through a call with a literal index (not a
/// loop): once inlined, the range is a constant, so the tests fold and each row of the
/// constant tableau is known, with its zeros and loop bounds folded away at compile time.
#[inline(always)]
fn stages<S: System<N>, const N: usize>(
    sys: &S,
    step: (f64, f64, f64),
    y: &[f64; N],
    tableau: (&[&[f64]], &[f64]),
    range: Range<usize>,
    k: &mut Stages<N>,
) {
    macro_rules! each {
        ($($s:literal)+) => {
            $( if range.contains(&$s) { stage(sys, step, y, tableau, $s, k); } )+
        };
    }
    // Every stage index a `Stages` array holds but the first (f(t, y), never made here).
    each!(1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20);
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
    (y, y_new): (&[f64; N], &[f64; N]),
    tol: (f64, f64),
) -> f64 {
    let mut acc = 0.0;
    for i in 0..N {
        let r = h * e[i] / error_scale(y[i], y_new[i], tol);
        acc += r * r;
    }
    (acc / N as f64).sqrt()
}

/// The error norm of a trial step by the pair's [`ErrorEstimate`], `increment` its
/// propagated Σⱼ bⱼ kⱼ.
#[inline(always)]
fn error_norm<const N: usize>(
    estimate: ErrorEstimate,
    h: f64,
    increment: &[f64; N],
    ys: (&[f64; N], &[f64; N]),
    k: &Stages<N>,
    tol: (f64, f64),
) -> f64 {
    match estimate {
        ErrorEstimate::Weights(e) => rms_error(h, &weighted(e, k), ys, tol),
        ErrorEstimate::Difference(b_hat) => {
            let other = weighted(b_hat, k);
            let e: [f64; N] = std::array::from_fn(|i| increment[i] - other[i]);
            rms_error(h, &e, ys, tol)
        }
        ErrorEstimate::Combined { e5, b3 } => {
            let e5v = weighted(e5, k);
            let (mut e3sum, mut e5sum) = (0.0, 0.0);
            for i in 0..N {
                // b̂₃ has three non-zero weights: summed in place, component by component,
                // over those alone and from −0 (which adds nothing, not even a sign).
                let low = b3
                    .iter()
                    .zip(k)
                    .filter(|(w, _)| **w != 0.0)
                    .fold(-0.0, |acc, (w, kj)| acc + w * kj[i]);
                let (e5, e3) = (e5v[i], increment[i] - low);
                let sk = error_scale(ys.0[i], ys.1[i], tol);
                e3sum += (e3 / sk) * (e3 / sk);
                e5sum += (e5 / sk) * (e5 / sk);
            }
            let mut deno = e5sum + 0.01 * e3sum;
            if deno <= 0.0 {
                deno = 1.0;
            }
            h.abs() * e5sum * (1.0 / (N as f64 * deno)).sqrt()
        }
    }
}

/// Hairer's dense coefficients: the cubic Hermite part from y, y_new, f₀ and f₁ = `k[fsal]`,
/// then h Σⱼ Dᵣⱼ kⱼ for each published row Dᵣ.
#[inline(always)]
fn hermite<const N: usize>(
    h: f64,
    (y, y_new): (&[f64; N], &[f64; N]),
    k: &Stages<N>,
    fsal: usize,
    rows: &[&[f64]],
    d: &mut DenseCoeffs<N>,
) {
    for i in 0..N {
        let dy = y_new[i] - y[i];
        let bspl = h * k[0][i] - dy;
        d[0][i] = y[i];
        d[1][i] = dy;
        d[2][i] = bspl;
        d[3][i] = dy - h * k[fsal][i] - bspl;
        for (r, row) in rows.iter().enumerate() {
            let mut s = 0.0;
            for (j, dj) in row.iter().enumerate() {
                s += dj * k[j][i];
            }
            d[4 + r][i] = h * s;
        }
    }
}

/// The coefficients of a polynomial interpolant: d₀ = y, dₚ = h Σⱼ Pⱼ,ₚ₋₁ kⱼ.
#[inline(always)]
fn polynomial<const N: usize>(
    h: f64,
    y: &[f64; N],
    k: &Stages<N>,
    p: &[[f64; 8]],
    d: &mut DenseCoeffs<N>,
) {
    d[0] = *y;
    for col in 0..8 {
        let w: [f64; 21] = std::array::from_fn(|j| p.get(j).map_or(0.0, |row| row[col]));
        let c = weighted(&w, k);
        for (di, ci) in d[col + 1].iter_mut().zip(c) {
            *di = h * ci;
        }
    }
}
