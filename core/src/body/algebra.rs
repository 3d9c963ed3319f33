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
}
