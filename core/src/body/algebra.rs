//! The scalar algebra the body physics is written over: plain `f64` at run time, symbolic
//! expressions in an [`Arena`] inside the derive macro. One implementation of the physics
//! serves both.

use crate::sym::{Arena, ExprId, Rational};

/// The four field operations, exact rational constants, and the sine, cosine and square
/// root a part's rotation needs, over some value type.
///
/// Implemented by [`Numeric`] (values are `f64`) and by [`Arena`] (values are [`ExprId`]s,
/// so a body of literals folds to exact rational constants).
pub trait Algebra {
    /// The scalar type.
    type Value: Copy;
    /// The rational constant `num / den` (`den` is never zero in this crate).
    fn ratio(&mut self, num: i64, den: i64) -> Self::Value;
    /// `a + b`.
    fn plus(&mut self, a: Self::Value, b: Self::Value) -> Self::Value;
    /// `a − b`.
    fn minus(&mut self, a: Self::Value, b: Self::Value) -> Self::Value;
    /// `a · b`.
    fn times(&mut self, a: Self::Value, b: Self::Value) -> Self::Value;
    /// `a / b`, `None` when `b` is (identically) zero.
    fn divide(&mut self, a: Self::Value, b: Self::Value) -> Option<Self::Value>;

    /// `sin a`.
    fn sin(&mut self, a: Self::Value) -> Self::Value;
    /// `cos a`.
    fn cos(&mut self, a: Self::Value) -> Self::Value;
    /// `√a`, `None` when `a` is (a constant) below zero.
    fn sqrt(&mut self, a: Self::Value) -> Option<Self::Value>;

    /// `c · a` for the rational `c = num / den`.
    fn scaled(&mut self, num: i64, den: i64, a: Self::Value) -> Self::Value {
        let c = self.ratio(num, den);
        self.times(c, a)
    }

    /// `a²`.
    fn square(&mut self, a: Self::Value) -> Self::Value {
        self.times(a, a)
    }

    /// The sum of `terms`.
    fn total(&mut self, terms: &[Self::Value]) -> Self::Value {
        let mut acc = self.ratio(0, 1);
        for &t in terms {
            acc = self.plus(acc, t);
        }
        acc
    }

    /// The rotation nearest `r`, a matrix given as a rotation (rows), so that a matrix
    /// within the orthonormality tolerance turns a part without stretching it.
    ///
    /// The default takes one Newton–Schulz step R ← R (3E − RᵀR)/2 toward the orthogonal
    /// factor of R's polar decomposition: for RᵀR − E of size δ ≤ 1e-9 (the tolerance) the
    /// step leaves (3/8) δ² ≤ 4e-19, below rounding, and it is polynomial, so it applies
    /// to symbolic entries as well. [`Numeric`] and constant matrices in an [`Arena`] take
    /// it in `f64` to rounding, and keep a matrix that is a rotation to rounding as given.
    fn orthonormalise(&mut self, r: &[[Self::Value; 3]; 3]) -> [[Self::Value; 3]; 3] {
        newton_schulz(self, r)
    }
}

/// One Newton–Schulz step R (3E − RᵀR)/2 toward the nearest rotation.
fn newton_schulz<A: Algebra + ?Sized>(al: &mut A, r: &[[A::Value; 3]; 3]) -> [[A::Value; 3]; 3] {
    let zero = al.ratio(0, 1);
    let mut gram = [[zero; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            let terms: Vec<A::Value> = (0..3).map(|k| al.times(r[k][i], r[k][j])).collect();
            gram[i][j] = al.total(&terms);
        }
    }
    // (3E − RᵀR)/2.
    let mut c = [[zero; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            let g = al.scaled(-1, 2, gram[i][j]);
            c[i][j] = if i == j {
                let three_halves = al.ratio(3, 2);
                al.plus(three_halves, g)
            } else {
                g
            };
        }
    }
    let mut out = [[zero; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            let terms: Vec<A::Value> = (0..3).map(|k| al.times(r[i][k], c[k][j])).collect();
            out[i][j] = al.total(&terms);
        }
    }
    out
}

