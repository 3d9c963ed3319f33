//! The radius of convergence a Taylor step is sized by, estimated from the jet so that no
//! vanishing coefficient is trusted, with every component measured at its own scale.
//!
//! Jorba and Zou estimate the radius from the last two rows, ρ = min over k ∈ {p − 1, p} of
//! (1/‖c_k‖)^(1/k); the two rows cover a solution that is even or odd about the step's start.
//! A row can vanish for other reasons: at t₀ = 0, x' = t²y, y' = −t²x has non-zero
//! coefficients only at the orders 0, 3, 6, …, and x' = tᵐy only every m + 1 orders, so both
//! last rows can be zero and the estimate +∞ although the solution moves. Here
//! - the norms are weighted, n_k = maxᵢ |c_k,ᵢ|/sᵢ with sᵢ the component's own scale (see
//!   `Taylor::step_rule`), so a large component no longer loosens the others;
//! - ρ comes from the two highest rows that do not vanish, k₁ > k₂ (one if only one does):
//!   the smaller of their root estimates (1/n_k)^(1/k), and at most `RATIO` times their
//!   ratio estimate (n_k₂/n_k₁)^(1/(k₁−k₂)), which catches coefficients that still grow;
//! - rows just below them may only lower it: a row k in the top quarter of the orders,
//!   k₁ − ⌈k₁/4⌉ ≤ k < k₂, bounds ρ ≤ (k₁/k)·(1/n_k)^(1/k). The estimates (1/n_k)^(1/k) of a
//!   solution analytic in a disc are about constant in k, and those of an entire function
//!   grow about linearly (k!^(1/k) ≈ k/e), so the bound leaves an ordinary jet alone; it
//!   catches the top rows that are tiny rather than zero (a start just off t = 0 above, where
//!   they are of the size of t₀). It is tested without a logarithm, n_k·(kρ/k₁)ᵏ ≤ 1;
//! - every row of orders 1 … p vanishing gives +∞, which the caller does not take on trust.

/// How far past the ratio estimate of the radius the root estimate may go: the steps,
/// κ·ρ with κ ≈ e⁻² ≈ 0.13, stay within about half the ratio estimate. A regular jet's ratio
/// estimate is the larger of the two (k + 1 against k/e for eᵗ, R(1 − α/k) against
/// R·k^(−α/k) for a singularity (1 − t/R)^(−α−1)), and one whose variation is small against
/// its scale has a root estimate larger by (scale/variation)^(1/k), so the bound is met only
/// past a factor 4/e⁻² ≈ 30 of that. It binds where the coefficients still grow at the order
/// p, as those of x' = t²⁰y just after t = 0 (ratio (20 − k)/((k + 1)t₀) at order k), whose
/// root estimate sees nothing of the orders to come.
pub(super) const RATIO: f64 = 4.0;

