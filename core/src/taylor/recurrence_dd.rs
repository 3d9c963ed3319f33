//! The recurrences of a [`Tape`](super::Tape) in double-double, for the low orders of the
//! extended mode ([`TaylorSystem::coefficients_extended_into`](super::TaylorSystem)).
//!
//! The same recurrences as [`super::recurrence`], every sum and product in double-double
//! ([`Dd`], about 106 bits): a Cauchy product `Σⱼ a_j b_{k−j}` is summed with each leading
//! product exact and every rounding kept ([`Dd::dot`]), so its error is about
//! 2⁻¹⁰⁴·k·Σ|a_j b_{k−j}| instead of 2⁻⁵³·k·Σ|…| in `f64`. The coefficients live in the `f64` workspace of
//! [`super::TaylorTape`], two words per coefficient (hi, lo), after the `f64` table.
//!
//! Every operation of a tape is carried. A sine–cosine pair and a real power take their
//! order 0 from the double-double functions ([`Dd::sin_cos`], [`Dd::powf`]); a real power
//! whose exponent is the double nearest a rational p/q (a literal such as `3/2`) is taken
//! as exactly p/q at every order, its weights r(k − j) − j summed as the integers
//! p(k − j) − q j and divided by q once.

use super::tape::{SeriesOp, SeriesStep};
use crate::exact::{Dd, rational};
pub(crate) use crate::sym::functions::DdTable;

/// Writes the order-`k` coefficient of `step`'s output in double-double, every operand known
/// to order `k` and the output to order `k − 1`; `s` gives the scalars in double-double.
pub(crate) fn step(c: &mut DdTable<'_>, s: &impl Fn(u32) -> Dd, step: &SeriesStep, k: usize) {
    let out = step.out;
    if let SeriesOp::Func(f, a) = step.op {
        // A primitive writes its output and companions itself.
        f.primitive().series_dd(c, a, out, k);
        return;
    }
    let sc = s;
    let v = match step.op {
        SeriesOp::Add(a, b) => c.get(a, k) + c.get(b, k),
        SeriesOp::Sub(a, b) => c.get(a, k) - c.get(b, k),
        SeriesOp::AddScalar(a, x) if k == 0 => c.get(a, 0) + sc(x),
        SeriesOp::SubScalar(a, x) if k == 0 => c.get(a, 0) - sc(x),
        SeriesOp::ScalarSub(x, a) if k == 0 => sc(x) - c.get(a, 0),
        SeriesOp::AddScalar(a, _) | SeriesOp::SubScalar(a, _) => c.get(a, k),
        SeriesOp::ScalarSub(_, a) | SeriesOp::Neg(a) => -c.get(a, k),
        SeriesOp::Scale(a, x) => sc(x) * c.get(a, k),
        SeriesOp::DivScalar(a, x) => c.get(a, k) / sc(x),
        SeriesOp::Mul(a, b) => c.cauchy(a, b, k, 0, k),
        SeriesOp::Square(a) => c.cauchy(a, a, k, 0, k),
        SeriesOp::Div(a, b) if k == 0 => c.get(a, 0) / c.get(b, 0),
        SeriesOp::Div(a, b) => (c.get(a, k) - c.cauchy(b, out, k, 1, k)) / c.get(b, 0),
        SeriesOp::ScalarDiv(x, a) if k == 0 => sc(x) / c.get(a, 0),
        SeriesOp::ScalarDiv(_, a) => -(c.cauchy(a, out, k, 1, k) / c.get(a, 0)),
        SeriesOp::Sqrt(a) if k == 0 => c.get(a, 0).sqrt(),
        SeriesOp::Sqrt(a) => {
            let sum = if k >= 2 {
                c.cauchy(out, out, k, 1, k - 1)
            } else {
                Dd::default()
            };
            (c.get(a, k) - sum) / (Dd::from(2.0) * c.get(out, 0))
        }
        SeriesOp::Powf(a, r) if k == 0 => c.get(a, 0).powf(r),
        SeriesOp::Powf(a, r) => power(c, a, out, r, k),
        SeriesOp::SinCos(a) => {
            let (sin, cos, d) = (out, out + 1, out + 2);
            let (sv, cv) = if k == 0 {
                c.set(d, 0, Dd::default());
                c.get(a, 0).sin_cos()
            } else {
                // d_k = k a_k, then s_k = (1/k) Σⱼ₌₁ᵏ d_j c_{k−j}, c_k = −(1/k) Σⱼ₌₁ᵏ d_j s_{k−j}.
                c.set(d, k, c.get(a, k) * Dd::from(k as f64));
                let kf = k as f64;
                (
                    c.cauchy(d, cos, k, 1, k).div_f64(kf),
                    -c.cauchy(d, sin, k, 1, k).div_f64(kf),
                )
            };
            c.set(cos, k, cv);
            sv
        }
        // Written above, before the match.
        SeriesOp::Func(..) => return,
    };
    c.set(out, k, v);
}

