//! The engine's one graph walk: every node reachable from some roots, each once, children
//! before parents, with an explicit stack (no recursion, so no depth limit).
//!
//! Ids are numbered children first, so sorting the visited ids by position is a post-order;
//! the transforms (expansion, differentiation, substitution, evaluation, lowering) process
//! that list front to back, each node's children already done.

use super::arena::{Arena, ExprId, Node, SymbolId};
use super::hash::IdMap;

impl Arena {
    /// Every node reachable from `roots` (the roots included), each once, children before
    /// parents. Abbreviations are leaves here; see [`Arena::abbreviate`].
    ///
    /// ```
    /// use precess_core::sym::Arena;
    /// let mut a = Arena::new();
    /// let x = a.parameter("x");
    /// let s = a.cos(x);
    /// let e = a.mul(s, s);
    /// let order = a.post_order(&[e]);
    /// assert_eq!(order.last(), Some(&e));
    /// assert!(order.iter().position(|&n| n == x) < order.iter().position(|&n| n == s));
    /// ```
    pub fn post_order(&self, roots: &[ExprId]) -> Vec<ExprId> {
        self.walk(roots, false, |_| true)
    }

    /// [`Arena::post_order`], also walking into the definition of each abbreviation met when
    /// `through_definitions`, and into the children of a node only where `descend` says so
    /// (a memoised transform stops at nodes it has done).
    pub(crate) fn walk(
        &self,
        roots: &[ExprId],
        through_definitions: bool,
        mut descend: impl FnMut(ExprId) -> bool,
    ) -> Vec<ExprId> {
        let mut seen: IdMap<ExprId, ()> = IdMap::default();
        let mut out = Vec::new();
        let mut stack: Vec<ExprId> = roots.to_vec();
        while let Some(id) = stack.pop() {
            if seen.insert(id, ()).is_some() {
                continue;
            }
            out.push(id);
            if !descend(id) {
                continue;
            }
            let node = self.node(id);
            stack.extend(node.children().iter().filter(|c| !seen.contains_key(c)));
            if through_definitions
                && let Node::Sym(s) = node
                && let Some(&d) = self.definitions.get(s)
            {
                stack.push(d);
            }
        }
        out.sort_unstable_by_key(|id| id.index());
        out
    }

    /// The ids `e` depends on (itself included), children before parents.
    pub fn reachable(&self, e: ExprId) -> Vec<ExprId> {
        self.post_order(&[e])
    }

    /// The symbols `e` depends on, in symbol order (an abbreviation counts as one symbol).
    pub fn free_symbols(&self, e: ExprId) -> Vec<SymbolId> {
        let mut syms: Vec<SymbolId> = self
            .post_order(&[e])
            .into_iter()
            .filter_map(|n| self.as_symbol(n))
            .collect();
        syms.sort();
        syms.dedup();
        syms
    }
}
