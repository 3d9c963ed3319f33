//! Substitution: symbols replaced by expressions, the result rebuilt canonically.

use super::arena::{Arena, ExprId, Node, SymbolId};
use super::error::SymError;
use super::hash::IdMap;

impl Arena {
    /// `e` with each symbol in `map` replaced by its expression, rebuilt canonically. An
    /// abbreviation whose definition holds a replaced symbol is replaced by its substituted
    /// definition.
    ///
    /// ```
    /// use precess_core::sym::Arena;
    /// let mut a = Arena::new();
    /// let (x, y) = (a.parameter("x"), a.parameter("y"));
    /// let e = a.mul(x, y);
    /// let two = a.integer(2);
    /// let sx = a.as_symbol(x).unwrap();
    /// let got = a.subs(e, &[(sx, two)]).unwrap();
    /// assert_eq!(got, a.mul(two, y));
    /// ```
    ///
    /// # Errors
    /// [`SymError::DivisionByZero`] (or another constructor error) if the substitution makes
    /// a divisor vanish or a root's argument a negative constant;
    /// [`SymError::ForeignExpression`] for an id of another arena.
    pub fn subs(&mut self, e: ExprId, map: &[(SymbolId, ExprId)]) -> Result<ExprId, SymError> {
        self.check_owned(&[e])?;
        let values: Vec<ExprId> = map.iter().map(|&(_, v)| v).collect();
        self.check_owned(&values)?;
        let map: IdMap<SymbolId, ExprId> = map.iter().copied().collect();
        let mut done: IdMap<ExprId, ExprId> = IdMap::default();
        for id in self.walk(&[e], true, |_| true) {
            let r = self.subs_node(id, &map, &done)?;
            done.insert(id, r);
        }
        Ok(done.get(&e).copied().unwrap_or(e))
    }

    fn subs_node(
        &mut self,
        id: ExprId,
        map: &IdMap<SymbolId, ExprId>,
        done: &IdMap<ExprId, ExprId>,
    ) -> Result<ExprId, SymError> {
        let d = |x: &ExprId| done.get(x).copied().unwrap_or(*x);
        Ok(match self.node(id).clone() {
            Node::Const(_) => id,
            Node::Sym(s) => match (map.get(&s), self.definitions.get(&s)) {
                (Some(&v), _) => v,
                (None, Some(def)) if d(def) != *def => d(def),
                _ => id,
            },
            Node::Add(t) => {
                let v: Vec<ExprId> = t.iter().map(d).collect();
                self.sum(&v)
            }
            Node::Mul(f) => {
                let v: Vec<ExprId> = f.iter().map(d).collect();
                self.product(&v)
            }
            Node::Pow(b, n) => self.powi(d(&b), n)?,
            Node::Powr(b, r) => self.powr(d(&b), r)?,
            Node::Sqrt(u) => self.sqrt(d(&u))?,
            Node::Sin(u) => self.sin(d(&u)),
            Node::Cos(u) => self.cos(d(&u)),
            Node::Func(f, u) => self.apply(f, d(&u))?,
        })
    }
}
