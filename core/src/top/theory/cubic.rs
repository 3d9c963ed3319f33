//! The roots of the heavy top's cubic, taken about the initial cos θ so that the turning
//! points keep their digits.
//!
//! With u = cos θ, u̇² = f(u) = (α − β u)(1 − u²) − (b − a u)². Written about the initial
//! u0 as f(u0 + x) = β x³ + f2 x² + f1 x + f0, every coefficient comes from the state without
//! cancellation: with A0 = θ̇0² + φ̇0² sin²θ0 (= α − β u0) and B0 = φ̇0 sin²θ0 (= b − a u0),
//! f0 = θ̇0² sin²θ0, f1 = −2 A0 u0 − β sin²θ0 + 2 a B0, f2 = −A0 + 2 β u0 − a².
//!
//! For β > 0, f(−1) = −(b + a)² ≤ 0, f(u0) = f0 ≥ 0, f(1) = −(b − a)² ≤ 0 and f → +∞, so the
//! roots are x1 ∈ [−1 − u0, 0], x2 ∈ [0, 1 − u0] and x3 ≥ 1 − u0. x1 and x2 are found by
//! Newton's method safeguarded by bisection inside those brackets (at most
//! [`MAX_BRACKET_STEPS`] steps, so it ends), x3 from the sum of the roots, −f2/β, polished by
//! Newton. A turning point at the start (f0 = 0) is deflated exactly: x = 0 is a root and
//! the other two solve β x² + f2 x + f1 = 0.

/// Most steps of the safeguarded Newton iteration on one bracket (bisection alone would
/// reach the last bit of a bracket of width 2 in about 1100; Newton needs a handful).
pub(crate) const MAX_BRACKET_STEPS: usize = 200;

/// f(u0 + x) = β x³ + f2 x² + f1 x + f0, with β > 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ShiftedCubic {
    pub f0: f64,
    pub f1: f64,
    pub f2: f64,
    pub beta: f64,
}

impl ShiftedCubic {
    /// f(u0 + x).
    pub fn at(&self, x: f64) -> f64 {
        ((self.beta * x + self.f2) * x + self.f1) * x + self.f0
    }

    /// f′(u0 + x).
    fn slope(&self, x: f64) -> f64 {
        (3.0 * self.beta * x + 2.0 * self.f2) * x + self.f1
    }

    /// The roots x1 ≤ x2 ≤ x3, with x1 in [lo, 0] and x2 in [0, hi] (lo = −1 − u0,
    /// hi = 1 − u0).
    pub fn roots(&self, lo: f64, hi: f64) -> [f64; 3] {
        let [x1, x2] = if self.f0 == 0.0 {
            let [r1, r2] = self.deflated_roots();
            // 0 is the start's turning point; the smaller non-zero root says which one.
            let mut three = [0.0, r1, r2];
            three.sort_by(f64::total_cmp);
            return three;
        } else {
            [self.bracketed(lo, 0.0), self.bracketed(0.0, hi)]
        };
        let mut x3 = -self.f2 / self.beta - x1 - x2;
        for _ in 0..3 {
            let d = self.slope(x3);
            if d == 0.0 {
                break;
            }
            let next = x3 - self.at(x3) / d;
            if !next.is_finite() || (next - x3).abs() <= f64::EPSILON * x3.abs() {
                break;
            }
            x3 = next;
        }
        [x1, x2, x3.max(x2)]
    }

    /// The roots of β x² + f2 x + f1 = f(u0 + x)/x, without cancellation.
    fn deflated_roots(&self) -> [f64; 2] {
        // A negative discriminant can only be rounding (three real roots exist).
        let disc = (self.f2 * self.f2 - 4.0 * self.beta * self.f1).max(0.0);
        let sign = if self.f2 >= 0.0 { 1.0 } else { -1.0 };
        let q = -0.5 * (self.f2 + sign * disc.sqrt());
        if q == 0.0 {
            return [0.0, 0.0];
        }
        [q / self.beta, self.f1 / q]
    }

    /// The root of f in [a, b], where f changes sign (up to rounding at an end).
    fn bracketed(&self, a: f64, b: f64) -> f64 {
        let (mut a, mut b) = (a, b);
        let (fa, fb) = (self.at(a), self.at(b));
        if fa == 0.0 {
            return a;
        }
        if fb == 0.0 || fa.signum() == fb.signum() {
            // A root at an end, blurred by rounding: f(±1) = −(b ∓ a)² = 0 exactly there.
            return if fa.abs() < fb.abs() { a } else { b };
        }
        let a_sign = fa.signum();
        let mut x = 0.5 * (a + b);
        for _ in 0..MAX_BRACKET_STEPS {
            let fx = self.at(x);
            if fx == 0.0 {
                return x;
            }
            if fx.signum() == a_sign {
                a = x;
            } else {
                b = x;
            }
            let newton = x - fx / self.slope(x);
            let inside = newton > a.min(b) && newton < a.max(b);
            let next = if inside { newton } else { 0.5 * (a + b) };
            if (next - x).abs() <= 2.0 * f64::EPSILON * x.abs()
                || (b - a).abs() <= f64::MIN_POSITIVE
            {
                return next;
            }
            x = next;
        }
        x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roots_of_a_product_are_recovered() {
        // 2 (x + 0.3)(x − 0.2)(x − 1.5) = 2x³ − 2.8x² − 0.42x + 0.18.
        let c = ShiftedCubic {
            f0: 0.18,
            f1: -0.42,
            f2: -2.8,
            beta: 2.0,
        };
        let r = c.roots(-1.0, 1.0);
        for (got, want) in r.iter().zip([-0.3, 0.2, 1.5]) {
            assert!((got - want).abs() < 1e-15, "{r:?}");
        }
        // A turning point at the start: 2 x (x + 0.3)(x − 1.5).
        let c = ShiftedCubic {
            f0: 0.0,
            f1: -0.9,
            f2: -2.4,
            beta: 2.0,
        };
        let r = c.roots(-1.0, 1.0);
        for (got, want) in r.iter().zip([-0.3, 0.0, 1.5]) {
            assert!((got - want).abs() < 1e-15, "{r:?}");
        }
    }
}
