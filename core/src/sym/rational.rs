//! Exact rational constants with checked arithmetic, over the whole range of `f64` and
//! beyond.
//!
//! A value is n/d · 2^a · 5^b: the powers of two and five carry the magnitude of decimal
//! literals and binary floats, so `1.989e30`, `1e-300` and every finite `f64` are exact, and
//! products of large and small decimals stay exact. Every operation returns `None` when an
//! odd part leaves `i128` or an exponent its bound, instead of wrapping; the engine then keeps
//! the operands unfolded, which is exact if less tidy (see `docs/symbolic.md`).

mod big;
mod magnitude;

use std::cmp::Ordering;
use std::fmt;

use magnitude::{Scaled, compare, nearest};

/// Bound on the power of two: far beyond the f64 range (2⁻¹⁰⁷⁴ … 2¹⁰²⁴), small enough that
/// exact comparison and rounding stay cheap.
const MAX_TWO: i64 = 1 << 14;
/// Bound on the power of five (5⁴⁰⁹⁶ ≈ 10²⁸⁶³).
const MAX_FIVE: i64 = 1 << 12;

/// An exact rational number.
///
/// The representation is canonical, so equal values are equal (and hash alike):
/// - a value that is a ratio of `i128`s is held as that ratio in lowest terms, `den > 0`;
/// - any other value as `num/den · 2^two · 5^five` with `num`, `den` coprime, neither
///   divisible by 2 or 5, `den > 0`, and the exponents within ±2¹⁴ and ±2¹² (values beyond
///   are `None` from the arithmetic).
///
/// ```
/// use precess_core::sym::Rational;
/// // The Sun as a sphere: I = 2/5 M R², exact, then rounded once.
/// let m = Rational::from_f64(1.989e30).unwrap();
/// let r = Rational::from_f64(6.957e8).unwrap();
/// let r2 = r.checked_mul(r).unwrap();
/// let i = Rational::new(2, 5).unwrap().checked_mul(m).unwrap().checked_mul(r2).unwrap();
/// assert_eq!(i.to_f64(), 0.4 * 1.989e30 * (6.957e8 * 6.957e8));
/// ```
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub struct Rational {
    num: i128,
    den: i128,
    two: i32,
    five: i32,
}

/// A rational split into sign, odd parts free of 2 and 5, and the exponents of 2 and 5: the
/// form the extended arithmetic works in.
#[derive(Clone, Copy, Debug)]
struct Parts {
    negative: bool,
    n: u128,
    d: u128,
    two: i64,
    five: i64,
}

fn gcd(mut a: u128, mut b: u128) -> u128 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

fn gcd_i128(a: i128, b: i128) -> i128 {
    // Both below 2¹²⁷ in absolute value (never i128::MIN), so the gcd fits.
    gcd(a.unsigned_abs(), b.unsigned_abs()) as i128
}

/// `x` without its factors 2 and 5, and how many of each it had (`x > 0`).
fn strip(x: u128) -> (u128, i64, i64) {
    let twos = x.trailing_zeros();
    let mut x = x >> twos;
    let mut fives = 0;
    while x.is_multiple_of(5) {
        x /= 5;
        fives += 1;
    }
    (x, i64::from(twos), fives)
}

/// `x · 2^two · 5^five` for non-negative exponents, `None` past `u128`.
fn scale_up(x: u128, two: i64, five: i64) -> Option<u128> {
    let p5 = 5u128.checked_pow(u32::try_from(five).ok()?)?;
    let y = x.checked_mul(p5)?;
    let t = u32::try_from(two).ok().filter(|&t| t < 128)?;
    (y.leading_zeros() >= t).then(|| y << t)
}

fn isqrt(n: u128) -> Option<u128> {
    let mut r = (n as f64).sqrt() as u128;
    // Correct the float estimate by a step or two either way.
    while r > 0 && r.checked_mul(r).is_none_or(|sq| sq > n) {
        r -= 1;
    }
    while (r + 1).checked_mul(r + 1).is_some_and(|sq| sq <= n) {
        r += 1;
    }
    (r * r == n).then_some(r)
}

