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
//! The check costs one evaluation of f (the system's jet to order 1) and a Horner sum for
//! y_p′(h), a few per cent of a step. It is an estimate at one point, not a bound: a defect
//! that vanishes at the step's end by chance passes.

use crate::taylor::TaylorSystem;

/// How much rounding the defect may carry, in units of the rounding of f and y_p′: their
/// difference cancels when the step is good, and a few ulps of each, times the p terms of
/// the derivative, must not read as an error at the tightest tolerances.
const ROUNDING: f64 = 64.0 * f64::EPSILON;

/// The shortest a rejected step is cut to, and the longest, as fractions of it: the error
/// goes as h^(p+1), so the cut aims at 0.9·(ε/error)^(1/(p+1)), kept in these bounds so that
/// a wild estimate neither stalls the run nor barely changes the step.
const CUT: (f64, f64) = (0.1, 0.5);

/// y_p′(h) = Σₖ₌₁ᵖ k c_k hᵏ⁻¹ for every component, and the same sum of the terms' sizes
/// Σₖ k |c_k| hᵏ⁻¹, which bounds its rounding (an oscillating solution's terms can be far
/// larger than their sum); by Horner with the order outside (the N chains overlap, as in the
/// step's own sum).
fn derivative<const N: usize>(c: &[[f64; N]], h: f64) -> ([f64; N], [f64; N]) {
    let p = c.len().saturating_sub(1);
    let (mut s, mut a) = ([0.0; N], [0.0; N]);
    for k in (1..=p).rev() {
        let kf = k as f64;
        for ((si, ai), cki) in s.iter_mut().zip(a.iter_mut()).zip(&c[k]) {
            *si = *si * h + kf * cki;
            *ai = *ai * h + kf * cki.abs();
        }
    }
    (s, a)
}

/// The estimated error of the step from `(t, y)` by `h` with the jet `c` (orders 0 … p) to
/// `y_new`, in units of the step's tolerance: ‖δ‖_w·h/(p + 1), the weights `w` those of the
/// step rule, less the defect's own rounding. NaN when f or y_p′ is not finite (the caller
/// treats it as a failed check, and the new state's own check names it).
fn error<S: TaylorSystem<N>, const N: usize>(
    sys: &S,
    ws: &mut S::Workspace,
    c: &[[f64; N]],
    t_end: f64,
    h: f64,
    y_new: &[f64; N],
    w: &[f64; N],
) -> f64 {
    let mut rows = [[0.0; N]; 2];
    sys.coefficients_into(ws, t_end, y_new, 1, &mut rows);
    let (slope, sizes) = derivative(c, h);
    let mut worst = 0.0f64;
    for i in 0..N {
        let (f, d) = (rows[1][i], slope[i]);
        let excess = ((f - d).abs() - ROUNDING * (f.abs() + sizes[i])) * w[i];
        if excess.is_nan() {
            return f64::NAN;
        }
        worst = worst.max(excess);
    }
    let p = c.len().saturating_sub(1) as f64;
    worst * h / (p + 1.0)
}

/// `None` when the step from `t` by `h` to `y_new` passes the defect check at tolerance
/// `eps` with weights `w`; otherwise the shorter step to take again from the same jet.
#[allow(clippy::too_many_arguments)]
pub(super) fn shorter_step<S: TaylorSystem<N>, const N: usize>(
    sys: &S,
    ws: &mut S::Workspace,
    c: &[[f64; N]],
    t: f64,
    h: f64,
    y_new: &[f64; N],
    w: &[f64; N],
    eps: f64,
) -> Option<f64> {
    let err = error(sys, ws, c, t + h, h, y_new, w);
    if err <= eps {
        return None;
    }
    let p = c.len().saturating_sub(1) as f64;
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

    fn sum(c: &[[f64; 1]], h: f64) -> [f64; 1] {
        [c.iter().rev().fold(0.0, |s, ck| s * h + ck[0])]
    }

    #[test]
    fn the_derivative_is_the_polynomial_s() {
        // c = (1, 2, −3): y′(h) = 2 − 6h, its terms' sizes 2 + 6h.
        assert_eq!(derivative(&[[1.0], [2.0], [-3.0]], 0.5), ([-1.0], [5.0]));
    }

    #[test]
    fn an_ordinary_step_passes_and_a_long_one_is_cut() {
        // Order 13, ε = 1e-10: a step of 0.7 has an estimated error near 8e-14 and passes.
        let c = jet(13);
        let w = [1.0];
        let y = sum(&c, 0.7);
        assert_eq!(
            shorter_step(&Decay, &mut (), &c, 0.0, 0.7, &y, &w, 1e-10),
            None
        );
        // A step of 3 has an estimated error near 5e-5 ≫ 1e-10: cut to between 0.3 and 1.5.
        let y = sum(&c, 3.0);
        let cut = shorter_step(&Decay, &mut (), &c, 0.0, 3.0, &y, &w, 1e-10);
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
        let y = sum(&c, 1.0);
        let truth = (y[0] - (-1.0f64).exp()).abs();
        let est = error(&Decay, &mut (), &c, 1.0, 1.0, &y, &[1.0]);
        assert!(
            est > 0.5 * truth && est < 2.0 * truth,
            "{est:e} against {truth:e}"
        );
    }
}
