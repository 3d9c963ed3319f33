//! The check of a summed step: the defect of the step polynomial at its end.
//!
//! The radius (the `radius` module) is estimated from the rows 0 … p the step computes, and
//! no estimate made from them can see rows that are tiny up to p and large past it. At
//! t₀ = 0.15, x' = P(t) y, y' = −P(t) x with P = 0.0306 t¹⁰ − 1.86 t¹³ has rows of order ≤ 6
//! of size 10⁻⁶ (powers of t₀, and the two terms nearly cancelling at order 6) and rows of
//! orders 7 … 14 of size 1: at 1e-4 (order 6) the rows gave a radius near 10 and the run
//! ended with an error of 0.69.
//!
//! After the sum, the step polynomial y_p(θ) = Σₖ c_k θᵏ is compared with the solution
//! through its end, whose jet d₀, d₁, d₂, … at t + h the next step needs anyway: its first
//! rows are d₁ = f(t + h, y_p(h)) and d₂ = f′/2 there. The polynomial re-expanded at its end
//! has the rows y_p′(h) and y_p″(h)/2, so the differences
//! - δ₁ = d₁ − y_p′(h), the defect of the polynomial against the equation, and
//! - δ₂ = d₂ − y_p″(h)/2, the same one order up,
//!
//! are those of the truncation error e(θ) ≈ c_{p+1} θ^(p+1): δ₁ ≈ (p + 1) e(h)/h and
//! δ₂ ≈ C(p + 1, 2) e(h)/h². The step's error is estimated from each, ‖δ₁‖·h/(p + 1) and
//! ‖δ₂‖·h²/C(p + 1, 2), each component at its own scale (the weights of the step rule), less
//! the rounding of the two terms, and the larger is the estimate. The step is kept when it is
//! at most ε: an ordinary step, sized for an error near e⁻²ᵖ⁻² ≈ e⁻⁴ε, passes with a margin of
//! about 50 and keeps its bits; a step that missed the growth of the solution has a defect of
//! the size of f and is taken again, shorter, from the same jet.
//!
//! Why the second row: a defect can vanish at the step's end by chance. x′ = cos t +
//! a s²⁰(1 − s/h) over the first step h from tₛ (s = t − tₛ) is invisible to the jet at tₛ
//! (no row below order 21) and has δ₁ = 0 at tₛ + h, so the step passed with an error of 2.2
//! at 1e-10. Its slope there is not zero: δ₂ = −a h¹⁹/2, an estimate 2.5 times the true
//! error at order 13. An earlier version took the defect at the step's middle for this,
//! Simpson's ⅔ h ‖δ(h/2)‖, at the price of one more evaluation of f; the second row is free.
//!
//! What the check costs: the jet at the step's end is the next step's, computed once and
//! kept (`Taylor::step`), so the check adds the Horner chains of y_p′(h) and y_p″(h)/2
//! beside the step's own sum, in the same pass, and N comparisons; the sums of the terms'
//! sizes, which bound the rounding, are summed only for a step whose estimate without them
//! fails (at the tightest tolerances, or a step to be refused). Only a
//! rejected step pays a jet more (the next jet of the shorter step). Where no next jet is
//! kept (the lanes, whose jets are packed, and the extended mode), the two rows are a jet of
//! order 2 at the end.
//!
//! It is an estimate from the value and the slope of the defect at one point, not a bound: a
//! defect that vanishes there to first order by chance passes.

use crate::taylor::TaylorSystem;

/// How much rounding the defect may carry, in units of the rounding of the rows and the
/// polynomial's: their difference cancels when the step is good, and a few ulps of each,
/// times the p terms of the sums, must not read as an error at the tightest tolerances.
const ROUNDING: f64 = 64.0 * f64::EPSILON;

/// The shortest a rejected step is cut to, and the longest, as fractions of it: the error
/// goes as h^(p+1), so the cut aims at 0.9·(ε/error)^(1/(p+1)), kept in these bounds so that
/// a wild estimate neither stalls the run nor barely changes the step.
const CUT: (f64, f64) = (0.1, 0.5);

/// The order of the jet a check needs at the step's end when no next jet is kept.
pub(super) const ORDER: usize = 2;

/// The step polynomial re-expanded at its end: y_p′(h) = Σₖ₌₁ᵖ k c_k hᵏ⁻¹ and
/// y_p″(h)/2 = Σₖ₌₂ᵖ C(k, 2) c_k hᵏ⁻² for every component. It belongs to the step of order
/// `p` and size `h` it was summed for.
#[derive(Debug, Clone, Copy)]
pub(super) struct Slope<const N: usize> {
    p: usize,
    h: f64,
    value: [f64; N],
    second: [f64; N],
}

impl<const N: usize> Slope<N> {
    /// The slope of the step of order `p` and size `h` whose re-expanded rows are `value`
    /// (y_p′(h)) and `second` (y_p″(h)/2), summed elsewhere (the lanes).
    pub(super) fn new(p: usize, h: f64, value: [f64; N], second: [f64; N]) -> Self {
        Self {
            p,
            h,
            value,
            second,
        }
    }
}

