//! Elementary functions: sin, cos, sqrt, real powers, with the exact rules that never change a value.

use super::arena::{Arena, ExprId, Node};
use super::error::SymError;
use super::rational::Rational;

impl Arena {
    /// `sin u`; odd symmetry pulls a negative coefficient out: `sin(−2x) = −sin 2x`.
    pub fn sin(&mut self, u: ExprId) -> ExprId {
        if u == self.zero() {
            return self.zero();
        }
        match self.negated_argument(u) {
            Some(pos) => {
                let s = self.intern(Node::Sin(pos));
                self.neg(s)
            }
            None => self.intern(Node::Sin(u)),
        }
    }

    /// `cos u`; even symmetry drops a negative coefficient: `cos(−2x) = cos 2x`.
    pub fn cos(&mut self, u: ExprId) -> ExprId {
        if u == self.zero() {
            return self.one();
        }
        let arg = self.negated_argument(u).unwrap_or(u);
        self.intern(Node::Cos(arg))
    }

    /// `√u`, the principal root; exact for squares of rationals.
    ///
    /// # Errors
    /// [`SymError::SqrtOfNegative`] for a negative constant.
    pub fn sqrt(&mut self, u: ExprId) -> Result<ExprId, SymError> {
        match self.node(u) {
            Node::Const(r) if r.is_negative() => {
                Err(SymError::SqrtOfNegative { value: r.to_f64() })
            }
            Node::Const(r) => Ok(match r.sqrt_exact() {
                Some(root) => self.constant(root),
                None => self.intern(Node::Sqrt(u)),
            }),
            _ => Ok(self.intern(Node::Sqrt(u))),
        }
    }

    /// `u^r` for a rational `r`: an integer `r` is [`Arena::powi`], `r = 1/2` is
    /// [`Arena::sqrt`], any other `r` a [`Node::Powr`] of a base taken positive (the principal
    /// branch `exp(r ln u)`; the numeric value of a negative base is NaN). Nested powers are
    /// not merged: `(u^r)^s = u^(rs)` holds for a positive `u`, but `(u²)^(1/4)` is `√|u|`,
    /// and keeping the node is always correct.
    ///
    /// # Errors
    /// [`SymError::RealPowerUndefined`] for a non-integer power of a negative constant, a
    /// negative power of zero, or an integer `r` past `i64`; [`SymError::DivisionByZero`]
    /// for a negative power of an expression that is identically zero; those of
    /// [`Arena::powi`] for an integer `r`.
    ///
    /// ```
    /// use approx::assert_relative_eq;
    /// use precess_core::sym::{Arena, Rational};
    /// let mut a = Arena::new();
    /// let x = a.parameter("x");
    /// let p = a.powr(x, Rational::new(3, 2).unwrap()).unwrap();
    /// assert_eq!(a.display(p), "x^(3/2)");
    /// assert_relative_eq!(a.eval(p, &[4.0]), 8.0);
    /// let four = a.integer(4);
    /// assert_eq!(a.powr(four, Rational::new(1, 2).unwrap()), Ok(a.integer(2)));
    /// ```
    pub fn powr(&mut self, u: ExprId, r: Rational) -> Result<ExprId, SymError> {
        self.check_owned(&[u])?;
        let undefined = |arena: &Arena| SymError::RealPowerUndefined {
            base: arena.display(u),
            exponent: r.to_string(),
        };
        if r.is_integer() {
            let n = r
                .fraction()
                .and_then(|(n, _)| i64::try_from(n).ok())
                .ok_or_else(|| undefined(self))?;
            return self.powi(u, n);
        }
        if r == Rational::new(1, 2).unwrap_or(Rational::ONE) {
            return self.sqrt(u);
        }
        match self.node(u) {
            Node::Const(c) if c.is_negative() || (c.is_zero() && r.is_negative()) => {
                Err(undefined(self))
            }
            Node::Const(c) if c.is_zero() || c.is_one() => Ok(u),
            _ => {
                if r.is_negative() && self.is_zero(u)? {
                    return Err(SymError::DivisionByZero {
                        divisor: self.display(u),
                    });
                }
                Ok(self.intern(Node::Powr(u, r)))
            }
        }
    }

    /// If `u = −v` with a negative rational coefficient, returns `v`.
    fn negated_argument(&mut self, u: ExprId) -> Option<ExprId> {
        let negative = match self.node(u) {
            Node::Const(r) => r.is_negative(),
            Node::Mul(f) => matches!(self.node(f[0]), Node::Const(r) if r.is_negative()),
            _ => false,
        };
        negative.then(|| self.neg(u))
    }
}
