//! Double-double arithmetic (≈ 32 digits) for the few quantities whose rounding would grow
//! with time: the phase λ t + u₀ and its reduction modulo the real period 4K.
//!
//! Error-free transformations after Dekker and Knuth; products use `mul_add`.

use core::ops::{Add, Div, Mul, Neg, Sub};

/// An unevaluated sum `hi + lo` with `|lo| ≤ ½ ulp(hi)`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Dd {
    /// Leading part.
    pub hi: f64,
    /// Trailing part.
    pub lo: f64,
}

/// π as a double-double.
pub(crate) const PI: Dd = Dd {
    hi: core::f64::consts::PI,
    lo: 1.224_646_799_147_353_2e-16,
};

#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

#[inline]
fn quick_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

impl Dd {
    /// The exact value of a double.
    pub const fn from_f64(x: f64) -> Self {
        Self { hi: x, lo: 0.0 }
    }

    /// Rounds to the nearest double.
    pub fn to_f64(self) -> f64 {
        self.hi + self.lo
    }

    /// The exact product of two doubles.
    pub fn prod(a: f64, b: f64) -> Self {
        let p = a * b;
        Self {
            hi: p,
            lo: a.mul_add(b, -p),
        }
    }

    /// Square root by one Newton correction of the double root.
    pub fn sqrt(self) -> Self {
        if self.hi <= 0.0 {
            return Self::from_f64(self.hi.max(0.0).sqrt());
        }
        let x = self.hi.sqrt();
        let r = self - Self::prod(x, x);
        let (hi, lo) = quick_two_sum(x, r.hi / (2.0 * x));
        Self { hi, lo }
    }

    /// `Σⱼ aⱼ bⱼ` over pairs of double-doubles, to about 2⁻¹⁰⁴·n·Σ|aⱼ bⱼ|: the leading
    /// products are made exact (`mul_add`), their running sum is kept by two-sums, and all
    /// the small parts — the sums' and products' roundings, the cross terms a_hi b_lo +
    /// a_lo b_hi — go into one `f64` that is added at the end (Ogita, Rump & Oishi's Dot2
    /// on double-double inputs; a_lo b_lo, below 2⁻¹⁰⁶|ab|, is left out). Only the leading
    /// sum is a chain of dependent additions, so it runs several times faster than a fold
    /// of [`Dd`] additions.
    ///
    /// ```
    /// use precess_core::exact::Dd;
    /// let third = Dd::from(1.0) / Dd::from(3.0);
    /// // 3·(1/3) + 3·(1/3) − 2·1 = 0 to 32 digits.
    /// let pairs = [(third, Dd::from(3.0)), (Dd::from(3.0), third), (Dd::from(-2.0), Dd::from(1.0))];
    /// assert!(Dd::dot(pairs).to_f64().abs() < 1e-30);
    /// ```
    pub fn dot(pairs: impl IntoIterator<Item = (Dd, Dd)>) -> Dd {
        let (mut s, mut small) = (0.0, 0.0);
        for (a, b) in pairs {
            let p = Dd::prod(a.hi, b.hi);
            let (sum, e) = two_sum(s, p.hi);
            s = sum;
            small += e + (p.lo + (a.hi * b.lo + a.lo * b.hi));
        }
        let (hi, lo) = two_sum(s, small);
        Dd { hi, lo }
    }

    /// `self / d` for a double `d`, to about 2⁻¹⁰⁴ relative: cheaper than the division by a
    /// [`Dd`] (one exact product for the remainder).
    ///
    /// ```
    /// use precess_core::exact::Dd;
    /// let t = Dd::from(1.0).div_f64(3.0);
    /// assert!((t * Dd::from(3.0) - Dd::from(1.0)).to_f64().abs() < 1e-31);
    /// ```
    pub fn div_f64(self, d: f64) -> Dd {
        let q1 = self.hi / d;
        let p = Dd::prod(q1, d);
        // The remainder self − q1·d, exact in its leading part (Sterbenz).
        let r = ((self.hi - p.hi) - p.lo) + self.lo;
        let (hi, lo) = quick_two_sum(q1, r / d);
        Dd { hi, lo }
    }

    /// Nearest integer (ties away from zero), as a double.
    pub fn round(self) -> f64 {
        let r = self.hi.round();
        if r == self.hi {
            // hi is an integer: the trailing part decides.
            r + self.lo.round()
        } else {
            r
        }
    }
}

impl Add for Dd {
    type Output = Dd;
    fn add(self, o: Dd) -> Dd {
        let (s, e) = two_sum(self.hi, o.hi);
        let (t, f) = two_sum(self.lo, o.lo);
        let (s, e) = quick_two_sum(s, e + t);
        let (hi, lo) = quick_two_sum(s, e + f);
        Dd { hi, lo }
    }
}

impl Neg for Dd {
    type Output = Dd;
    fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

impl Sub for Dd {
    type Output = Dd;
    fn sub(self, o: Dd) -> Dd {
        self + (-o)
    }
}

impl Mul for Dd {
    type Output = Dd;
    fn mul(self, o: Dd) -> Dd {
        let p = Dd::prod(self.hi, o.hi);
        let lo = p.lo + (self.hi * o.lo + self.lo * o.hi);
        let (hi, lo) = quick_two_sum(p.hi, lo);
        Dd { hi, lo }
    }
}

impl Div for Dd {
    type Output = Dd;
    fn div(self, o: Dd) -> Dd {
        let q1 = self.hi / o.hi;
        let r = self - o * Dd::from_f64(q1);
        let q2 = r.hi / o.hi;
        let r = r - o * Dd::from_f64(q2);
        let q3 = r.hi / o.hi;
        let (hi, lo) = quick_two_sum(q1, q2);
        Dd { hi, lo } + Dd::from_f64(q3)
    }
}

impl From<f64> for Dd {
    fn from(x: f64) -> Self {
        Self::from_f64(x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sqrt2_squared_is_two_to_32_digits() {
        let r = Dd::from(2.0).sqrt();
        let e = (r * r - Dd::from(2.0)).to_f64();
        assert!(e.abs() < 1e-30, "{e:e}");
    }

    #[test]
    fn division_recovers_third() {
        let t = Dd::from(1.0) / Dd::from(3.0);
        let e = (t * Dd::from(3.0) - Dd::from(1.0)).to_f64();
        assert!(e.abs() < 1e-31, "{e:e}");
        assert!(t.lo != 0.0);
    }
}