/// C(k, 2) = k(k − 1)/2, the weight of c_k hᵏ⁻² in y_p″(h)/2.
fn binomial(k: f64) -> f64 {
    0.5 * k * (k - 1.0)
}

/// The step's increment Σₖ₌₁ᵖ c_k hᵏ and its [`Slope`] in one pass over the rows (p ≥ 1),
/// by Horner with the order outside and the derivatives by repeated synthetic division (each
/// chain one multiply-add a term: e ← e·h + d, d ← d·h + s, s ← s·h + c_k). The increment's
/// operations are those of the step's own sum (`horner_increment`), so its bits are; the
/// slope's chains run beside it, where a second pass would wait on each chain again.
pub(super) fn increment_and_slope<const N: usize>(c: &[[f64; N]], h: f64) -> ([f64; N], Slope<N>) {
    let p = c.len().saturating_sub(1);
    let zero = [0.0; N];
    let Some((top, lower)) = c.split_last().filter(|_| p >= 1) else {
        let slope = Slope {
            p,
            h,
            value: zero,
            second: zero,
        };
        return (zero, slope);
    };
    let (mut s, mut d, mut e) = (*top, zero, zero);
    for ck in lower.iter().skip(1).rev() {
        for (((si, di), ei), cki) in s.iter_mut().zip(&mut d).zip(&mut e).zip(ck) {
            *ei = *ei * h + *di;
            *di = *di * h + *si;
            *si = *si * h + cki;
        }
    }
    // The last division (by the order 0) for the derivatives; the increment is s·h.
    for ((si, di), ei) in s.iter().zip(&mut d).zip(&mut e) {
        *ei = *ei * h + *di;
        *di = *di * h + si;
    }
    let slope = Slope {
        p,
        h,
        value: d,
        second: e,
    };
    (s.map(|si| si * h), slope)
}

/// The sums of the sizes of the terms of y_p′(h) and of y_p″(h)/2, Σₖ k |c_k| hᵏ⁻¹ and
/// Σₖ C(k, 2) |c_k| hᵏ⁻², which bound their rounding (an oscillating solution's terms can be
/// far larger than their sum). Only a step whose estimate without them is above ε needs
/// them: a second pass over its rows, not a cost of every step.
fn sizes<const N: usize>(c: &[[f64; N]], h: f64) -> ([f64; N], [f64; N]) {
    let (mut first, mut second) = ([0.0; N], [0.0; N]);
    for (k, row) in c.iter().enumerate().skip(1).rev() {
        let (kf, bk) = (k as f64, binomial(k as f64));
        for i in 0..N {
            first[i] = first[i] * h + kf * row[i].abs();
            if k >= 2 {
                second[i] = second[i] * h + bk * row[i].abs();
            }
        }
    }
    (first, second)
}

/// The estimated error of the step whose polynomial has the slope `slope`, in units of the
/// step's tolerance, from the rows d₁ (`rows[0]`) and, if given, d₂ (`rows[1]`) of the jet
/// at its end: the larger of ‖δ₁‖_w·h/(p + 1) and ‖δ₂‖_w·h²/C(p + 1, 2), the weights `w`
/// those of the step rule, each defect less its own rounding when `sizes` (the terms' sizes
/// of the two sums) are given. NaN when a row or the polynomial is not finite (the caller
/// treats it as a failed check, and the new state's own check names it).
fn error<const N: usize>(
    slope: &Slope<N>,
    rows: &[[f64; N]],
    w: &[f64; N],
    sizes: Option<&([f64; N], [f64; N])>,
) -> f64 {
    let (h, p1) = (slope.h, slope.p as f64 + 1.0);
    let first = rows
        .first()
        .map_or(0.0, |d1| excess(d1, &slope.value, sizes.map(|s| &s.0), w));
    let second = rows
        .get(1)
        .map_or(0.0, |d2| excess(d2, &slope.second, sizes.map(|s| &s.1), w));
    if first.is_nan() || second.is_nan() {
        return f64::NAN;
    }
    (first * h / p1).max(second * h * h / (0.5 * p1 * slope.p as f64))
}

/// ‖d − y‖_w, less the rounding of the two when `sizes` (the sum of the polynomial's terms'
/// sizes) is given: `d` a row of the jet at the step's end, `y` the polynomial's. NaN if any
/// component is.
fn excess<const N: usize>(
    d: &[f64; N],
    y: &[f64; N],
    sizes: Option<&[f64; N]>,
    w: &[f64; N],
) -> f64 {
    let mut worst = 0.0f64;
    for i in 0..N {
        let rounding = sizes.map_or(0.0, |s| ROUNDING * (d[i].abs() + s[i]));
        let e = ((d[i] - y[i]).abs() - rounding) * w[i];
        if e.is_nan() {
            return f64::NAN;
        }
        worst = worst.max(e);
    }
    worst
}

