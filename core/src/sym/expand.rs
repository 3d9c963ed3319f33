//! Expansion into the trig-canonical polynomial form.
//!
//! `expand` distributes products over sums and positive integer powers of sums. Because the
//! constructors already rewrite `sin² u` as `1 − cos² u`, the expanded form of a polynomial in
//! the sines and cosines of its angles (and in any other symbols) is unique: two such
//! polynomials are equal exactly when their expanded ids are equal. Negative powers are kept
//! as denominators (expanded inside), so rational functions are canonical only up to common
//! factors of numerator and denominator.
//!
//! Products are multiplied out one factor at a time into a map from monomial to coefficient,
//! so like terms are collected after every step: `(a + b + c + d + e)¹¹` costs its 1,365
//! terms times the 5 of the base per step, not the 5¹¹ products of naive distribution.

use super::arena::{Arena, ExprId, Node};
use super::error::SymError;
use super::hash::IdMap;
use super::monomial::Product;
use super::rational::Rational;

/// The most terms an expansion may produce; a product or power whose expansion would have
/// more is kept factored ([`Arena::expand`]) or reported ([`Arena::try_expand`]).
pub const MAX_EXPANDED_TERMS: usize = 1 << 20;

/// A polynomial being multiplied out: (coefficient, monomial) pairs, monomials distinct.
type Terms = Vec<(Rational, ExprId)>;

