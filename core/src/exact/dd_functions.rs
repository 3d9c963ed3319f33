//! Elementary functions of a double-double to about 106 bits: sine and cosine, the
//! exponential and the logarithm, integer and real powers. The Taylor integrator's extended
//! mode needs them at order 0 of a sine–cosine pair and of a real power (the higher orders
//! follow from the recurrences), and for the constants of a tape (`sin k`, `k^(3/2)`).
//!
//! - sin, cos: x = n·π/2 + r with π/2 in three doubles (so n·π/2 is exact to ~2⁻¹⁵⁰ for
//!   |n| < 2³⁰), then the two Taylor series on |r| ≤ π/4, summed until a term is below
//!   2⁻¹¹⁰ of the sum, and the quadrant's signs.
//! - exp: x = k ln 2 + r, r/2⁸ by its series for eʳ − 1, raised back by (1 + s)² − 1 =
//!   s(s + 2) eight times (which keeps the small s to full relative precision), times 2ᵏ.
//! - ln: one Newton step y ← y + a·e⁻ʸ − 1 from the double logarithm (quadratic: 53 → 106 bits).
//! - a^r: for r = p/q a rational with q ≤ 1000 (what a literal exponent is, see
//!   `Rational::to_f64`), the q-th root by one Newton step from the double root, raised to
//!   p by squaring; any other r as exp(r ln a).

use super::Dd;

/// π/2 as the sum of three doubles (each the rounding of what the previous leave).
const HALF_PI: [f64; 3] = [
    core::f64::consts::FRAC_PI_2,
    6.123_233_995_736_766e-17,
    -1.497_384_904_859_169_8e-33,
];
/// ln 2 as the sum of three doubles.
const LN2: [f64; 3] = [
    core::f64::consts::LN_2,
    2.319_046_813_846_299_6e-17,
    5.707_708_438_416_212e-34,
];
/// The largest |x| whose reduction by π/2 keeps every digit (|n| < 2³⁰): beyond it the
/// double sine and cosine of the leading part are returned.
const REDUCTION_LIMIT: f64 = 1.0e9;
/// The largest denominator [`Dd::powf`] recognises in an exponent.
const MAX_DENOMINATOR: i64 = 1000;

impl Dd {
    /// `self · 2ᵉ`, exact (barring overflow and underflow).
    fn scale2(self, e: i32) -> Dd {
        let f = 2f64.powi(e);
        Dd {
            hi: self.hi * f,
            lo: self.lo * f,
        }
    }

    /// `self − n·c` for a constant `c` given as three doubles: the leading products exact.
    fn reduce(self, n: f64, c: &[f64; 3]) -> Dd {
        self - Dd::prod(n, c[0]) - Dd::prod(n, c[1]) - Dd::from(n * c[2])
    }

    /// `(sin x, cos x)` to about 2⁻¹⁰⁴ (absolute) for |x| ≤ 10⁹; beyond, or for a
    /// non-finite x, the `f64` values of the leading part (NaN for ±∞, NaN).
    ///
    /// ```
    /// use precess_core::exact::Dd;
    /// // sin(π/6) = 1/2 to 32 digits, with π/6 in double-double.
    /// let pi = Dd::from(std::f64::consts::PI) + Dd::from(1.2246467991473532e-16);
    /// let (s, _) = pi.div_f64(6.0).sin_cos();
    /// assert!((s - Dd::from(0.5)).to_f64().abs() < 1e-31);
    /// ```
    pub fn sin_cos(self) -> (Dd, Dd) {
        if self.hi.is_nan() || self.hi.abs() > REDUCTION_LIMIT {
            let (s, c) = self.hi.sin_cos();
            return (Dd::from(s), Dd::from(c));
        }
        let n = (self.hi / HALF_PI[0]).round();
        let r = self.reduce(n, &HALF_PI);
        let (s, c) = sin_cos_series(r);
        // n mod 4, for n of either sign (|n| < 2³⁰ is exact in i64).
        match (n as i64).rem_euclid(4) {
            0 => (s, c),
            1 => (c, -s),
            2 => (-s, -c),
            _ => (-c, s),
        }
    }

    /// `eˣ` to about 2⁻¹⁰² relative; +∞ above ln(f64::MAX), 0 far below the subnormals.
    ///
    /// ```
    /// use precess_core::exact::Dd;
    /// let e = Dd::from(1.0).exp();
    /// assert_eq!(e.hi, std::f64::consts::E);
    /// assert!((e.lo - 1.4456468917292502e-16).abs() < 1e-31);
    /// ```
    pub fn exp(self) -> Dd {
        if self.hi.is_nan() {
            return self;
        }
        if self.hi > 709.8 {
            return Dd::from(f64::INFINITY);
        }
        if self.hi < -745.2 {
            return Dd::default();
        }
        let k = (self.hi / LN2[0]).round();
        let r = self.reduce(k, &LN2).scale2(-8);
        // s = eʳ − 1 = r + r²/2! + …, |r| < 2⁻⁹: 11 terms reach 2⁻¹¹⁰.
        let mut term = r;
        let mut s = r;
        for j in 2..=12 {
            term = (term * r).div_f64(j as f64);
            s = s + term;
            if term.hi.abs() < 1e-34 * s.hi.abs() {
                break;
            }
        }
        for _ in 0..8 {
            s = s * (s + Dd::from(2.0));
        }
        // 2ᵏ in two factors, so that neither overflows nor underflows on its own.
        let k = k as i32;
        (s + Dd::from(1.0)).scale2(k / 2).scale2(k - k / 2)
    }

