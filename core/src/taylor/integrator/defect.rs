//! The check of a summed step: the defect of the step polynomial at its end.
//!
//! The radius (the `radius` module) is estimated from the rows 0 … p the step computes, and
//! no estimate made from them can see rows that are tiny up to p and large past it. At
//! t₀ = 0.15, x' = P(t) y, y' = −P(t) x with P = 0.0306 t¹⁰ − 1.86 t¹³ has rows of order ≤ 6
//! of size 10⁻⁶ (powers of t₀, and the two terms nearly cancelling at order 6) and rows of
//! orders 7 … 14 of size 1: at 1e-4 (order 6) the rows gave a radius near 10 and the run
//! ended with an error of 0.69.
//!
//! After the sum, the step polynomial y_p(θ) = Σₖ c_k θᵏ is compared with the equation at
//! the step's end: the defect δ = f(t + h, y_p(h)) − y_p′(h). For a truncation error
//! e(θ) ≈ c_{p+1} θ^(p+1), δ ≈ e′(h) = (p + 1) e(h)/h, so the step's error is estimated as
//! ‖δ‖·h/(p + 1), each component at its own scale (the weights of the step rule). The step
//! is kept when that is at most ε: an ordinary step, sized for an error near e⁻²ᵖ⁻² ≈ e⁻⁴ε,
//! passes with a margin of about 50 and keeps its bits; a step that missed the growth of the
//! solution has a defect of the size of f and is taken again, shorter, from the same jet.
//!
//! The defect is also taken at the step's middle, where it costs one more evaluation of f
//! and three more Horner chains in the same pass. The error of the step is, to first order
//! over a short step, the integral of the defect, e(h) ≈ ∫₀ʰ δ, and Simpson's rule
//! h/6·(δ(0) + 4 δ(h/2) + δ(h)) gives the middle its own estimate ⅔ h ‖δ(h/2)‖ (δ(0) = 0:
//! the jet is exact at the start). A defect that vanishes at the end by chance no longer
//! passes: x′ = cos t + a t²⁰(1 − t/h) over the first step h has δ(h) = 0 to rounding and
//! an error of 2.2 at 1e-10, and its middle has δ = a (h/2)²⁰/2. For the truncation error
//! of an ordinary step, δ(θ) ∝ θᵖ, the middle's estimate is ⅔/2ᵖ of ‖δ(h)‖h against the
//! end's 1/(p + 1), smaller for every p ≥ 1, so no step the end's estimate kept is refused
//! by it and every such run keeps its bits.
//!
//! The check costs two evaluations of f (the system's jet to order 1) and the Horner sums,
//! a few per cent of a step. It is an estimate at two points, not a bound: a defect that
//! vanishes at both by chance passes.

use crate::taylor::TaylorSystem;

/// How much rounding the defect may carry, in units of the rounding of f and y_p′: their
/// difference cancels when the step is good, and a few ulps of each, times the p terms of
/// the derivative, must not read as an error at the tightest tolerances.
const ROUNDING: f64 = 64.0 * f64::EPSILON;

/// The shortest a rejected step is cut to, and the longest, as fractions of it: the error
/// goes as h^(p+1), so the cut aims at 0.9·(ε/error)^(1/(p+1)), kept in these bounds so that
/// a wild estimate neither stalls the run nor barely changes the step.
const CUT: (f64, f64) = (0.1, 0.5);

/// The evaluations of f one check costs: at the step's end and at its middle.
pub(super) const EVALUATIONS: u64 = 2;

/// Simpson's weight of the middle's defect in ∫₀ʰ δ ≈ h/6·(δ(0) + 4 δ(h/2) + δ(h)).
const MIDDLE: f64 = 2.0 / 3.0;

/// y_p′(h) = Σₖ₌₁ᵖ k c_k hᵏ⁻¹ for every component, and the same sum of the terms' sizes
/// Σₖ k |c_k| hᵏ⁻¹, which bounds its rounding (an oscillating solution's terms can be far
/// larger than their sum); and at the middle, y_p(h/2) with y_p′(h/2) and its sizes.
/// It belongs to the step of order `p` and size `h` it was summed for.
#[derive(Debug, Clone, Copy)]
pub(super) struct Slope<const N: usize> {
    p: usize,
    h: f64,
    value: [f64; N],
    sizes: [f64; N],
    middle: [f64; N],
    middle_value: [f64; N],
    middle_sizes: [f64; N],
}