impl Arena {
    /// The expanded, trig-canonical form of `e` (memoised per node).
    ///
    /// A product or positive power whose expansion would exceed [`MAX_EXPANDED_TERMS`] terms
    /// is kept as a product of expanded factors: exact, but not canonical;
    /// [`Arena::try_expand`] reports it instead.
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
        let memo = &self.memo.expand;
        // Most calls meet a node whose children are done: skip the walk's bookkeeping.
        if self.node(e).children().iter().all(|c| memo.contains_key(c)) {
            let out = self.expand_node(e);
            self.memo.expand.insert(e, out);
            self.memo.expand.entry(out).or_insert(out);
            return out;
        }
        let order = self.walk(&[e], false, |id| !memo.contains_key(&id));
        for id in order {
            if self.memo.expand.contains_key(&id) {
                continue;
            }
            let out = self.expand_node(id);
            self.memo.expand.insert(id, out);
            self.memo.expand.entry(out).or_insert(out);
        }
        self.memo.expand.get(&e).copied().unwrap_or(e)
    }

    /// [`Arena::expand`], or an error where the expansion would pass the term limit.
    ///
    /// # Errors
    /// [`SymError::ExpansionTooLarge`] if a product or power in `e` would expand to more
    /// than [`MAX_EXPANDED_TERMS`] terms; [`SymError::ForeignExpression`] for an id of
    /// another arena.
    ///
    /// ```
    /// use precess_core::sym::{Arena, SymError};
    /// let mut a = Arena::new();
    /// let (x, y) = (a.parameter("x"), a.parameter("y"));
    /// let s = a.add(x, y);
    /// let huge = a.powi(s, 1 << 40).unwrap();
    /// assert!(matches!(a.try_expand(huge), Err(SymError::ExpansionTooLarge { .. })));
    /// ```
    pub fn try_expand(&mut self, e: ExprId) -> Result<ExprId, SymError> {
        self.check_owned(&[e])?;
        let out = self.expand(e);
        if !self.memo.too_large.is_empty() {
            let too_large = &self.memo.too_large;
            if let Some(terms) = self
                .post_order(&[e])
                .into_iter()
                .find_map(|n| too_large.get(&n).copied())
            {
                return Err(SymError::ExpansionTooLarge {
                    terms,
                    limit: MAX_EXPANDED_TERMS,
                });
            }
        }
        Ok(out)
    }

    /// Expands one node whose children are expanded already.
    fn expand_node(&mut self, id: ExprId) -> ExprId {
        let done = |a: &Arena, x: ExprId| a.memo.expand.get(&x).copied().unwrap_or(x);
        match self.node(id).clone() {
            Node::Const(_) | Node::Sym(_) => id,
            Node::Add(terms) => {
                let ex: Vec<ExprId> = terms.iter().map(|&t| done(self, t)).collect();
                self.sum(&ex)
            }
            Node::Mul(factors) => {
                let ex: Vec<ExprId> = factors.iter().map(|&f| done(self, f)).collect();
                let size = ex
                    .iter()
                    .fold(1usize, |n, &f| n.saturating_mul(self.term_count(f)));
                if size > MAX_EXPANDED_TERMS {
                    self.memo.too_large.insert(id, size);
                    return self.product(&ex);
                }
                self.expand_product(&ex)
            }
            Node::Pow(b, n) if n > 0 => {
                let eb = done(self, b);
                let k = self.term_count(eb);
                if k == 1 {
                    let p = self.pow_nonzero_base(eb, n);
                    // sinⁿ became sin^(n mod 2)·(1 − cos²)^(n div 2): expand that in turn.
                    return if self.has_sum_factor(p) {
                        self.expand(p)
                    } else {
                        p
                    };
                }
                let size = multinomial_terms(n.unsigned_abs(), k);
                if size > MAX_EXPANDED_TERMS {
                    self.memo.too_large.insert(id, size);
                    return self.pow_nonzero_base(eb, n);
                }
                let base = self.split_terms(eb);
                let mut acc: Terms = vec![(Rational::ONE, self.one())];
                for _ in 0..n {
                    acc = self.multiply_terms(&acc, &base);
                }
                self.sum_of_terms(&acc)
            }
            Node::Pow(b, n) => {
                let eb = done(self, b);
                // A base that expands to zero was rejected when the power was built; keep
                // the original if substitution made one, rather than invent a value.
                self.powi(eb, n).unwrap_or(id)
            }
            Node::Sqrt(u) => {
                let eu = done(self, u);
                self.sqrt(eu).unwrap_or(id)
            }
            // An opaque function of its expanded base.
            Node::Powr(b, r) => {
                let eb = done(self, b);
                self.powr(eb, r).unwrap_or(id)
            }
            Node::Sin(u) => {
                let eu = done(self, u);
                self.sin(eu)
            }
            Node::Cos(u) => {
                let eu = done(self, u);
                self.cos(eu)
            }
            // An opaque function of its expanded argument, as real powers are.
            Node::Func(f, u) => {
                let eu = done(self, u);
                self.apply(f, eu).unwrap_or(id)
            }
        }
    }

    /// Number of terms of an expanded expression.
    fn term_count(&self, e: ExprId) -> usize {
        match self.node(e) {
            Node::Add(t) => t.len(),
            _ => 1,
        }
    }

    /// The terms of `e` as (coefficient, monomial) pairs.
    pub(crate) fn split_terms(&mut self, e: ExprId) -> Terms {
        let terms: Vec<ExprId> = match self.node(e) {
            Node::Add(t) => t.to_vec(),
            _ => vec![e],
        };
        terms
            .into_iter()
            .map(|t| self.split_coefficient(t))
            .collect()
    }

    /// The expanded product of expanded factors.
    fn expand_product(&mut self, factors: &[ExprId]) -> ExprId {
        let mut acc: Terms = vec![(Rational::ONE, self.one())];
        for &f in factors {
            let terms = self.split_terms(f);
            acc = self.multiply_terms(&acc, &terms);
        }
        self.sum_of_terms(&acc)
    }

    /// The sum of `terms`, as [`Arena::sum`] builds it; directly when the monomials are
    /// distinct (as [`Arena::multiply_terms`] leaves them unless a coefficient overflowed).
    pub(crate) fn sum_of_terms(&mut self, terms: &Terms) -> ExprId {
        let one = self.one();
        let mut constant = Some(Rational::ZERO);
        let mut parts: Vec<(ExprId, Rational)> = Vec::with_capacity(terms.len());
        for &(c, m) in terms.iter().filter(|(c, _)| !c.is_zero()) {
            if m == one {
                constant = constant.and_then(|k| k.checked_add(c));
            } else {
                parts.push((m, c));
            }
        }
        parts.sort_unstable_by_key(|&(m, _)| m);
        let distinct = parts.windows(2).all(|w| w[0].0 != w[1].0);
        let Some(constant) = constant.filter(|_| distinct) else {
            let all: Vec<ExprId> = terms
                .iter()
                .map(|&(c, m)| self.scale_monomial(c, m))
                .collect();
            return self.sum(&all);
        };
        let mut out: Vec<ExprId> = parts
            .into_iter()
            .map(|(m, c)| self.scaled_monomial(c, m))
            .collect();
        out.sort_unstable();
        if !constant.is_zero() {
            out.insert(0, self.constant(constant));
        }
        match out.len() {
            0 => self.zero(),
            1 => out[0],
            _ => self.intern(Node::Add(out.into_boxed_slice())),
        }
    }

    /// `(Σ a) · (Σ b)` with like monomials collected; every monomial product is canonical
    /// and expanded (`sin · sin` folds to `1 − cos²`, whose terms are spread out), and
    /// remembered per pair ([`Arena::remembered_product`]).
    fn multiply_terms(&mut self, a: &Terms, b: &Terms) -> Terms {
        let mut index: IdMap<ExprId, usize> = IdMap::default();
        let mut out: Terms = Vec::with_capacity(a.len().max(b.len()));
        for &(c1, m1) in a {
            for &(c2, m2) in b {
                match self.remembered_product(m1, m2) {
                    Product::Monomial(m) => {
                        self.collect_term(&mut index, &mut out, [c1, c2, Rational::ONE], m);
                    }
                    Product::Terms(terms) => {
                        for &(ci, mi) in terms.iter() {
                            self.collect_term(&mut index, &mut out, [c1, c2, ci], mi);
                        }
                    }
                }
            }
        }
        out.retain(|(c, _)| !c.is_zero());
        out
    }

    /// Adds `k₀ k₁ k₂ · m` to `out`, whose monomials `index` locates.
    fn collect_term(
        &mut self,
        index: &mut IdMap<ExprId, usize>,
        out: &mut Terms,
        k: [Rational; 3],
        m: ExprId,
    ) {
        let (c, m) = match k[0].checked_mul(k[1]).and_then(|c| c.checked_mul(k[2])) {
            Some(c) => (c, m),
            None => {
                // Keep the coefficients unfolded inside the term: exact.
                let ks = k.map(|c| self.constant(c));
                let t = self.product(&[ks[0], ks[1], ks[2], m]);
                self.split_coefficient(t)
            }
        };
        match index.get(&m) {
            Some(&i) => match out[i].0.checked_add(c) {
                Some(s) => out[i].0 = s,
                // An overflowing sum of coefficients stays two terms: exact, unfolded.
                None => out.push((c, m)),
            },
            None => {
                index.insert(m, out.len());
                out.push((c, m));
            }
        }
    }

    /// True if `e` is a sum, or a product or positive power with a sum inside it.
    pub(crate) fn has_sum_factor(&self, e: ExprId) -> bool {
        match self.node(e) {
            Node::Add(_) => true,
            Node::Pow(b, n) => *n > 0 && matches!(self.node(*b), Node::Add(_)),
            Node::Mul(f) => f.iter().any(|&x| match self.node(x) {
                Node::Add(_) => true,
                Node::Pow(b, n) => *n > 0 && matches!(self.node(*b), Node::Add(_)),
                _ => false,
            }),
            _ => false,
        }
    }
}

/// The number of monomials of `(x₁ + … + x_k)ⁿ`, C(n + k − 1, k − 1), saturating.
fn multinomial_terms(n: u64, k: usize) -> usize {
    let mut r = 1f64;
    for i in 1..k {
        r *= (n as f64 + i as f64) / i as f64;
        if r > MAX_EXPANDED_TERMS as f64 {
            return usize::MAX;
        }
    }
    r.round() as usize
}
