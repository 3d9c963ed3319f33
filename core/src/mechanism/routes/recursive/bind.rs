//! Named intermediates: each quantity the algorithm hands from one link to the next is bound
//! to a symbol standing for its expression, so later sums hold it as one atom.
//!
//! Without this the canonical constructors undo the sharing the recursion relies on: a sum is
//! flattened into every sum it enters and a rational times a sum is distributed over its terms
//! (right for a canonical form, wrong for O(n)), so the articulated inertia of the root would
//! hold every descendant's terms and the code would grow as n². A bound intermediate is an
//! abbreviation in the arena's sense: evaluation, lowering, differentiation and zero tests
//! look through it to its definition, and `Program::lower` computes it once. Unlike
//! [`Arena::abbreviate`] the definitions here depend on q and q̇: they are meant for
//! lowering, evaluation and `diff`, not for `Arena::dt` (which treats abbreviations as
//! constants).

use crate::sym::{Arena, ExprId, IdMap, Node, SymbolKind};

/// Binds expressions to symbols, each distinct expression once.
#[derive(Default)]
pub(crate) struct Binder {
    bound: IdMap<ExprId, ExprId>,
}

impl Binder {
    /// `e` itself if it is already an atom (a constant or a symbol), else its symbol.
    pub(crate) fn bind(&mut self, arena: &mut Arena, e: ExprId) -> ExprId {
        if matches!(arena.node(e), Node::Const(_) | Node::Sym(_)) {
            return e;
        }
        // A negative expression is bound as −(its magnitude): the sign then stays visible to
        // the canonical constructors, so x + (−x) cancels and a sum subtracts the atom
        // instead of the code negating it first.
        if is_negative(arena, e) {
            let magnitude = arena.neg(e);
            let s = self.bind(arena, magnitude);
            return arena.neg(s);
        }
        if let Some(&s) = self.bound.get(&e) {
            return s;
        }
        let name = format!("aba{}", self.bound.len());
        let s = arena.new_symbol(&name, name.clone(), SymbolKind::Abbreviation);
        arena.definitions.insert(s, e);
        let x = arena.symbol_expr(s);
        self.bound.insert(e, x);
        x
    }

    pub(crate) fn bind3(&mut self, arena: &mut Arena, v: &[ExprId; 3]) -> [ExprId; 3] {
        v.map(|e| self.bind(arena, e))
    }
}

/// Whether `e` reads as negative: a product with a negative rational coefficient, or a sum
/// whose every term does.
fn is_negative(arena: &Arena, e: ExprId) -> bool {
    match arena.node(e) {
        Node::Mul(factors) => {
            matches!(factors.first().map(|&f| arena.node(f)), Some(Node::Const(r)) if r.is_negative())
        }
        Node::Add(terms) => terms
            .iter()
            .all(|&t| matches!(arena.node(t), Node::Mul(_)) && is_negative(arena, t)),
        _ => false,
    }
}
