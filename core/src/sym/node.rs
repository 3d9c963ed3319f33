//! The nodes of the expression graph and the one place that knows their children.
//!
//! Every walk of the engine (reachability, free symbols, substitution, expansion,
//! differentiation, printing, lowering) visits children through [`Node::children`], so a new
//! node kind is added here and in the constructors, not in every walk.

use super::arena::{ExprId, SymbolId};
use super::functions::Func;
use super::rational::Rational;

/// One node of the expression graph. Constructors in [`Arena`](super::Arena) keep these
/// canonical: sums and products are flat and sorted, constants are folded, like terms are
/// collected.
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
pub enum Node {
    /// An exact rational constant.
    Const(Rational),
    /// A symbol.
    Sym(SymbolId),
    /// A sum of at least two terms.
    Add(Box<[ExprId]>),
    /// A product of at least two factors; a rational coefficient comes first.
    Mul(Box<[ExprId]>),
    /// An integer power other than 0 and 1 of a non-constant base.
    Pow(ExprId, i64),
    /// A real power `x^r` with a non-integer rational `r` of a base taken positive (the
    /// principal branch, `exp(r ln x)`): [`Arena::powr`](super::Arena::powr).
    Powr(ExprId, Rational),
    /// The principal square root.
    Sqrt(ExprId),
    /// Sine.
    Sin(ExprId),
    /// Cosine.
    Cos(ExprId),
    /// A registered primitive function of its argument ([`super::functions`]).
    Func(Func, ExprId),
}

impl Node {
    /// The children of the node, in order (terms, factors, the base, the argument).
    ///
    /// ```
    /// use precess_core::sym::Arena;
    /// let mut a = Arena::new();
    /// let x = a.parameter("x");
    /// let s = a.sin(x);
    /// assert_eq!(a.node(s).children(), &[x]);
    /// ```
    pub fn children(&self) -> &[ExprId] {
        match self {
            Node::Const(_) | Node::Sym(_) => &[],
            Node::Add(c) | Node::Mul(c) => c,
            Node::Pow(b, _) | Node::Powr(b, _) => std::slice::from_ref(b),
            Node::Sqrt(u) | Node::Sin(u) | Node::Cos(u) | Node::Func(_, u) => {
                std::slice::from_ref(u)
            }
        }
    }

    /// True for a leaf (a constant or a symbol).
    pub fn is_leaf(&self) -> bool {
        self.children().is_empty()
    }
}
