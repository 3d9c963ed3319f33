//! Memo tables: nodes never change, so a transform's result for a node stays valid forever.

use super::arena::{ExprId, SymbolId};
use super::hash::IdMap;
use super::monomial::Product;

/// Per-node results of the arena's transforms.
#[derive(Clone, Debug, Default)]
pub(crate) struct Memo {
    pub(crate) diff: IdMap<(ExprId, SymbolId), ExprId>,
    pub(crate) expand: IdMap<ExprId, ExprId>,
    /// Products and powers left factored because their expansion would pass the term
    /// limit, with the number of terms it would have had.
    pub(crate) too_large: IdMap<ExprId, usize>,
    /// The expanded product of two monomials, by the pair (smaller id first).
    pub(crate) products: IdMap<(ExprId, ExprId), Product>,
}