/// The estimated radius of convergence of the jet `c` (orders 0 … p, p ≥ 1) with the
/// components weighted by `w` (wᵢ = 1/sᵢ): +∞ when every row of orders 1 … p vanishes,
/// `None` when a weighted norm is not finite (an overflowed coefficient would otherwise give
/// ρ = 0 and pass for a step-size underflow).
///
/// In the ordinary case (the last two rows non-zero) this costs two logarithms and one
/// exponential, as Jorba and Zou's rule, plus the weighted norms of a quarter of the rows.
///
/// A logarithm and exponential of our own (the exponent from the bits, a short series for
/// the rest, 1e-10 relative on ρ) were measured slower than the library's table-driven ones:
/// their polynomial chains are longer than a table lookup.
pub(super) fn radius<const N: usize>(c: &[[f64; N]], w: &[f64; N]) -> Option<f64> {
    let p = c.len().checked_sub(1)?;
    // The two highest rows that do not vanish, (order, weighted norm).
    let mut top = [(0usize, 0.0f64); 2];
    let mut found = 0;
    let mut k = p;
    while k >= 1 && found < 2 {
        let n = weighted_norm(&c[k], w);
        if !n.is_finite() {
            return None;
        }
        if n > 0.0 {
            top[found] = (k, n);
            found += 1;
        }
        k -= 1;
    }
    let (k1, n1) = top[0];
    if found == 0 {
        return Some(f64::INFINITY);
    }
    let log_radius = |n: f64, k: usize| -n.ln() / k as f64;
    let log_n1 = n1.ln();
    let mut log_rho = -log_n1 / k1 as f64;
    let k2 = if found == 2 {
        let (k2, n2) = top[1];
        let log_n2 = n2.ln();
        // The root estimates of both rows, and RATIO times the ratio estimate
        // (n_k₂/n_k₁)^(1/(k₁−k₂)), from the same two logarithms.
        log_rho = log_rho
            .min(-log_n2 / k2 as f64)
            .min(RATIO.ln() + (log_n2 - log_n1) / (k1 - k2) as f64);
        k2
    } else {
        k1
    };
    let mut rho = log_rho.exp();
    let k1f = k1 as f64;
    let lowest = (k1 - k1.div_ceil(4)).max(1);
    // A slice, not `enumerate().take().skip()`: the skip was a call (`Take::nth`) a step.
    let guard = c.get(lowest..k2).unwrap_or(&[]);
    for (k, row) in (lowest..).zip(guard) {
        let n = weighted_norm(row, w);
        if !n.is_finite() {
            return None;
        }
        let kf = k as f64;
        // n·(kρ/k₁)ᵏ > 1 ⇔ ρ > (k₁/k)(1/n)^(1/k). A zero row passes (0 ≤ 1); an overflow of
        // the power fails and is settled by the logarithm, which can only lower ρ.
        if n * power(kf * rho / k1f, k) > 1.0 {
            rho = rho.min(k1f / kf * log_radius(n, k).exp());
        }
    }
    Some(rho)
}

/// xᵏ by binary powering, inline: the multiplications of `f64::powi`'s out-of-line
/// `__powidf2` (the runtime's square-and-multiply: r ← r·x for each set bit of k from the
/// lowest, x ← x² between), in the same order, so the same bits, without its call, which
/// callgrind counted at 89 of the 4 700 instructions of a heavy-top step.
pub(super) fn power(mut x: f64, mut k: usize) -> f64 {
    let mut r = 1.0;
    loop {
        if k & 1 == 1 {
            r *= x;
        }
        k >>= 1;
        if k == 0 {
            return r;
        }
        x *= x;
    }
}

/// maxᵢ |cᵢ|·wᵢ, the norm of a coefficient row with each component at its own scale. NaN
/// entries are skipped (`f64::max`): in a coefficient they reach the new state through the
/// step's sum and are reported there.
pub(super) fn weighted_norm<const N: usize>(c: &[f64; N], w: &[f64; N]) -> f64 {
    c.iter()
        .zip(w)
        .fold(0.0f64, |m, (v, wi)| m.max(v.abs() * wi))
}