/// The step's increment Σₖ₌₁ᵖ c_k hᵏ and its [`Slope`] in one pass over the rows (p ≥ 1),
/// by Horner with the order outside: the increment's operations are those of the step's own
/// sum (`horner_increment`), so its bits are; the slope's two chains run beside it, where
/// a second pass would wait on each chain again.
pub(super) fn increment_and_slope<const N: usize>(c: &[[f64; N]], h: f64) -> ([f64; N], Slope<N>) {
    let p = c.len().saturating_sub(1);
    let Some(top) = c.get(p).filter(|_| p >= 1) else {
        let zero = [0.0; N];
        let slope = Slope {
            p,
            h,
            value: zero,
            sizes: zero,
            middle: c.first().copied().unwrap_or(zero),
            middle_value: zero,
            middle_sizes: zero,
        };
        return (zero, slope);
    };
    let (pf, m) = (p as f64, 0.5 * h);
    let mut s = *top;
    let mut value = top.map(|v| pf * v);
    let mut sizes = top.map(|v| pf * v.abs());
    let (mut ms, mut mvalue, mut msizes) = (s, value, sizes);
    for k in (1..p).rev() {
        let kf = k as f64;
        for i in 0..N {
            let cki = c[k][i];
            s[i] = s[i] * h + cki;
            value[i] = value[i] * h + kf * cki;
            sizes[i] = sizes[i] * h + kf * cki.abs();
            ms[i] = ms[i] * m + cki;
            mvalue[i] = mvalue[i] * m + kf * cki;
            msizes[i] = msizes[i] * m + kf * cki.abs();
        }
    }
    let middle = std::array::from_fn(|i| c[0][i] + ms[i] * m);
    let slope = Slope {
        p,
        h,
        value,
        sizes,
        middle,
        middle_value: mvalue,
        middle_sizes: msizes,
    };
    (s.map(|si| si * h), slope)
}

/// The estimated error of the step from `t` to `y_new` whose polynomial has the slope
/// `slope`, in units of the step's tolerance: the larger of the end's ‖δ(h)‖_w·h/(p + 1) and
/// the middle's ⅔ h ‖δ(h/2)‖_w, the weights `w` those of the step rule, each defect less its
/// own rounding. NaN when f or y_p′ is not finite (the caller treats it as a failed check,
/// and the new state's own check names it).
fn error<S: TaylorSystem<N>, const N: usize>(
    sys: &S,
    ws: &mut S::Workspace,
    t: f64,
    y_new: &[f64; N],
    slope: &Slope<N>,
    w: &[f64; N],
) -> f64 {
    let h = slope.h;
    let end = excess(sys, ws, t + h, y_new, &slope.value, &slope.sizes, w);
    let middle = excess(
        sys,
        ws,
        t + 0.5 * h,
        &slope.middle,
        &slope.middle_value,
        &slope.middle_sizes,
        w,
    );
    if end.is_nan() || middle.is_nan() {
        return f64::NAN;
    }
    (end * h / (slope.p as f64 + 1.0)).max(middle * h * MIDDLE)
}

/// ‖f(t, y) − y_p′‖_w less the rounding of the two, at one point of the step: `d` is y_p′
/// there and `sizes` the sum of its terms' sizes. NaN if any component is.
fn excess<S: TaylorSystem<N>, const N: usize>(
    sys: &S,
    ws: &mut S::Workspace,
    t: f64,
    y: &[f64; N],
    d: &[f64; N],
    sizes: &[f64; N],
    w: &[f64; N],
) -> f64 {
    let mut rows = [[0.0; N]; 2];
    sys.coefficients_into(ws, t, y, 1, &mut rows);
    let mut worst = 0.0f64;
    for i in 0..N {
        let f = rows[1][i];
        let e = ((f - d[i]).abs() - ROUNDING * (f.abs() + sizes[i])) * w[i];
        if e.is_nan() {
            return f64::NAN;
        }
        worst = worst.max(e);
    }
    worst
}

/// `None` when the step from `t` to `y_new`, its polynomial's slope at its end `slope`,
/// passes the defect check at tolerance `eps` with weights `w`; otherwise the shorter step
/// to take again from the same jet.
pub(super) fn shorter_step<S: TaylorSystem<N>, const N: usize>(
    sys: &S,
    ws: &mut S::Workspace,
    t: f64,
    y_new: &[f64; N],
    slope: &Slope<N>,
    w: &[f64; N],
    eps: f64,
) -> Option<f64> {
    let h = slope.h;
    let err = error(sys, ws, t, y_new, slope, w);
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
        // c = (1, 2, −3): y′(h) = 2 − 6h, its terms' sizes 2 + 6h; the increment 2h − 3h².
        let (inc, slope) = increment_and_slope(&[[1.0], [2.0], [-3.0]], 0.5);
        assert_eq!((inc, slope.value, slope.sizes), ([0.25], [-1.0], [5.0]));
    }

    fn check(c: &[[f64; 1]], h: f64) -> Option<f64> {
        let (inc, slope) = increment_and_slope(c, h);
        let y = [c[0][0] + inc[0]];
        shorter_step(&Decay, &mut (), 0.0, &y, &slope, &[1.0], 1e-10)
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
    fn the_estimate_is_within_a_small_factor_of_the_true_error() {
        // At order 6 and h = 1 the truncation error of e^(−1) is ≈ 1/7! − 1/8! … = 1.76e-4;
        // the estimate ‖δ‖·h/(p + 1) should be within a factor 2 of it.
        let c = jet(6);
        let (inc, slope) = increment_and_slope(&c, 1.0);
        let y = [1.0 + inc[0]];
        let truth = (y[0] - (-1.0f64).exp()).abs();
        let est = error(&Decay, &mut (), 0.0, &y, &slope, &[1.0]);
        assert!(
            est > 0.5 * truth && est < 2.0 * truth,
            "{est:e} against {truth:e}"
        );
    }
}
