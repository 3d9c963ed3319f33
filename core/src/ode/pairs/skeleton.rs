//! The steps of the one stepping skeleton, [`EmbeddedPair`](super::EmbeddedPair)'s provided
//! methods: the stages, the weighted sums, the error estimates and the dense coefficients,
//! each over a pair's constant [`Tableau`](super::Tableau) data.
//!
//! Everything a pair is made of is a constant, so once the skeleton is inlined each row of A,
//! each stage's range test and each `match` on the estimate or the dense form is known at
//! compile time: the tableaux' zeros, the stages outside a range and the other pairs' arms
//! fold away, and each pair's machine code is what a hand-written step would be.

use std::ops::Range;

use super::tableau::ErrorEstimate;
use super::{DenseCoeffs, Stages};
use crate::ode::system::System;

/// `out = y + h Σ a_j k_j` over the row `a`.
#[inline(always)]
pub(super) fn stage_state<const N: usize>(
    y: &[f64; N],
    h: f64,
    a: &[f64],
    k: &Stages<N>,
    out: &mut [f64; N],
) {
    out.copy_from_slice(&weighted(a, k));
    for (o, yi) in out.iter_mut().zip(y) {
        *o = yi + h * *o;
    }
}

/// Σ_j w_j k_j, stage by stage (contiguous in N) and skipping the tableaux' many zeros.
#[inline(always)]
pub(super) fn weighted<const N: usize>(w: &[f64], k: &Stages<N>) -> [f64; N] {
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
pub(super) fn stages<S: System<N>, const N: usize>(
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

/// The first stage of the trial stages `0..end` whose f is not finite, as its time and the
/// state it was evaluated at (rebuilt from the finite stages before it), or `None`.
pub(super) fn failed_stage<const N: usize>(
    (t, h, t_hi): (f64, f64, f64),
    y: &[f64; N],
    (a, c): (&[&[f64]], &[f64]),
    end: usize,
    k: &Stages<N>,
) -> Option<(f64, [f64; N])> {
    (0..end).find_map(|s| {
        if k[s].iter().all(|v| v.is_finite()) {
            return None;
        }
        let mut ys = *y;
        if s > 0 {
            stage_state(y, h, a[s], k, &mut ys);
        }
        Some(((t + c[s] * h).min(t_hi), ys))
    })
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
pub(super) fn error_norm<const N: usize>(
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
                // b̂₃'s few non-zero weights, summed in place from −0 (which adds nothing,
                // not even a sign).
                let low = b3.iter().fold(-0.0, |acc, &(j, w)| acc + w * k[j][i]);
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
pub(super) fn hermite<const N: usize>(
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
pub(super) fn polynomial<const N: usize>(
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