/// Whether every row of orders 1 … p of `c` is zero: the jet says nothing of the step size.
pub(super) fn vanishes<const N: usize>(c: &[[f64; N]]) -> bool {
    // The top rows first: an ordinary jet is decided by its last row.
    c.iter()
        .skip(1)
        .rev()
        .all(|row| row.iter().all(|&v| v == 0.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rows c_k = a/Rᵏ (k ≥ 1) of one component.
    fn geometric(a: f64, r: f64, p: usize) -> Vec<[f64; 1]> {
        (0..=p).map(|k| [a / r.powi(k as i32)]).collect()
    }

    #[test]
    fn power_is_powi_bit_for_bit() {
        // Against `powi` itself (the runtime's `__powidf2`; `black_box` keeps the compiler
        // from folding it) on awkward bases: every bit.
        use std::hint::black_box;
        for &x in &[
            0.9999999999999999,
            1.0000000000000002,
            0.3,
            -1.7,
            2.718281828459045e3,
            1e-3,
        ] {
            for k in 0..40 {
                let want = black_box::<f64>(x).powi(black_box(k as i32));
                assert_eq!(power(x, k).to_bits(), want.to_bits(), "{x}^{k}");
            }
        }
    }

    #[test]
    fn a_geometric_jet_gives_its_radius() {
        // c_k = 1/2ᵏ: (1/n_k)^(1/k) = 2 at every order.
        let c = geometric(1.0, 2.0, 12);
        let rho = radius(&c, &[1.0]).unwrap();
        assert!((rho - 2.0).abs() < 1e-14, "{rho}");
    }

    #[test]
    fn vanishing_top_rows_are_skipped() {
        // Only the orders 0, 3, 6 non-zero (the chirp x' = t²y at t₀ = 0): the radius comes
        // from orders 6 and 3, min(18^(1/6), 3^(1/3)) = 3^(1/3).
        let mut c = vec![[0.0; 1]; 9];
        c[0] = [1.0];
        c[3] = [-1.0 / 3.0];
        c[6] = [-1.0 / 18.0];
        let rho = radius(&c, &[1.0]).unwrap();
        assert!((rho - 3f64.cbrt()).abs() < 1e-14, "{rho}");
        assert!(!vanishes(&c));
    }

    #[test]
    fn tiny_top_rows_are_bounded_by_the_rows_below() {
        // Rows 7 and 8 of size 1e-6 and 1e-12 alone would give ρ = 1e6^(1/7) ≈ 7.2; row
        // 6 = 1/18 bounds it by (8/6)·18^(1/6).
        let mut c = vec![[0.0; 1]; 9];
        c[0] = [1.0];
        c[6] = [-1.0 / 18.0];
        c[7] = [1e-6];
        c[8] = [1e-12];
        let rho = radius(&c, &[1.0]).unwrap();
        let want = 8.0 / 6.0 * 18f64.powf(1.0 / 6.0);
        assert!((rho - want).abs() < 1e-13, "{rho} against {want}");
    }

    #[test]
    fn coefficients_that_still_grow_are_bounded_by_their_ratio() {
        // c_k = 10ᵏ·1e-12: the root estimate of row 8 is (1e12/1e8)^(1/8) = 10^(1/2), but
        // the coefficients grow tenfold per order: ρ ≤ 4·(1/10).
        let c: Vec<[f64; 1]> = (0..=8).map(|k| [1e-12 * 10f64.powi(k)]).collect();
        let rho = radius(&c, &[1.0]).unwrap();
        assert!((rho - 0.4).abs() < 1e-14, "{rho}");
    }

    #[test]
    fn an_entire_function_is_left_to_its_last_two_rows() {
        // c_k = 1/k! (eˣ): the guard's rows give (k₁/k)·k!^(1/k) above 13!^(1/13).
        let c: Vec<[f64; 1]> = (0..=13)
            .map(|k| [1.0 / (1..=k).map(f64::from).product::<f64>()])
            .collect();
        let rho = radius(&c, &[1.0]).unwrap();
        let want = (1..=12).map(f64::from).product::<f64>().powf(1.0 / 12.0);
        assert!((rho - want).abs() < 1e-13 * want, "{rho} against {want}");
    }

    #[test]
    fn each_component_is_measured_at_its_own_scale() {
        // A large slow component (1e5, radius 100) and a small fast one (1, radius 1): with
        // weights 1/1e5 and 1 the small one decides.
        let c: Vec<[f64; 2]> = (0..=10).map(|k| [1e5 / 100f64.powi(k), 1.0]).collect();
        let rho = radius(&c, &[1e-5, 1.0]).unwrap();
        assert!((rho - 1.0).abs() < 1e-14, "{rho}");
    }

    #[test]
    fn only_a_vanishing_jet_is_infinite_and_an_overflow_is_refused() {
        let mut c = vec![[0.0; 2]; 6];
        c[0] = [1.0, 2.0];
        assert!(vanishes(&c));
        assert_eq!(radius(&c, &[1.0, 1.0]), Some(f64::INFINITY));
        c[5][1] = f64::INFINITY;
        assert_eq!(radius(&c, &[1.0, 1.0]), None);
    }
}