    /// `ln x` to about 2⁻¹⁰² relative (absolute near x = 1); −∞ at 0, NaN below.
    ///
    /// ```
    /// use precess_core::exact::Dd;
    /// // ln(eˣ) = x to 30 digits.
    /// let x = Dd::from(1.0) / Dd::from(3.0);
    /// assert!((x.exp().ln() - x).to_f64().abs() < 1e-31);
    /// ```
    pub fn ln(self) -> Dd {
        if self.hi.is_nan() || self.hi <= 0.0 || self.hi.is_infinite() {
            return Dd::from(self.hi.ln());
        }
        let y = Dd::from(self.hi.ln());
        y + self * (-y).exp() - Dd::from(1.0)
    }

    /// `xⁿ` by repeated squaring (about log₂|n| roundings of 2⁻¹⁰⁶); `x⁻ⁿ = 1/xⁿ`.
    ///
    /// ```
    /// use precess_core::exact::Dd;
    /// assert_eq!(Dd::from(3.0).powi(-2).to_f64(), 1.0 / 9.0);
    /// ```
    pub fn powi(self, n: i64) -> Dd {
        let mut base = self;
        let mut e = n.unsigned_abs();
        let mut acc = Dd::from(1.0);
        while e > 0 {
            if e & 1 == 1 {
                acc = acc * base;
            }
            e >>= 1;
            if e > 0 {
                base = base * base;
            }
        }
        if n < 0 { Dd::from(1.0) / acc } else { acc }
    }

    /// `x^r` of a base taken positive, to about 2⁻¹⁰⁰ relative: NaN for x < 0, the `f64`
    /// value of `0^r`. An exponent that is the double nearest a rational p/q with
    /// q ≤ 1000 (how a literal such as `3/2` or `1/3` reaches it) is taken as exactly p/q:
    /// a q-th root by Newton's method, then the p-th power. Any other r: exp(r ln x).
    ///
    /// ```
    /// use precess_core::exact::Dd;
    /// // 2^(1/3) cubed is 2 to 30 digits.
    /// let c = Dd::from(2.0).powf(1.0 / 3.0);
    /// assert!((c * c * c - Dd::from(2.0)).to_f64().abs() < 1e-30);
    /// ```
    pub fn powf(self, r: f64) -> Dd {
        if self.hi.is_nan() || self.hi <= 0.0 || !self.hi.is_finite() || !r.is_finite() {
            return Dd::from(self.hi.powf(r));
        }
        match rational(r) {
            Some((p, 1)) => self.powi(p),
            Some((p, q)) => self.root(q).powi(p),
            None => (Dd::from(r) * self.ln()).exp(),
        }
    }

    /// The positive q-th root of a positive finite x, q ≥ 2: one Newton step
    /// b + (x − b^q)/(q b^(q−1)) from the double root b.
    fn root(self, q: i64) -> Dd {
        let b = Dd::from(self.hi.powf(1.0 / q as f64));
        let b_q1 = b.powi(q - 1);
        b + (self - b_q1 * b) / (Dd::from(q as f64) * b_q1)
    }
}

/// `(p, q)` with q ≤ [`MAX_DENOMINATOR`] and `p as f64 / q as f64 == r`, the simplest such
/// (the first convergent of r's continued fraction that rounds to r), if any.
pub(crate) fn rational(r: f64) -> Option<(i64, i64)> {
    if r.abs() > 1e15 {
        return None;
    }
    // Convergents h/k of the continued fraction of r.
    let (mut h0, mut h1, mut k0, mut k1) = (0i64, 1i64, 1i64, 0i64);
    let mut x = r;
    for _ in 0..40 {
        let a = x.floor();
        let (h, k) = (a as i64 * h1 + h0, a as i64 * k1 + k0);
        if k > MAX_DENOMINATOR || k <= 0 {
            return None;
        }
        if h as f64 / k as f64 == r {
            return Some((h, k));
        }
        (h0, h1, k0, k1) = (h1, h, k1, k);
        let frac = x - a;
        if frac == 0.0 {
            return None;
        }
        x = 1.0 / frac;
    }
    None
}

/// sin r and cos r for |r| ≲ π/4 by their Taylor series, each summed until its term falls
/// below 2⁻¹¹⁰ of the sum (at most 14 terms each).
fn sin_cos_series(r: Dd) -> (Dd, Dd) {
    let r2 = r * r;
    let (mut ts, mut tc) = (r, Dd::from(1.0));
    let (mut s, mut c) = (ts, tc);
    for j in 1..=16 {
        let j = j as f64;
        // t_{j} = −t_{j−1} r² / ((2j)(2j + 1)) for the sine, / ((2j − 1)(2j)) for the cosine.
        ts = -(ts * r2).div_f64((2.0 * j) * (2.0 * j + 1.0));
        tc = -(tc * r2).div_f64((2.0 * j - 1.0) * (2.0 * j));
        s = s + ts;
        c = c + tc;
        if tc.hi.abs() < 1e-34 && ts.hi.abs() <= 1e-34 * s.hi.abs() {
            break;
        }
    }
    (s, c)
}

#[cfg(test)]
mod tests;
