//! The step control of a batch's lanes in lane arithmetic: the step size (the weighted norms,
//! the radius and its guard rows, the bounds) and the sum (Horner with the slope, Kahan, the
//! time's two-sum) of every lane at once, on the batch's jet as it lies (a row is
//! `[Lanes<L>; N]`), each operation the scalar step's own on each lane, in the same order:
//! a lane's [`PendingStep`] is bit for bit the one the scalar code makes
//! ([`Taylor::lane_begin_ruled`]).
//!
//! Only the ordinary step is taken here: every lane at the same order p ≥ 2, its two top
//! rows finite and non-zero (the radius from rows p and p − 1), its step neither NaN nor too
//! small, its sum finite, checked ([`super::TaylorConfig::defect_check`]) and not fixed. A
//! lane outside it is left to the scalar code, which meets the case as a scalar run does.
//! The logarithms and exponentials stay the library's calls, one per lane, as in the scalar
//! step; the rest is loops over the lanes, which the compiler packs.

use super::lanes::PendingStep;
use super::radius::{RATIO, power};
use super::{GROWTH, StepRule, Taylor, defect};
use crate::taylor::TaylorSystem;
use crate::taylor::batch::Lanes;

/// `f64::max(a, b)` (IEEE maxNum: a NaN gives the other argument) written as a comparison,
/// for the loops over the lanes.
///
/// In pulp's AVX-512 copy of the batch's loop, rustc 1.95's LLVM compiled `f64::max` in
/// [`weighted_norm`]'s loop over 8 lanes (the full x86-v4 features: with AVX2, or AVX-512F
/// alone, it was right) to code that gave 6.8e18 for the norm of a row whose largest
/// weighted entry was 1.4e20. The radius of a derived top's first step came out 20 times
/// too small, and its lanes of 8 and 16 left their scalar runs' bits; an underestimated top
/// row would have given too long a step instead. The same loop written with a comparison
/// was right in every copy (a standalone reproduction: the baseline, AVX2, AVX-512F alone,
/// and x86-v4 with the comparison).
#[inline(always)]
fn max_num(a: f64, b: f64) -> f64 {
    if b > a || a.is_nan() { b } else { a }
}

/// `f64::min(a, b)` as a comparison, for the same reason as [`max_num`].
#[inline(always)]
fn min_num(a: f64, b: f64) -> f64 {
    if b < a || a.is_nan() { b } else { a }
}

/// maxᵢ |cᵢ|·wᵢ in every lane, as `radius::weighted_norm` (NaN skipped, as `f64::max` skips
/// it).
#[inline(always)]
fn weighted_norm<const N: usize, const L: usize>(c: &[Lanes<L>; N], w: &[[f64; L]; N]) -> [f64; L] {
    let mut m = [0.0f64; L];
    for (ci, wi) in c.iter().zip(w) {
        for l in 0..L {
            m[l] = max_num(m[l], ci.0[l].abs() * wi[l]);
        }
    }
    m
}

/// One component's Horner sum from its top row `top` down the rows `rows` (highest first),
/// with the slope's two running sums: (s, d, e) ← (s·h + cₖ, d·h + s, e·h + d) in every lane,
/// the scalar `defect::increment_and_slope`'s operations in its order. The lane loop is the
/// innermost, so the compiler packs the lanes and cannot vectorise across components.
#[inline(always)]
fn horner_with_slope<'a, const L: usize>(
    top: Lanes<L>,
    rows: impl Iterator<Item = &'a Lanes<L>>,
    h: &[f64; L],
) -> (Lanes<L>, Lanes<L>, Lanes<L>) {
    let (mut s, mut d, mut e) = (top.0, [0.0f64; L], [0.0f64; L]);
    for ck in rows {
        for l in 0..L {
            e[l] = e[l] * h[l] + d[l];
            d[l] = d[l] * h[l] + s[l];
            s[l] = s[l] * h[l] + ck.0[l];
        }
    }
    (Lanes(s), Lanes(d), Lanes(e))
}

