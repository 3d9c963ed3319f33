//! Exact rational constants with checked arithmetic.
//!
//! Every operation returns `None` on overflow instead of wrapping; the engine then keeps the
//! operands unfolded, which is exact if less tidy (see `docs/symbolic.md`).

use std::cmp::Ordering;
use std::fmt;

/// An exact rational number `num / den` in lowest terms with `den > 0`.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub struct Rational {
    num: i128,
    den: i128,
}

fn gcd(mut a: i128, mut b: i128) -> i128 {
    // Callers pass values whose absolute value is representable (never i128::MIN).
    a = a.abs();
    b = b.abs();
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

impl Rational {
    /// Zero.
    pub const ZERO: Rational = Rational { num: 0, den: 1 };
    /// One.
    pub const ONE: Rational = Rational { num: 1, den: 1 };
    /// Minus one.
    pub const MINUS_ONE: Rational = Rational { num: -1, den: 1 };

    /// The rational `num / den` in lowest terms; `None` if `den == 0` or a value would overflow.
    pub fn new(num: i128, den: i128) -> Option<Rational> {
        if den == 0 || num == i128::MIN || den == i128::MIN {
            return None;
        }
        let g = gcd(num, den).max(1);
        let (mut n, mut d) = (num / g, den / g);
        if d < 0 {
            n = -n;
            d = -d;
        }
        Some(Rational { num: n, den: d })
    }

    /// The integer `n`.
    pub fn integer(n: i64) -> Rational {
        Rational {
            num: n as i128,
            den: 1,
        }
    }

    /// Numerator (carries the sign).
    pub fn numer(self) -> i128 {
        self.num
    }

    /// Denominator (always positive).
    pub fn denom(self) -> i128 {
        self.den
    }

    /// True for zero.
    pub fn is_zero(self) -> bool {
        self.num == 0
    }

    /// True for one.
    pub fn is_one(self) -> bool {
        self.num == 1 && self.den == 1
    }

    /// True if strictly negative.
    pub fn is_negative(self) -> bool {
        self.num < 0
    }

    /// True for an integer.
    pub fn is_integer(self) -> bool {
        self.den == 1
    }

    /// `self + rhs`, `None` on overflow.
    pub fn checked_add(self, rhs: Rational) -> Option<Rational> {
        // Cross-multiply over the gcd of the denominators to stay small.
        let g = gcd(self.den, rhs.den);
        let (a, b) = (self.den / g, rhs.den / g);
        let num = self
            .num
            .checked_mul(b)?
            .checked_add(rhs.num.checked_mul(a)?)?;
        let den = self.den.checked_mul(b)?;
        Rational::new(num, den)
    }

    /// `self * rhs`, `None` on overflow.
    pub fn checked_mul(self, rhs: Rational) -> Option<Rational> {
        let g1 = gcd(self.num, rhs.den).max(1);
        let g2 = gcd(rhs.num, self.den).max(1);
        let num = (self.num / g1).checked_mul(rhs.num / g2)?;
        let den = (self.den / g2).checked_mul(rhs.den / g1)?;
        Rational::new(num, den)
    }

    /// `|self|`.
    pub fn abs_value(self) -> Rational {
        Rational {
            num: self.num.abs(),
            den: self.den,
        }
    }

    /// `1 / self`, `None` for zero.
    pub fn recip(self) -> Option<Rational> {
        Rational::new(self.den, self.num)
    }

    /// `self^n` for an integer `n`, `None` on overflow or for `0^n` with `n < 0`.
    pub fn checked_pow(self, n: i64) -> Option<Rational> {
        let base = if n < 0 { self.recip()? } else { self };
        let mut e = n.unsigned_abs();
        let (mut acc, mut sq) = (Rational::ONE, base);
        while e > 0 {
            if e & 1 == 1 {
                acc = acc.checked_mul(sq)?;
            }
            e >>= 1;
            if e > 0 {
                sq = sq.checked_mul(sq)?;
            }
        }
        Some(acc)
    }

    /// The exact square root if `self` is the square of a rational.
    pub fn sqrt_exact(self) -> Option<Rational> {
        if self.num < 0 {
            return None;
        }
        let (n, d) = (isqrt(self.num)?, isqrt(self.den)?);
        Some(Rational { num: n, den: d })
    }

    /// The nearest `f64` (exact for the values decimal literals of ordinary size produce).
    pub fn to_f64(self) -> f64 {
        // Both conversions are exact below 2^53, and the division then rounds once.
        self.num as f64 / self.den as f64
    }

    /// The exact value of a finite `f64`, `None` if it does not fit in `i128 / i128`.
    pub fn from_f64(x: f64) -> Option<Rational> {
        if !x.is_finite() {
            return None;
        }
        if x == 0.0 {
            return Some(Rational::ZERO);
        }
        let bits = x.to_bits();
        let sign = if bits >> 63 == 1 { -1 } else { 1 };
        let exp = ((bits >> 52) & 0x7ff) as i32;
        let frac = bits & ((1 << 52) - 1);
        let (mant, e) = if exp == 0 {
            (frac as i128, -1074)
        } else {
            ((frac | (1 << 52)) as i128, exp - 1075)
        };
        let mant = sign * mant;
        if e >= 0 {
            let scale = 1i128.checked_shl(e as u32).filter(|_| e < 126)?;
            Rational::new(mant.checked_mul(scale)?, 1)
        } else {
            // Strip factors of two before shifting the denominator.
            let tz = (mant.trailing_zeros() as i32).min(-e);
            let (m, e) = (mant >> tz, e + tz);
            if -e >= 126 {
                return None;
            }
            Rational::new(m, 1i128 << (-e))
        }
    }
}

fn isqrt(n: i128) -> Option<i128> {
    if n < 0 {
        return None;
    }
    let mut r = (n as f64).sqrt() as i128;
    // Correct the float estimate by a step or two either way.
    while r > 0 && r.checked_mul(r).is_none_or(|sq| sq > n) {
        r -= 1;
    }
    while (r + 1).checked_mul(r + 1).is_some_and(|sq| sq <= n) {
        r += 1;
    }
    (r * r == n).then_some(r)
}

impl std::ops::Neg for Rational {
    type Output = Rational;

    /// `-self` (never overflows: `num` is never `i128::MIN`).
    fn neg(self) -> Rational {
        Rational {
            num: -self.num,
            den: self.den,
        }
    }
}

impl PartialOrd for Rational {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Rational {
    fn cmp(&self, other: &Self) -> Ordering {
        match (
            self.num.checked_mul(other.den),
            other.num.checked_mul(self.den),
        ) {
            (Some(a), Some(b)) => a.cmp(&b),
            // Overflowing cross products: compare in floating point, which only decides
            // the order of terms in a sum, never a value.
            _ => self
                .to_f64()
                .partial_cmp(&other.to_f64())
                .unwrap_or(Ordering::Equal),
        }
    }
}

impl fmt::Display for Rational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.den == 1 {
            write!(f, "{}", self.num)
        } else {
            write!(f, "{}/{}", self.num, self.den)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalises_and_folds() {
        let a = Rational::new(6, -4).unwrap();
        assert_eq!((a.numer(), a.denom()), (-3, 2));
        let b = a.checked_add(Rational::new(1, 2).unwrap()).unwrap();
        assert_eq!(b, Rational::integer(-1));
        assert_eq!(
            Rational::new(2, 3).unwrap().checked_pow(-2),
            Rational::new(9, 4)
        );
        assert_eq!(Rational::ZERO.checked_pow(-1), None);
        assert_eq!(
            Rational::new(9, 4).unwrap().sqrt_exact(),
            Rational::new(3, 2)
        );
        assert_eq!(Rational::new(2, 1).unwrap().sqrt_exact(), None);
    }

    #[test]
    fn overflow_is_none_not_wrap() {
        let big = Rational::new(i128::MAX, 1).unwrap();
        assert_eq!(big.checked_add(Rational::ONE), None);
        assert_eq!(big.checked_mul(Rational::integer(2)), None);
        assert_eq!(Rational::integer(10).checked_pow(40), None);
    }

    #[test]
    fn from_f64_is_exact() {
        assert_eq!(Rational::from_f64(0.5), Rational::new(1, 2));
        assert_eq!(Rational::from_f64(-3.0), Rational::new(-3, 1));
        let r = Rational::from_f64(0.1).unwrap();
        assert_eq!(r.to_f64(), 0.1);
        assert_eq!(Rational::from_f64(f64::NAN), None);
        assert_eq!(Rational::from_f64(1e300), None);
    }
}