impl Parts {
    /// `±n/d · 2^two · 5^five` with `n`, `d` free of 2 and 5, reduced to lowest terms.
    fn new(negative: bool, n: u128, d: u128, two: i64, five: i64) -> Parts {
        let g = gcd(n, d).max(1);
        Parts {
            negative,
            n: n / g,
            d: d / g,
            two,
            five,
        }
    }

    /// `±n · 2^two · 5^five` for any `n`: its own factors 2 and 5 join the exponents.
    fn from_integer(negative: bool, n: u128, two: i64, five: i64) -> Parts {
        if n == 0 {
            return Parts::new(false, 0, 1, 0, 0);
        }
        let (n, t, f) = strip(n);
        Parts::new(negative, n, 1, two + t, five + f)
    }

    /// The canonical rational; `None` if an odd part leaves `i128` or an exponent its bound.
    fn canonical(self) -> Option<Rational> {
        if self.n == 0 {
            return Some(Rational::ZERO);
        }
        let sign = if self.negative { -1 } else { 1 };
        let num = scale_up(self.n, self.two.max(0), self.five.max(0));
        let den = scale_up(self.d, (-self.two).max(0), (-self.five).max(0));
        if let (Some(n), Some(d)) = (num, den)
            && let (Ok(n), Ok(d)) = (i128::try_from(n), i128::try_from(d))
        {
            // n and d share no factor (2 and 5 sit on one side only), so this is lowest terms.
            return Some(Rational {
                num: sign * n,
                den: d,
                two: 0,
                five: 0,
            });
        }
        if self.two.abs() > MAX_TWO || self.five.abs() > MAX_FIVE {
            return None;
        }
        Some(Rational {
            num: sign * i128::try_from(self.n).ok()?,
            den: i128::try_from(self.d).ok()?,
            two: self.two as i32,
            five: self.five as i32,
        })
    }

    fn magnitude(self) -> Scaled {
        Scaled {
            n: self.n,
            d: self.d,
            two: self.two,
            five: self.five,
        }
    }
}

impl Rational {
    /// Zero.
    pub const ZERO: Rational = Rational::plain(0, 1);
    /// One.
    pub const ONE: Rational = Rational::plain(1, 1);
    /// Minus one.
    pub const MINUS_ONE: Rational = Rational::plain(-1, 1);

    const fn plain(num: i128, den: i128) -> Rational {
        Rational {
            num,
            den,
            two: 0,
            five: 0,
        }
    }

    /// The rational `num / den` in lowest terms; `None` if `den == 0` or either is `i128::MIN`.
    pub fn new(num: i128, den: i128) -> Option<Rational> {
        if den == 0 || num == i128::MIN || den == i128::MIN {
            return None;
        }
        let g = gcd_i128(num, den).max(1);
        let (mut n, mut d) = (num / g, den / g);
        if d < 0 {
            n = -n;
            d = -d;
        }
        Some(Rational::plain(n, d))
    }

    /// The integer `n`.
    pub fn integer(n: i64) -> Rational {
        Rational::plain(n.into(), 1)
    }

    /// `(numerator, denominator)` in lowest terms, the denominator positive, when the value is
    /// a ratio of `i128`s; `None` for values only the scaled form holds (e.g. `1e40`).
    pub fn fraction(self) -> Option<(i128, i128)> {
        self.is_plain().then_some((self.num, self.den))
    }

    /// `(n, d, a, b)` with the value `n/d · 2^a · 5^b`: the ratio itself (`a = b = 0`) when it
    /// fits `i128`s, else odd parts free of 2 and 5 and the exponents.
    pub fn scaled(self) -> (i128, i128, i32, i32) {
        (self.num, self.den, self.two, self.five)
    }

    fn is_plain(self) -> bool {
        self.two == 0 && self.five == 0
    }

    fn parts(self) -> Parts {
        let negative = self.num < 0;
        let (n, d) = (self.num.unsigned_abs(), self.den.unsigned_abs());
        if !self.is_plain() || n == 0 {
            return Parts {
                negative,
                n,
                d,
                two: self.two.into(),
                five: self.five.into(),
            };
        }
        let (n, tn, fn_) = strip(n);
        let (d, td, fd) = strip(d);
        Parts {
            negative,
            n,
            d,
            two: tn - td,
            five: fn_ - fd,
        }
    }

    /// True for zero.
    pub fn is_zero(self) -> bool {
        self.num == 0
    }