/// The nearest rotation to `r` in `f64`: `r` itself when it is a rotation to rounding
/// (|RᵀR − E| within four ulps of 1, as one from angles or a quaternion is), else
/// Newton–Schulz steps until they stop changing it (two from the tolerance's 1e-9; three at
/// most).
fn orthonormalise_f64(r: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    let deviation = (0..9).fold(0.0f64, |m, n| {
        let (i, j) = (n / 3, n % 3);
        let g: f64 = (0..3).map(|k| r[k][i] * r[k][j]).sum();
        let e = if i == j { 1.0 } else { 0.0 };
        m.max((g - e).abs())
    });
    if deviation <= 4.0 * f64::EPSILON {
        return *r;
    }
    let mut r = *r;
    for _ in 0..3 {
        let next = newton_schulz(&mut Numeric, &r);
        if next == r {
            break;
        }
        r = next;
    }
    r
}

/// Plain floating-point arithmetic: the run-time builder's algebra.
#[derive(Clone, Copy, Debug, Default)]
pub struct Numeric;

impl Algebra for Numeric {
    type Value = f64;
    fn ratio(&mut self, num: i64, den: i64) -> f64 {
        num as f64 / den as f64
    }
    fn plus(&mut self, a: f64, b: f64) -> f64 {
        a + b
    }
    fn minus(&mut self, a: f64, b: f64) -> f64 {
        a - b
    }
    fn times(&mut self, a: f64, b: f64) -> f64 {
        a * b
    }
    fn divide(&mut self, a: f64, b: f64) -> Option<f64> {
        (b != 0.0).then(|| a / b)
    }
    fn sin(&mut self, a: f64) -> f64 {
        a.sin()
    }
    fn cos(&mut self, a: f64) -> f64 {
        a.cos()
    }
    fn sqrt(&mut self, a: f64) -> Option<f64> {
        (a >= 0.0).then(|| a.sqrt())
    }
    fn orthonormalise(&mut self, r: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
        orthonormalise_f64(r)
    }
}

impl Algebra for Arena {
    type Value = ExprId;
    fn ratio(&mut self, num: i64, den: i64) -> ExprId {
        match Rational::new(num.into(), den.into()) {
            Some(r) => self.constant(r),
            None => self.zero(),
        }
    }
    fn plus(&mut self, a: ExprId, b: ExprId) -> ExprId {
        Arena::add(self, a, b)
    }
    fn minus(&mut self, a: ExprId, b: ExprId) -> ExprId {
        Arena::sub(self, a, b)
    }
    fn times(&mut self, a: ExprId, b: ExprId) -> ExprId {
        Arena::mul(self, a, b)
    }
    fn divide(&mut self, a: ExprId, b: ExprId) -> Option<ExprId> {
        Arena::div(self, a, b).ok()
    }
    fn sin(&mut self, a: ExprId) -> ExprId {
        Arena::sin(self, a)
    }
    fn cos(&mut self, a: ExprId) -> ExprId {
        Arena::cos(self, a)
    }
    fn sqrt(&mut self, a: ExprId) -> Option<ExprId> {
        Arena::sqrt(self, a).ok()
    }
    fn total(&mut self, terms: &[ExprId]) -> ExprId {
        self.sum(terms)
    }
    /// A matrix of constants that is a rotation exactly (decimal literals such as 0.6 and
    /// 0.8 are exact rationals) is kept; any other matrix of constants is taken to the
    /// nearest rotation in `f64`, as the run-time builder does, so both give one tensor. A
    /// matrix that reads fields takes the symbolic step of the default.
    fn orthonormalise(&mut self, r: &[[ExprId; 3]; 3]) -> [[ExprId; 3]; 3] {
        let constants = r.map(|row| row.map(|e| self.as_rational(e)));
        if constants.iter().flatten().any(Option::is_none) {
            return newton_schulz(self, r);
        }
        let exact = newton_schulz(self, r);
        if exact == *r {
            return exact;
        }
        let numeric = orthonormalise_f64(
            &constants.map(|row| row.map(|c| c.map_or(f64::NAN, |c| c.to_f64()))),
        );
        numeric.map(|row| {
            row.map(|v| match Rational::from_f64(v) {
                Some(c) => self.constant(c),
                None => self.zero(),
            })
        })
    }
}
