//! Differentiation: the partial derivative and the total time derivative.

use super::arena::{Arena, ExprId, Node, SymbolId, SymbolKind};
use super::rational::Rational;

impl Arena {
    /// ∂e/∂s, memoised per (node, symbol). An abbreviation is differentiated through its
    /// definition (the chain rule), so the result is right for every symbol.
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
        let memo = &self.memo.diff;
        let node = self.node(e);
        let definition_done = match node {
            Node::Sym(t) => self
                .definitions
                .get(t)
                .is_none_or(|d| memo.contains_key(&(*d, s))),
            _ => true,
        };
        if definition_done && node.children().iter().all(|c| memo.contains_key(&(*c, s))) {
            let d = self.diff_node(e, s);
            self.memo.diff.insert((e, s), d);
            return d;
        }
        let order = self.walk(&[e], true, |id| !memo.contains_key(&(id, s)));
        for id in order {
            if !self.memo.diff.contains_key(&(id, s)) {
                let d = self.diff_node(id, s);
                self.memo.diff.insert((id, s), d);
            }
        }
        self.memo.diff.get(&(e, s)).copied().unwrap_or(self.zero())
    }

    /// ∂e/∂s for one node whose children (and definition) are differentiated already.
    fn diff_node(&mut self, e: ExprId, s: SymbolId) -> ExprId {
        let zero = self.zero();
        let d = |a: &Arena, x: ExprId| a.memo.diff.get(&(x, s)).copied().unwrap_or(zero);
        match self.node(e).clone() {
            Node::Const(_) => zero,
            Node::Sym(t) if t == s => self.one(),
            Node::Sym(t) => match self.definitions.get(&t) {
                Some(&def) => d(self, def),
                None => zero,
            },
            Node::Add(terms) => {
                let ds: Vec<ExprId> = terms.iter().map(|&t| d(self, t)).collect();
                self.sum(&ds)
            }
            Node::Mul(factors) => {
                let mut terms = Vec::new();
                for i in 0..factors.len() {
                    let di = d(self, factors[i]);
                    if di == zero {
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
                let db = d(self, b);
                if db == zero {
                    return zero;
                }
                // n b^(n−1) b′, written b^n · b^−1 so that no exponent arithmetic can
                // overflow here (the product keeps an overflowing pair unfolded).
                let inv = self.pow_nonzero_base(b, -1);
                let lower = self.mul(e, inv);
                let k = self.integer(n);
                self.product(&[k, lower, db])
            }
            Node::Powr(b, r) => {
                let db = d(self, b);
                if db == zero {
                    return zero;
                }
                // d b^r = r b^(r−1) b′, written b^r · b^−1 as for integer powers (no
                // exponent arithmetic, and b^r is a node, so b is not identically zero).
                let inv = self.pow_nonzero_base(b, -1);
                let k = self.constant(r);
                self.product(&[k, e, inv, db])
            }
            Node::Sqrt(u) => {
                let du = d(self, u);
                if du == zero {
                    return zero;
                }
                // d√u = u′ / (2√u); √u is not identically zero here, it is a node.
                let half = self.constant(Rational::new(1, 2).unwrap_or(Rational::ONE));
                let root = self.intern(Node::Sqrt(u));
                let inv = self.intern(Node::Pow(root, -1));
                self.product(&[half, inv, du])
            }
            Node::Sin(u) => {
                let du = d(self, u);
                let c = self.cos(u);
                self.mul(c, du)
            }
            Node::Cos(u) => {
                let du = d(self, u);
                let sn = self.sin(u);
                let m = self.mul(sn, du);
                self.neg(m)
            }
            Node::Func(f, u) => {
                let du = d(self, u);
                self.diff_func(f, u, e, du)
            }
        }
    }

    /// The total time derivative d e/dt = ∂e/∂t + Σ ∂e/∂q q̇ + Σ ∂e/∂q̇ q̈ + …, over every
    /// coordinate and coordinate derivative in `e`; parameters, inputs and abbreviations
    /// (which never depend on time) are constant.
    pub fn dt(&mut self, e: ExprId) -> ExprId {
        let mut terms = Vec::new();
        for s in self.free_symbols(e) {
            let rate = match self.symbol(s).kind {
                SymbolKind::Parameter | SymbolKind::Input | SymbolKind::Abbreviation => continue,
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
}