impl<S: TaylorSystem<N>, const N: usize> Taylor<S, N> {
    /// The steps of the lanes `odes` (each with its rule, `None` for a lane without a step)
    /// towards `t_limit`, from the batch's jet `c` at their points: `Some` for the lanes
    /// summed here, `None` for those left to the scalar code.
    #[inline(always)]
    pub(crate) fn lanes_begin<const L: usize>(
        odes: [Option<(&Self, StepRule<N>)>; L],
        t_limit: [f64; L],
        c: &[[Lanes<L>; N]],
    ) -> [Option<PendingStep<N>>; L] {
        let p = odes
            .iter()
            .flatten()
            .map(|(_, r)| r.order)
            .min()
            .unwrap_or(0);
        let mut ok = odes.map(|o| {
            o.is_some_and(|(ode, r)| {
                r.order == p && ode.cfg.defect_check && ode.cfg.fixed_step.is_none()
            })
        });
        let base = (0..L).find(|&l| ok[l]).and_then(|l| odes[l]);
        let (Some(base), true) = (base, p >= 2 && c.len() > p) else {
            return [None; L];
        };
        // A lane outside takes an ordinary lane's values; its results are not read.
        let at: [(&Self, StepRule<N>); L] =
            core::array::from_fn(|l| odes[l].filter(|_| ok[l]).unwrap_or(base));
        let w: [[f64; L]; N] = core::array::from_fn(|i| at.map(|(_, r)| r.weights[i]));
        let (t, t_lo) = (at.map(|(o, _)| o.t), at.map(|(o, _)| o.t_lo));

        // The radius (`radius::radius`) from the rows k₁ = p and k₂ = p − 1.
        let (k1, k2) = (p, p - 1);
        let (n1, n2) = (weighted_norm(&c[k1], &w), weighted_norm(&c[k2], &w));
        let mut rho = [0.0f64; L];
        for l in 0..L {
            ok[l] &= n1[l].is_finite() && n1[l] > 0.0 && n2[l].is_finite() && n2[l] > 0.0;
            let (log_n1, log_n2) = (n1[l].ln(), n2[l].ln());
            let log_rho = min_num(
                min_num(-log_n1 / k1 as f64, -log_n2 / k2 as f64),
                RATIO.ln() + (log_n2 - log_n1) / (k1 - k2) as f64,
            );
            rho[l] = log_rho.exp();
        }
        let k1f = k1 as f64;
        let lowest = (k1 - k1.div_ceil(4)).max(1);
        for (k, row) in (lowest..).zip(c.get(lowest..k2).unwrap_or(&[])) {
            let n = weighted_norm(row, &w);
            let kf = k as f64;
            let mut x = [0.0f64; L];
            for l in 0..L {
                ok[l] &= n[l].is_finite();
                x[l] = n[l] * power(kf * rho[l] / k1f, k);
            }
            for l in 0..L {
                if x[l] > 1.0 {
                    rho[l] = min_num(rho[l], k1f / kf * (-n[l].ln() / k as f64).exp());
                }
            }
        }

        // The step size (`Taylor::step_size`).
        let (mut h, mut clamped) = ([0.0f64; L], [false; L]);
        for l in 0..L {
            let (ode, rule) = at[l];
            let natural = min_num(
                min_num(rule.factor * rho[l], GROWTH * ode.prev_natural),
                ode.cfg.h_max,
            );
            let remaining = (t_limit[l] - t[l]) - t_lo[l];
            clamped[l] = natural >= remaining;
            h[l] = if clamped[l] { remaining } else { natural };
            ok[l] &= !natural.is_nan() && h[l] > 0.0 && (clamped[l] || t[l] + h[l] != t[l]);
        }

        // The sum with the slope (`defect::increment_and_slope`), one component at a time
        // over its rows with the lanes innermost: with the components inside, the 8-lane
        // AVX-512 copy vectorised across the 6 components with gathers and scatters.
        let hl = Lanes(h);
        let mut s = [Lanes::<L>::splat(0.0); N];
        let (mut d, mut e) = (s, s);
        for i in 0..N {
            (s[i], d[i], e[i]) =
                horner_with_slope(c[p][i], c[1..p].iter().rev().map(|ck| &ck[i]), &h);
        }
        let (mut y_new, mut comp_new) = ([[0.0f64; L]; N], [[0.0f64; L]; N]);
        for i in 0..N {
            e[i] = e[i] * hl + d[i];
            d[i] = d[i] * hl + s[i];
            let y = Lanes(at.map(|(o, _)| o.y[i]));
            let inc = s[i] * hl - Lanes(at.map(|(o, _)| o.y_comp[i]));
            let sum = y + inc;
            comp_new[i] = ((sum - y) - inc).0;
            y_new[i] = sum.0;
        }
        let (d, e) = (d.map(|v| v.0), e.map(|v| v.0));
        for (l, o) in ok.iter_mut().enumerate() {
            *o &= y_new.iter().all(|v| v[l].is_finite());
        }
        core::array::from_fn(|l| {
            if !ok[l] {
                return None;
            }
            let (ode, rule) = at[l];
            let y_new = core::array::from_fn(|i| y_new[i][l]);
            let lane = |v: &[[f64; L]; N]| core::array::from_fn(|i| v[i][l]);
            Some(PendingStep {
                rule,
                h: h[l],
                clamped: clamped[l],
                t_limit: t_limit[l],
                comp_new: lane(&comp_new),
                slope: defect::Slope::new(p, h[l], lane(&d), lane(&e)),
                t_new: ode.advanced(h[l], clamped[l], t_limit[l]).0,
                y_new,
                order: ode.next_order(&y_new),
            })
        })
    }
}
