//! Where an exact positive value n/d · 2^two · 5^five sits on the real line: the nearest
//! `f64` (rounded once) and the exact order of two such values.
//!
//! Both first decide from a logarithm when the answer is plain (far outside the f64 range,
//! or two values apart by more than a factor of four), which also bounds the big integers the
//! exact path builds by the exponents' size.

use std::cmp::Ordering;

use super::big::Big;

const LOG2_5: f64 = 2.321_928_094_887_362;

/// A positive value n/d · 2^two · 5^five (n, d > 0).
#[derive(Clone, Copy, Debug)]
pub(super) struct Scaled {
    pub n: u128,
    pub d: u128,
    pub two: i64,
    pub five: i64,
}

impl Scaled {
    /// log₂ of the value to about 1e-12: the exponents are bounded by the caps of
    /// `Rational`, so the products below lose nothing that matters at the margins used.
    fn log2(self) -> f64 {
        (self.n as f64).log2() - (self.d as f64).log2()
            + self.two as f64
            + self.five as f64 * LOG2_5
    }

    /// The value as a ratio of big integers times a power of two: `(num, den, two)`.
    fn as_big(self) -> (Big, Big, i64) {
        let (mut num, mut den) = (Big::from_u128(self.n), Big::from_u128(self.d));
        if self.five >= 0 {
            num.mul_pow5(self.five.unsigned_abs());
        } else {
            den.mul_pow5(self.five.unsigned_abs());
        }
        (num, den, self.two)
    }
}

/// The `f64` nearest the value: round to nearest, ties to even, subnormals included, +∞ at
/// or beyond 2¹⁰²⁴ (the first value that rounds past the largest finite `f64`).
pub(super) fn nearest(x: Scaled) -> f64 {
    let log2 = x.log2();
    if log2 > 1025.0 {
        return f64::INFINITY;
    }
    if log2 < -1080.0 {
        // Below a quarter of the smallest subnormal 2⁻¹⁰⁷⁴: rounds to zero.
        return 0.0;
    }
    let (mut num, mut den, two) = x.as_big();
    // Scale so the quotient has 65 or 66 bits: 53 for the significand, the rest to round.
    let s = den.bit_len() as i64 - num.bit_len() as i64 + 65;
    if s >= 0 {
        num.shl(s.unsigned_abs());
    } else {
        den.shl(s.unsigned_abs());
    }
    // Restoring division, one quotient bit at a time: 2⁶⁴ < num/den < 2⁶⁶.
    let mut q: u128 = 0;
    den.shl(66);
    for i in (0..=66).rev() {
        if num >= den {
            num.sub_assign(&den);
            q |= 1 << i;
        }
        den.shr1();
    }
    round(q, two - s, !num.is_zero())
}

/// Rounds (m + δ)·2^e to an `f64`, where 0 ≤ δ < 1 and δ > 0 exactly when `sticky`; `m`
/// has at least 55 bits, so the rounding bit lies inside it.
fn round(m: u128, e: i64, sticky: bool) -> f64 {
    let bits = i64::from(128 - m.leading_zeros());
    let top = bits - 1 + e;
    if top > 1023 {
        return f64::INFINITY;
    }
    // The unit in the last place of the result: 53 significant bits, or the subnormal unit.
    let ulp = (top - 52).max(-1074);
    let shift = ulp - e;
    if shift > bits {
        // Less than half the smallest subnormal.
        return 0.0;
    }
    let q = m >> shift;
    let rem = m & ((1u128 << shift) - 1);
    let half = 1u128 << (shift - 1);
    let up = rem > half || (rem == half && (sticky || q & 1 == 1));
    compose(q + u128::from(up), ulp)
}

/// q · 2^ulp as an `f64`, for q ≤ 2⁵³ (q < 2⁵² only with the subnormal unit 2⁻¹⁰⁷⁴).
fn compose(q: u128, ulp: i64) -> f64 {
    let (q, ulp) = if q == 1 << 53 {
        (q >> 1, ulp + 1)
    } else {
        (q, ulp)
    };
    if q < 1 << 52 {
        return f64::from_bits(q as u64);
    }
    let biased = ulp + 1075;
    if biased >= 2047 {
        return f64::INFINITY;
    }
    f64::from_bits(((biased as u64) << 52) | (q as u64 - (1 << 52)))
}

/// The exact order of two positive values.
pub(super) fn compare(x: Scaled, y: Scaled) -> Ordering {
    let (lx, ly) = (x.log2(), y.log2());
    if lx > ly + 2.0 {
        return Ordering::Greater;
    }
    if ly > lx + 2.0 {
        return Ordering::Less;
    }
    // n₁ d₂ 2^(a₁−a₂) 5^(b₁−b₂) against n₂ d₁.
    let mut left = Big::from_u128(x.n).mul(&Big::from_u128(y.d));
    let mut right = Big::from_u128(y.n).mul(&Big::from_u128(x.d));
    let (dt, df) = (x.two - y.two, x.five - y.five);
    if df >= 0 {
        left.mul_pow5(df.unsigned_abs());
    } else {
        right.mul_pow5(df.unsigned_abs());
    }
    if dt >= 0 {
        left.shl(dt.unsigned_abs());
    } else {
        right.shl(dt.unsigned_abs());
    }
    left.cmp(&right)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(n: u128, d: u128, two: i64, five: i64) -> Scaled {
        Scaled { n, d, two, five }
    }

    #[test]
    fn rounds_ties_to_even_and_reaches_the_limits() {
        // 2⁵³ + 1 is halfway between 2⁵³ and 2⁵³ + 2: ties go to the even 2⁵³.
        assert_eq!(nearest(v((1 << 53) + 1, 1, 0, 0)), 9_007_199_254_740_992.0);
        assert_eq!(nearest(v((1 << 53) + 3, 1, 0, 0)), 9_007_199_254_740_996.0);
        assert_eq!(nearest(v(1, 3, 0, 0)), 1.0 / 3.0);
        assert_eq!(nearest(v(1, 1, -1074, 0)), f64::from_bits(1));
        // Exactly half the smallest subnormal ties to zero; a hair above rounds up.
        assert_eq!(nearest(v(1, 1, -1075, 0)), 0.0);
        assert_eq!(nearest(v(3, 1, -1076, 0)), f64::from_bits(1));
        assert_eq!(nearest(v((1 << 53) - 1, 1, 971, 0)), f64::MAX);
        // Halfway between the largest finite and 2¹⁰²⁴ rounds (to even) to +∞.
        assert_eq!(nearest(v((1 << 54) - 1, 1, 970, 0)), f64::INFINITY);
        // Three quarters of an ulp below 2¹⁰²⁴ − ulp: the largest finite.
        assert_eq!(nearest(v((1 << 55) - 3, 1, 969, 0)), f64::MAX);
    }

    #[test]
    fn compares_exactly_near_equality() {
        // 10/8 · 2 = 5/2 · 1: equal through different exponents.
        assert_eq!(compare(v(5, 1, -1, 0), v(1, 1, -1, 1)), Ordering::Equal);
        assert_eq!(
            compare(v(1, 3, 0, 0), v(333_333, 1, -6, -6)),
            Ordering::Greater
        );
        assert_eq!(
            compare(v(1, 1, 2322, 0), v(1, 1, 0, 1000)),
            Ordering::Greater
        );
        assert_eq!(compare(v(1, 1, 2321, 0), v(1, 1, 0, 1000)), Ordering::Less);
    }
}
