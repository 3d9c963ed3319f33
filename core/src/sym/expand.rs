//! Expansion into the trig-canonical polynomial form.
//!
//! `expand` distributes products over sums and positive integer powers of sums. Because the
//! constructors already rewrite `sin² u` as `1 − cos² u`, the expanded form of a polynomial in
//! the sines and cosines of its angles (and in any other symbols) is unique: two such
//! polynomials are equal exactly when their expanded ids are equal. Negative powers are kept
//! as denominators (expanded inside), so rational functions are canonical only up to common
//! factors of numerator and denominator.

use super::arena::{Arena, ExprId, Node};

impl Arena {
    /// The expanded, trig-canonical form of `e` (memoised per node).
    ///
    /// ```
    /// use precess_core::sym::Arena;
    /// let mut a = Arena::new();
    /// let x = a.coordinate("x");
    /// let (s, c) = (a.sin(x), a.cos(x));
    /// let sc = a.add(s, c);
    /// let sq = a.powi(sc, 2).unwrap();
    /// let two = a.integer(2);
    /// let two_sc = a.product(&[two, s, c]);
    /// let e = a.sub(sq, two_sc);
    /// // (sin x + cos x)² − 2 sin x cos x = 1
    /// assert_eq!(a.expand(e), a.one());
    /// ```
    pub fn expand(&mut self, e: ExprId) -> ExprId {
        if let Some(&done) = self.memo.expand.get(&e) {
            return done;
        }
        let out = match self.node(e).clone() {
            Node::Const(_) | Node::Sym(_) => e,
            Node::Add(terms) => {
                let ex: Vec<ExprId> = terms.iter().map(|&t| self.expand(t)).collect();
                self.sum(&ex)
            }
            Node::Mul(factors) => {
                let mut acc = vec![self.one()];
                for &f in factors.iter() {
                    let ef = self.expand(f);
                    acc = self.distribute(&acc, ef);
                }
                self.sum(&acc)
            }
            Node::Pow(b, n) if n > 0 => {
                let eb = self.expand(b);
                let mut acc = vec![self.one()];
                for _ in 0..n {
                    acc = self.distribute(&acc, eb);
                }
                self.sum(&acc)
            }
            Node::Pow(b, n) => {
                let eb = self.expand(b);
                // A base that expands to zero was rejected when the power was built; keep
                // the original if substitution made one, rather than invent a value.
                self.powi(eb, n).unwrap_or(e)
            }
            Node::Sqrt(u) => {
                let eu = self.expand(u);
                self.sqrt(eu).unwrap_or(e)
            }
            Node::Sin(u) => {
                let eu = self.expand(u);
                self.sin(eu)
            }
            Node::Cos(u) => {
                let eu = self.expand(u);
                self.cos(eu)
            }
        };
        self.memo.expand.insert(e, out);
        if out != e {
            self.memo.expand.insert(out, out);
        }
        out
    }

    /// The terms of `(Σ acc) · f`, each fully expanded.
    fn distribute(&mut self, acc: &[ExprId], f: ExprId) -> Vec<ExprId> {
        let f_terms: Vec<ExprId> = match self.node(f) {
            Node::Add(t) => t.to_vec(),
            _ => vec![f],
        };
        let mut out = Vec::with_capacity(acc.len() * f_terms.len());
        for &a in acc {
            for &b in &f_terms {
                let p = self.mul(a, b);
                // sin · sin folds to 1 − cos², a new sum: expand that product again.
                if self.has_sum_factor(p) {
                    let ep = self.expand(p);
                    match self.node(ep) {
                        Node::Add(t) => out.extend(t.iter().copied()),
                        _ => out.push(ep),
                    }
                } else {
                    out.push(p);
                }
            }
        }
        out
    }

    /// True if `e` is a sum, or a product or positive power with a sum inside it.
    fn has_sum_factor(&self, e: ExprId) -> bool {
        match self.node(e) {
            Node::Add(_) => true,
            Node::Pow(b, n) => *n > 0 && matches!(self.node(*b), Node::Add(_)),
            Node::Mul(f) => f.iter().any(|&x| self.has_sum_factor(x)),
            _ => false,
        }
    }
}