    /// True for one.
    pub fn is_one(self) -> bool {
        self == Rational::ONE
    }

    /// True if strictly negative.
    pub fn is_negative(self) -> bool {
        self.num < 0
    }

    /// True for an integer.
    pub fn is_integer(self) -> bool {
        self.den == 1 && self.two >= 0 && self.five >= 0
    }

    /// `self + rhs`, `None` on overflow.
    pub fn checked_add(self, rhs: Rational) -> Option<Rational> {
        if self.is_zero() {
            return Some(rhs);
        }
        if rhs.is_zero() {
            return Some(self);
        }
        if self.is_plain() && rhs.is_plain() && self.den == 1 && rhs.den == 1 {
            match self.num.checked_add(rhs.num) {
                Some(n) if n != i128::MIN => return Some(Rational::plain(n, 1)),
                _ => {}
            }
        }
        if self.is_plain() && rhs.is_plain() {
            // Cross-multiply over the gcd of the denominators to stay small.
            let g = gcd_i128(self.den, rhs.den);
            let (a, b) = (self.den / g, rhs.den / g);
            let sum = self
                .num
                .checked_mul(b)
                .zip(rhs.num.checked_mul(a))
                .and_then(|(x, y)| x.checked_add(y));
            if let (Some(num), Some(den)) = (sum, self.den.checked_mul(b))
                && let Some(r) = Rational::new(num, den)
            {
                return Some(r);
            }
        }
        let (x, y) = (self.parts(), rhs.parts());
        // Factor out the smaller powers of 2 and 5; the terms keep the rest.
        let (two, five) = (x.two.min(y.two), x.five.min(y.five));
        let tx = scale_up(x.n, x.two - two, x.five - five)?;
        let ty = scale_up(y.n, y.two - two, y.five - five)?;
        let g = gcd(x.d, y.d);
        let (dx, dy) = (x.d / g, y.d / g);
        let (tx, ty) = (tx.checked_mul(dy)?, ty.checked_mul(dx)?);
        let den = x.d.checked_mul(dy)?;
        let (negative, num) = if x.negative == y.negative {
            (x.negative, tx.checked_add(ty)?)
        } else if tx >= ty {
            (x.negative, tx - ty)
        } else {
            (y.negative, ty - tx)
        };
        if num == 0 {
            return Some(Rational::ZERO);
        }
        let (num, t, f) = strip(num);
        Parts::new(negative, num, den, two + t, five + f).canonical()
    }

    /// `self * rhs`, `None` on overflow.
    pub fn checked_mul(self, rhs: Rational) -> Option<Rational> {
        if self.is_zero() || rhs.is_zero() {
            return Some(Rational::ZERO);
        }
        // Integers, the expansion's commonest coefficients: no gcd to take.
        if self.is_plain() && rhs.is_plain() && self.den == 1 && rhs.den == 1 {
            match self.num.checked_mul(rhs.num) {
                Some(n) if n != i128::MIN => return Some(Rational::plain(n, 1)),
                _ => {}
            }
        }
        if self.is_plain() && rhs.is_plain() {
            let g1 = gcd_i128(self.num, rhs.den).max(1);
            let g2 = gcd_i128(rhs.num, self.den).max(1);
            let num = (self.num / g1).checked_mul(rhs.num / g2);
            let den = (self.den / g2).checked_mul(rhs.den / g1);
            if let (Some(num), Some(den)) = (num, den)
                && let Some(r) = Rational::new(num, den)
            {
                return Some(r);
            }
        }
        let (x, y) = (self.parts(), rhs.parts());
        let (g1, g2) = (gcd(x.n, y.d).max(1), gcd(y.n, x.d).max(1));
        let n = (x.n / g1).checked_mul(y.n / g2)?;
        let d = (x.d / g2).checked_mul(y.d / g1)?;
        Parts {
            negative: x.negative != y.negative,
            n,
            d,
            two: x.two + y.two,
            five: x.five + y.five,
        }
        .canonical()
    }

    /// `|self|`.
    pub fn abs_value(self) -> Rational {
        Rational {
            num: self.num.abs(),
            ..self
        }
    }