/// The rows d₁, d₂ of the jet at `(t, y)` when no next jet is kept: a jet of order
/// [`ORDER`] (its row 0 is `y`).
pub(super) fn end_rows<S: TaylorSystem<N>, const N: usize>(
    sys: &S,
    ws: &mut S::Workspace,
    t: f64,
    y: &[f64; N],
) -> [[f64; N]; ORDER + 1] {
    let mut rows = [[0.0; N]; ORDER + 1];
    sys.coefficients_into(ws, t, y, ORDER, &mut rows);
    rows
}

/// `None` when the step of the jet `c` whose polynomial has the slope `slope` passes the
/// defect check at tolerance `eps` with weights `w`, given the rows d₁, d₂ (or d₁ alone) of
/// the jet at its end in `rows`; otherwise the shorter step to take again from the same jet.
/// The rounding of the sums is allowed for only when the estimate without it fails.
pub(super) fn shorter_step<const N: usize>(
    c: &[[f64; N]],
    slope: &Slope<N>,
    rows: &[[f64; N]],
    w: &[f64; N],
    eps: f64,
) -> Option<f64> {
    let h = slope.h;
    if error(slope, rows, w, None) <= eps {
        return None;
    }
    let err = error(slope, rows, w, Some(&sizes(c, h)));
    if err <= eps {
        return None;
    }
    let p = slope.p as f64;
    // A NaN estimate (f not finite at the new state) is cut by the most: the state itself is
    // refused by the commit if it is not finite, and a shorter step may stay where f is.
    let aim = 0.9 * (eps / err).powf(1.0 / (p + 1.0));
    let fraction = if aim.is_nan() {
        CUT.0
    } else {
        aim.clamp(CUT.0, CUT.1)
    };
    Some(h * fraction)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// y' = −y, c_k = (−1)ᵏ/k! at y = 1.
    struct Decay;
    impl TaylorSystem<1> for Decay {
        fn max_order(&self) -> usize {
            40
        }
        type Workspace = ();
        fn coefficients_into(
            &self,
            _ws: &mut (),
            _t: f64,
            y: &[f64; 1],
            order: usize,
            c: &mut [[f64; 1]],
        ) {
            c[0] = *y;
            for k in 1..=order {
                c[k][0] = -c[k - 1][0] / k as f64;
            }
        }
    }

    fn jet(p: usize) -> Vec<[f64; 1]> {
        let mut c = vec![[0.0]; p + 1];
        Decay.coefficients_into(&mut (), 0.0, &[1.0], p, &mut c);
        c
    }

    #[test]
    fn the_slope_is_the_polynomial_s_and_the_increment_the_step_s() {
        // c = (1, 2, −3, 4): y′(h) = 2 − 6h + 12h², its terms' sizes 2 + 6h + 12h²;
        // y″(h)/2 = −3 + 12h, sizes 3 + 12h; the increment 2h − 3h² + 4h³.
        let c = [[1.0], [2.0], [-3.0], [4.0]];
        let (inc, slope) = increment_and_slope(&c, 0.5);
        assert_eq!((inc, slope.value, slope.second), ([0.75], [2.0], [3.0]));
        assert_eq!(sizes(&c, 0.5), ([8.0], [9.0]));
    }

    /// The check of the step of size `h` from y = 1 with the jet `c`, against the jet of
    /// Decay at its end.
    fn check(c: &[[f64; 1]], h: f64) -> Option<f64> {
        let (inc, slope) = increment_and_slope(c, h);
        let rows = end_rows(&Decay, &mut (), h, &[c[0][0] + inc[0]]);
        shorter_step(c, &slope, &rows[1..], &[1.0], 1e-10)
    }

    #[test]
    fn an_ordinary_step_passes_and_a_long_one_is_cut() {
        // Order 13, ε = 1e-10: a step of 0.7 has an estimated error near 8e-14 and passes.
        let c = jet(13);
        assert_eq!(check(&c, 0.7), None);
        // A step of 3 has an estimated error near 5e-5 ≫ 1e-10: cut to between 0.3 and 1.5.
        let cut = check(&c, 3.0);
        assert!(
            matches!(cut, Some(h) if (0.3..=1.5).contains(&h)),
            "{cut:?}"
        );
    }

    #[test]
    fn both_estimates_are_within_a_small_factor_of_the_true_error() {
        // At order 6 and h = 1 the truncation error of e^(−1) is ≈ 1/7! − 1/8! … = 1.76e-4;
        // the estimates from d₁ and from d₂ should each be within a factor 2 of it.
        let c = jet(6);
        let (inc, slope) = increment_and_slope(&c, 1.0);
        let y = [1.0 + inc[0]];
        let truth = (y[0] - (-1.0f64).exp()).abs();
        let rows = end_rows(&Decay, &mut (), 1.0, &y);
        let sz = sizes(&c, 1.0);
        let second = excess(&rows[2], &slope.second, Some(&sz.1), &[1.0]) / 21.0;
        let first = error(&slope, &rows[1..2], &[1.0], Some(&sz));
        for (name, est) in [("d1", first), ("d2", second)] {
            assert!(
                est > 0.5 * truth && est < 2.0 * truth,
                "{name}: {est:e} against {truth:e}"
            );
        }
    }
}
