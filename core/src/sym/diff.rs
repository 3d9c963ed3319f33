//! Differentiation, the total time derivative, and substitution.

use super::arena::{Arena, ExprId, Node, SymbolId, SymbolKind};
use super::error::SymError;
use super::hash::IdMap;
use super::rational::Rational;

impl Arena {
    /// ∂e/∂s, memoised per (node, symbol).
    ///
    /// ```
    /// use precess_core::sym::Arena;
    /// let mut a = Arena::new();
    /// let x = a.coordinate("x");
    /// let s = a.as_symbol(x).unwrap();
    /// let e = a.sin(x);
    /// let e2 = a.powi(e, 2).unwrap(); // sin²x = 1 − cos²x
    /// let d = a.diff(e2, s);
    /// // d/dx sin²x = 2 sin x cos x
    /// let (two, s, c) = (a.integer(2), a.sin(x), a.cos(x));
    /// let expected = a.product(&[two, s, c]);
    /// assert_eq!(a.expand(d), expected);
    /// ```
    pub fn diff(&mut self, e: ExprId, s: SymbolId) -> ExprId {
        if let Some(&d) = self.memo.diff.get(&(e, s)) {
            return d;
        }
        let d = match self.node(e).clone() {
            Node::Const(_) => self.zero(),
            Node::Sym(t) => {
                if t == s {
                    self.one()
                } else {
                    self.zero()
                }
            }
            Node::Add(terms) => {
                let ds: Vec<ExprId> = terms.iter().map(|&t| self.diff(t, s)).collect();
                self.sum(&ds)
            }
            Node::Mul(factors) => {
                let mut terms = Vec::new();
                for i in 0..factors.len() {
                    let di = self.diff(factors[i], s);
                    if di == self.zero() {
                        continue;
                    }
                    let mut prod: Vec<ExprId> = Vec::with_capacity(factors.len());
                    prod.extend(
                        factors
                            .iter()
                            .enumerate()
                            .filter(|&(j, _)| j != i)
                            .map(|(_, &f)| f),
                    );
                    prod.push(di);
                    terms.push(self.product(&prod));
                }
                self.sum(&terms)
            }
            Node::Pow(b, n) => {
                let db = self.diff(b, s);
                if db == self.zero() {
                    self.zero()
                } else {
                    // n b^(n−1) b′, written b^n · b^−1 so that no exponent arithmetic can
                    // overflow here (the product keeps an overflowing pair unfolded).
                    let inv = self.pow_nonzero_base(b, -1);
                    let lower = self.mul(e, inv);
                    let k = self.integer(n);
                    self.product(&[k, lower, db])
                }
            }
            Node::Sqrt(u) => {
                let du = self.diff(u, s);
                if du == self.zero() {
                    self.zero()
                } else {
                    // d√u = u′ / (2√u); √u is not identically zero here, it is a node.
                    let half = self.constant(Rational::new(1, 2).unwrap_or(Rational::ONE));
                    let root = self.intern(Node::Sqrt(u));
                    let inv = self.intern(Node::Pow(root, -1));
                    self.product(&[half, inv, du])
                }
            }
            Node::Sin(u) => {
                let du = self.diff(u, s);
                let c = self.cos(u);
                self.mul(c, du)
            }
            Node::Cos(u) => {
                let du = self.diff(u, s);
                let sn = self.sin(u);
                let m = self.mul(sn, du);
                self.neg(m)
            }
        };
        self.memo.diff.insert((e, s), d);
        d
    }

    /// The symbols `e` depends on, in symbol order.
    pub fn free_symbols(&self, e: ExprId) -> Vec<SymbolId> {
        let mut seen = vec![false; e.index() + 1];
        let mut stack = vec![e];
        let mut syms = Vec::new();
        while let Some(n) = stack.pop() {
            if std::mem::replace(&mut seen[n.index()], true) {
                continue;
            }
            match self.node(n) {
                Node::Const(_) => {}
                Node::Sym(s) => syms.push(*s),
                Node::Add(c) | Node::Mul(c) => stack.extend(c.iter()),
                Node::Pow(b, _) => stack.push(*b),
                Node::Sqrt(u) | Node::Sin(u) | Node::Cos(u) => stack.push(*u),
            }
        }
        syms.sort();
        syms
    }

    /// The total time derivative d e/dt = ∂e/∂t + Σ ∂e/∂q q̇ + Σ ∂e/∂q̇ q̈ + …, over every
    /// coordinate and coordinate derivative in `e`; parameters are constant.
    pub fn dt(&mut self, e: ExprId) -> ExprId {
        let mut terms = Vec::new();
        for s in self.free_symbols(e) {
            let rate = match self.symbol(s).kind {
                SymbolKind::Parameter | SymbolKind::Input => continue,
                SymbolKind::Time => self.one(),
                SymbolKind::Coordinate | SymbolKind::Derivative { .. } => match self.rate_of(s) {
                    Some(r) => self.symbol_expr(r),
                    // Past the 255th derivative there is no symbol left to name.
                    None => continue,
                },
            };
            let partial = self.diff(e, s);
            terms.push(self.mul(partial, rate));
        }
        self.sum(&terms)
    }

    /// `e` with each symbol in `map` replaced by its expression, rebuilt canonically.
    ///
    /// # Errors
    /// [`SymError::DivisionByZero`] (or another constructor error) if the substitution makes
    /// a divisor vanish or a root's argument a negative constant.
    pub fn subs(&mut self, e: ExprId, map: &[(SymbolId, ExprId)]) -> Result<ExprId, SymError> {
        let mut memo: IdMap<ExprId, ExprId> = IdMap::default();
        self.subs_memo(e, map, &mut memo)
    }

    fn subs_memo(
        &mut self,
        e: ExprId,
        map: &[(SymbolId, ExprId)],
        memo: &mut IdMap<ExprId, ExprId>,
    ) -> Result<ExprId, SymError> {
        if let Some(&r) = memo.get(&e) {
            return Ok(r);
        }
        let r = match self.node(e).clone() {
            Node::Const(_) => e,
            Node::Sym(s) => map.iter().find(|(k, _)| *k == s).map_or(e, |&(_, v)| v),
            Node::Add(t) => {
                let v = t
                    .iter()
                    .map(|&x| self.subs_memo(x, map, memo))
                    .collect::<Result<Vec<_>, _>>()?;
                self.sum(&v)
            }
            Node::Mul(f) => {
                let v = f
                    .iter()
                    .map(|&x| self.subs_memo(x, map, memo))
                    .collect::<Result<Vec<_>, _>>()?;
                self.product(&v)
            }
            Node::Pow(b, n) => {
                let b = self.subs_memo(b, map, memo)?;
                self.powi(b, n)?
            }
            Node::Sqrt(u) => {
                let u = self.subs_memo(u, map, memo)?;
                self.sqrt(u)?
            }
            Node::Sin(u) => {
                let u = self.subs_memo(u, map, memo)?;
                self.sin(u)
            }
            Node::Cos(u) => {
                let u = self.subs_memo(u, map, memo)?;
                self.cos(u)
            }
        };
        memo.insert(e, r);
        Ok(r)
    }
}
