//! Elementary functions: sin, cos, sqrt, with the exact rules that never change a value.

use super::arena::{Arena, ExprId, Node};
use super::error::SymError;

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