/// The real power's order k ≥ 1: c_k = (1/(k a_0)) Σⱼ₌₀ᵏ⁻¹ (r(k − j) − j) a_{k−j} c_j, with
/// r = p/q exactly when the double r rounds a rational of small denominator (as at order 0,
/// [`Dd::powf`]), so that every order describes the same power.
fn power(c: &DdTable<'_>, a: u32, out: u32, r: f64, k: usize) -> Dd {
    let (num, den) = match rational(r) {
        Some((p, q)) => (p as f64, q as f64),
        None => (r, 1.0),
    };
    let kf = k as f64;
    let sum = Dd::dot((0..k).map(|j| {
        // num·(k − j) − den·j: exact for a rational (small integers), else r(k − j) − j in
        // double-double.
        let w = Dd::prod(num, (k - j) as f64) - Dd::prod(den, j as f64);
        (w * c.get(a, k - j), c.get(out, j))
    }));
    (sum / c.get(a, 0)).div_f64(kf * den)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The double-double Cauchy product of integer series whose terms need up to 106 bits is
    /// exact: checked against the same sum in 128-bit integers.
    #[test]
    fn cauchy_of_wide_integers_is_exact() {
        // a_j = 2⁵⁰ + 2j + 1, b_j = 3·2⁴⁸ − 7j: wide, so each product has ~100 significant
        // bits, which f64 would round, and the sums stay below 2¹⁰³, which two doubles hold.
        let a: Vec<i128> = (0..9).map(|j| (1i128 << 50) + 2 * j + 1).collect();
        let b: Vec<i128> = (0..9).map(|j| 3 * (1i128 << 48) - 7 * j).collect();
        for k in 0..9usize {
            let exact: i128 = (0..=k).map(|j| a[j] * b[k - j]).sum();
            let dd = Dd::dot((0..=k).map(|j| (Dd::from(a[j] as f64), Dd::from(b[k - j] as f64))));
            // hi + lo as an integer: both parts are integers here (|lo| ≥ 1 or 0).
            let got = dd.hi as i128 + dd.lo as i128;
            assert_eq!(got, exact, "order {k}");
            let plain: f64 = (0..=k).map(|j| a[j] as f64 * b[k - j] as f64).sum();
            if k > 0 {
                assert_ne!(
                    plain as i128, exact,
                    "f64 would have been exact at order {k}"
                );
            }
        }
    }

    /// A quotient's series to order 6 in double-double: 1/(3 − τ) = Σ τᵏ/3ᵏ⁺¹, whose
    /// coefficients are exact rationals; each is checked by 3ᵏ⁺¹·c_k = 1 to 30 digits.
    #[test]
    fn quotient_matches_the_rational_series() {
        let st = 7;
        let mut w = vec![0.0; DdTable::len(3, st)];
        let mut c = DdTable { w: &mut w, st };
        // series 0: 1 (constant), series 1: 3 − τ, series 2: the quotient.
        c.set(0, 0, Dd::from(1.0));
        c.set(1, 0, Dd::from(3.0));
        c.set(1, 1, Dd::from(-1.0));
        let div = SeriesStep {
            out: 2,
            op: SeriesOp::Div(0, 1),
        };
        for k in 0..st {
            step(&mut c, &|_| Dd::default(), &div, k);
        }
        for k in 0..st {
            let scaled = c.get(2, k) * Dd::from(3f64.powi(k as i32 + 1));
            let e = (scaled - Dd::from(1.0)).to_f64();
            assert!(e.abs() < 1e-30, "order {k}: {e:e}");
        }
    }
    /// √(3 + τ) to order 8 in double-double: its square, formed again by the Cauchy
    /// product, must give back 3 + τ to 30 digits at every order.
    #[test]
    fn square_root_squares_back() {
        let st = 9;
        let mut w = vec![0.0; DdTable::len(2, st)];
        let mut c = DdTable { w: &mut w, st };
        c.set(0, 0, Dd::from(3.0));
        c.set(0, 1, Dd::from(1.0));
        let sqrt = SeriesStep {
            out: 1,
            op: SeriesOp::Sqrt(0),
        };
        for k in 0..st {
            step(&mut c, &|_| Dd::default(), &sqrt, k);
        }
        for k in 0..st {
            let square = Dd::dot((0..=k).map(|j| (c.get(1, j), c.get(1, k - j))));
            let want = [3.0, 1.0].get(k).copied().unwrap_or(0.0);
            let e = (square - Dd::from(want)).to_f64();
            assert!(e.abs() < 1e-30, "order {k}: {e:e}");
        }
        assert!(c.get(1, 0).lo != 0.0, "√3 carries a low word");
    }
}