    /// `1 / self`, `None` for zero.
    pub fn recip(self) -> Option<Rational> {
        if self.is_zero() {
            return None;
        }
        // Swapping the odd parts and negating the exponents keeps the form canonical: the
        // reciprocal fits a ratio of i128s exactly when the value does.
        let sign = self.num.signum();
        Some(Rational {
            num: sign * self.den,
            den: self.num.abs(),
            two: -self.two,
            five: -self.five,
        })
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
        if self.is_negative() {
            return None;
        }
        if self.is_zero() {
            return Some(Rational::ZERO);
        }
        let p = self.parts();
        if p.two % 2 != 0 || p.five % 2 != 0 {
            return None;
        }
        Parts::new(false, isqrt(p.n)?, isqrt(p.d)?, p.two / 2, p.five / 2).canonical()
    }

    /// The nearest `f64`, rounded once: to nearest, ties to even, subnormals included; ±∞
    /// when the magnitude rounds past the largest finite `f64` (check with `is_finite`).
    pub fn to_f64(self) -> f64 {
        const EXACT: u128 = 1 << 53;
        let (n, d) = (self.num.unsigned_abs(), self.den.unsigned_abs());
        let magnitude = if n == 0 {
            0.0
        } else if self.is_plain() && n <= EXACT && d <= EXACT {
            // Both are exact in f64, and the division then rounds once.
            n as f64 / d as f64
        } else {
            nearest(self.parts().magnitude())
        };
        if self.is_negative() {
            -magnitude
        } else {
            magnitude
        }
    }

    /// The exact value of a finite `f64`; `None` for NaN and ±∞.
    pub fn from_f64(x: f64) -> Option<Rational> {
        if !x.is_finite() {
            return None;
        }
        let bits = x.to_bits();
        let exp = ((bits >> 52) & 0x7ff) as i64;
        let frac = bits & ((1 << 52) - 1);
        let (mant, e) = if exp == 0 {
            (frac, -1074)
        } else {
            (frac | (1 << 52), exp - 1075)
        };
        Parts::from_integer(bits >> 63 == 1, mant.into(), e, 0).canonical()
    }

    /// The exact value of `±digits · 10^exp10`; `None` if the odd part of `digits` leaves
    /// `i128` or the exponent its bound.
    pub(crate) fn from_decimal(negative: bool, digits: u128, exp10: i64) -> Option<Rational> {
        if exp10.abs() > MAX_TWO {
            return None;
        }
        Parts::from_integer(negative, digits, exp10, exp10).canonical()
    }
}

impl std::ops::Neg for Rational {
    type Output = Rational;

    /// `-self` (never overflows: `num` is never `i128::MIN`).
    fn neg(self) -> Rational {
        Rational {
            num: -self.num,
            ..self
        }
    }
}

impl PartialOrd for Rational {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Rational {
    /// The exact order of the values (it decides the order of terms in a sum, so it must
    /// agree with equality: two distinct values never compare equal).
    fn cmp(&self, other: &Self) -> Ordering {
        let by_sign = self.num.signum().cmp(&other.num.signum());
        if by_sign != Ordering::Equal || self.is_zero() {
            return by_sign;
        }
        if self.is_plain()
            && other.is_plain()
            && let (Some(a), Some(b)) = (
                self.num.checked_mul(other.den),
                other.num.checked_mul(self.den),
            )
        {
            return a.cmp(&b);
        }
        let magnitudes = compare(self.parts().magnitude(), other.parts().magnitude());
        if self.is_negative() {
            magnitudes.reverse()
        } else {
            magnitudes
        }
    }
}

impl fmt::Display for Rational {
    /// `n` or `n/d`; a scaled value as `n*2^a*5^b/d` with a common power of ten written as
    /// an exponent: `1989e27`, `3e-40/7`, `1*2^200`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (two, five) = (i64::from(self.two), i64::from(self.five));
        let ten = if two.signum() == five.signum() {
            two.signum() * two.abs().min(five.abs())
        } else {
            0
        };
        write!(f, "{}", self.num)?;
        if ten != 0 {
            write!(f, "e{ten}")?;
        }
        if two != ten {
            write!(f, "*2^{}", two - ten)?;
        }
        if five != ten {
            write!(f, "*5^{}", five - ten)?;
        }
        if self.den != 1 {
            write!(f, "/{}", self.den)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests;
