//! Fast paths of the expansion for its commonest step, the product of two monomials.
//!
//! Multiplying out a product of sums makes one monomial product per pair of terms, and the
//! same pairs recur from one entry of a mass matrix to the next (the Whipple bicycle's mass
//! matrix made 128 000 of them, 50 000 distinct). The general constructor
//! ([`Arena::product`]) flattens, sorts and folds powers for each, and a sine squared
//! becomes a sum the expansion then distributes; here the factors of two monomials are
//! merged base by base into the node the constructor would build, sin^(2k+r) is spread into
//! its binomial terms directly, each pair is remembered, and a sum of distinct monomials is
//! assembled without being split and collected again. Each result is the very node the
//! general path builds (`monomial_products_are_the_constructors`); only the order in which
//! nodes are created, and so the order of a sum's terms, differs.

use super::arena::{Arena, ExprId, Node};
use super::rational::Rational;

/// A monomial product as remembered: one monomial with coefficient one (the common case),
/// or the terms of a product a power rule turned into a sum (sin² = 1 − cos²).
#[derive(Clone, Debug)]
pub(crate) enum Product {
    /// The product is this monomial.
    Monomial(ExprId),
    /// The product's (coefficient, monomial) terms.
    Terms(Box<[(Rational, ExprId)]>),
}

/// A monomial's factors while it is merged: (the factor as it stands, or `None` where its
/// exponent changed; base; exponent).
type Merged = Vec<(Option<ExprId>, ExprId, i64)>;

/// The most factors a fast-path monomial holds; larger ones take the general path.
const MAX_FACTORS: usize = 24;

impl Arena {
    /// Pushes `m`'s factors as (factor, base, exponent); false where `m` is not a plain
    /// monomial the fast path may merge (a constant or a sum inside, or too many factors).
    fn monomial_factors(&self, m: ExprId, out: &mut Vec<(ExprId, ExprId, i64)>) -> bool {
        let plain = |a: &Arena, f: ExprId| -> Option<(ExprId, i64)> {
            match a.node(f) {
                Node::Const(_) | Node::Add(_) | Node::Mul(_) => None,
                Node::Pow(b, n) => match a.node(*b) {
                    Node::Const(_) => None,
                    Node::Add(_) if *n > 0 => None,
                    _ => Some((*b, *n)),
                },
                _ => Some((f, 1)),
            }
        };
        match self.node(m) {
            Node::Mul(fs) => {
                if out.len() + fs.len() > MAX_FACTORS {
                    return false;
                }
                for &f in fs.iter() {
                    let Some((b, n)) = plain(self, f) else {
                        return false;
                    };
                    out.push((f, b, n));
                }
                true
            }
            _ => match plain(self, m) {
                Some((b, n)) => {
                    out.push((m, b, n));
                    true
                }
                None => false,
            },
        }
    }

    /// `m1 · m2` for two monomials, expanded, as [`Arena::product`] then [`Arena::expand`]
    /// build it: the factors merged base by base, a sine raised past one folded by
    /// sin^(2k+r) = sin^r (1 − cos²)^k into its binomial terms; `None` where another power
    /// rule applies (an even power of a square root, a sum raised) or the monomials are
    /// not plain.
    pub(crate) fn monomial_product(&mut self, m1: ExprId, m2: ExprId) -> Option<Product> {
        let mut f: Vec<(ExprId, ExprId, i64)> = Vec::with_capacity(16);
        if !self.monomial_factors(m1, &mut f) || !self.monomial_factors(m2, &mut f) {
            return None;
        }
        f.sort_unstable_by_key(|&(_, b, _)| b);
        // (factor, base, exponent) merged; factor is None where the exponent changed.
        let mut merged: Merged = Vec::with_capacity(f.len());
        // Each sine folded: (the cosine of its argument, k of (1 − cos²)^k).
        let mut folded: Vec<(ExprId, i64)> = Vec::new();
        let mut i = 0;
        while i < f.len() {
            let (factor, b, n) = f[i];
            // Each monomial holds a base once, so a base occurs at most twice.
            if i + 1 < f.len() && f[i + 1].1 == b {
                let n = n.checked_add(f[i + 1].2)?;
                i += 2;
                if n == 0 {
                    continue;
                }
                match self.node(b) {
                    Node::Sin(u) if n >= 2 => {
                        let u = *u;
                        let c = self.cos(u);
                        if !matches!(self.node(c), Node::Cos(_)) {
                            return None;
                        }
                        folded.push((c, n / 2));
                        if n % 2 == 1 {
                            merged.push((Some(b), b, 1));
                        }
                    }
                    Node::Sqrt(_) if n % 2 == 0 => return None,
                    Node::Add(_) if n > 0 => return None,
                    _ => merged.push((None, b, n)),
                }
            } else {
                merged.push((Some(factor), b, n));
                i += 1;
            }
        }
        if folded.is_empty() {
            return Some(Product::Monomial(self.monomial_of(&merged)));
        }
        // Π (1 − c²)^k = Σ_j C(k, j) (−1)^j c^(2j), one cosine at a time.
        let mut terms: Vec<(Rational, Merged)> = vec![(Rational::ONE, merged)];
        for (c, k) in folded {
            let mut next = Vec::with_capacity(terms.len() * (k as usize + 1));
            for (coefficient, factors) in &terms {
                let mut binomial: i64 = 1;
                for j in 0..=k {
                    let sign = if j % 2 == 0 { 1 } else { -1 };
                    let b = Rational::integer(binomial.checked_mul(sign)?);
                    let mut fs = factors.clone();
                    if j > 0 {
                        match fs.iter_mut().find(|(_, base, _)| *base == c) {
                            Some(entry) => {
                                entry.2 = entry.2.checked_add(2 * j)?;
                                entry.0 = None;
                            }
                            None => fs.push((None, c, 2 * j)),
                        }
                        fs.retain(|&(_, _, n)| n != 0);
                    }
                    next.push((coefficient.checked_mul(b)?, fs));
                    binomial = binomial.checked_mul(k - j)? / (j + 1);
                }
            }
            terms = next;
        }
        let mut out: Vec<(Rational, ExprId)> = Vec::with_capacity(terms.len());
        for (coefficient, factors) in terms {
            let m = self.monomial_of(&factors);
            match out.iter_mut().find(|(_, seen)| *seen == m) {
                Some(entry) => entry.0 = entry.0.checked_add(coefficient)?,
                None => out.push((coefficient, m)),
            }
        }
        out.retain(|(c, _)| !c.is_zero());
        Some(Product::Terms(out.into_boxed_slice()))
    }

    /// The canonical monomial of merged (factor, base, exponent) entries, a new power
    /// interned where the factor changed.
    fn monomial_of(&mut self, merged: &[(Option<ExprId>, ExprId, i64)]) -> ExprId {
        let mut out: Vec<ExprId> = merged
            .iter()
            .map(|&(factor, b, n)| match factor {
                Some(f) => f,
                None if n == 1 => b,
                None => self.intern(Node::Pow(b, n)),
            })
            .collect();
        out.sort_unstable();
        match out.len() {
            0 => self.one(),
            1 => out[0],
            _ => self.intern(Node::Mul(out.into_boxed_slice())),
        }
    }

    /// `m1 · m2` expanded, remembered per pair.
    pub(crate) fn remembered_product(&mut self, m1: ExprId, m2: ExprId) -> Product {
        let one = self.one();
        if m1 == one {
            return Product::Monomial(m2);
        }
        if m2 == one {
            return Product::Monomial(m1);
        }
        let key = if m1 <= m2 { (m1, m2) } else { (m2, m1) };
        if let Some(p) = self.memo.products.get(&key) {
            return p.clone();
        }
        let p = match self.monomial_product(m1, m2) {
            Some(p) => p,
            None => {
                let p = self.mul(m1, m2);
                let p = if self.has_sum_factor(p) {
                    self.expand(p)
                } else {
                    p
                };
                match self.split_terms(p).as_slice() {
                    [(c, m)] if c.is_one() => Product::Monomial(*m),
                    terms => Product::Terms(terms.into()),
                }
            }
        };
        self.memo.products.insert(key, p.clone());
        p
    }

    /// `c · m` for a monomial `m`, as [`Arena::product`] builds it, without its sort.
    pub(crate) fn scaled_monomial(&mut self, c: Rational, m: ExprId) -> ExprId {
        if c.is_one() {
            return m;
        }
        let direct = match self.node(m) {
            Node::Mul(fs) => !fs.iter().any(|&f| matches!(self.node(f), Node::Const(_))),
            Node::Const(_) | Node::Add(_) => false,
            Node::Pow(b, _) => !matches!(self.node(*b), Node::Const(_)),
            _ => true,
        };
        if !direct {
            return self.scale_monomial(c, m);
        }
        let k = self.constant(c);
        let children: Box<[ExprId]> = match self.node(m) {
            Node::Mul(fs) => std::iter::once(k).chain(fs.iter().copied()).collect(),
            _ => Box::new([k, m]),
        };
        self.intern(Node::Mul(children))
    }
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;

    /// Atoms of monomials: symbols, sines and cosines (of one angle and of a sum), a square
    /// root, a sum (raised only to negative powers: a denominator).
    fn atoms(a: &mut Arena) -> Vec<ExprId> {
        let (x, y, p) = (a.coordinate("x"), a.coordinate("y"), a.parameter("p"));
        let xy = a.add(x, y);
        let one = a.one();
        let p2 = a.mul(p, p);
        let under = a.add(one, p2);
        vec![
            x,
            p,
            a.sin(x),
            a.cos(x),
            a.sin(xy),
            a.cos(xy),
            a.sqrt(under).expect("1 + p² ≥ 1"),
            under,
        ]
    }

    /// A monomial of the atoms at the given exponents (a sum only below zero).
    fn monomial(a: &mut Arena, atoms: &[ExprId], exponents: &[i64]) -> ExprId {
        let factors: Vec<ExprId> = atoms
            .iter()
            .zip(exponents)
            .enumerate()
            .map(|(i, (&b, &n))| {
                let n = if i == atoms.len() - 1 { -n.abs() } else { n };
                a.powi(b, n).expect("no atom is zero")
            })
            .collect();
        a.product(&factors)
    }

    fn sorted(mut terms: Vec<(Rational, ExprId)>) -> Vec<(Rational, ExprId)> {
        terms.sort_by_key(|&(_, m)| m);
        terms
    }

    proptest! {
        /// The fast path builds the very nodes of the general constructor and expansion,
        /// and their value is the product's.
        #[test]
        fn monomial_products_are_the_constructors(
            e1 in proptest::collection::vec(-3i64..=3, 8),
            e2 in proptest::collection::vec(-3i64..=3, 8),
            point in proptest::collection::vec(0.1f64..1.2, 3),
        ) {
            let mut a = Arena::new();
            let atoms = atoms(&mut a);
            let m1 = monomial(&mut a, &atoms, &e1);
            let m2 = monomial(&mut a, &atoms, &e2);
            let (c1, m1) = a.split_coefficient(m1);
            let (c2, m2) = a.split_coefficient(m2);
            prop_assert!(c1.is_one() && c2.is_one());
            let general = a.mul(m1, m2);
            let general = a.expand(general);
            let want = sorted(a.split_terms(general));
            let got = match a.monomial_product(m1, m2) {
                Some(Product::Monomial(m)) => vec![(Rational::ONE, m)],
                Some(Product::Terms(t)) => sorted(t.into_vec()),
                // Only an even power of the root or a raised sum leaves the fast path.
                None => return Ok(()),
            };
            prop_assert_eq!(&got, &want);
            let env = point;
            let value = a.eval(m1, &env) * a.eval(m2, &env);
            let sum: f64 = got.iter().map(|&(c, m)| c.to_f64() * a.eval(m, &env)).sum();
            prop_assert!((sum - value).abs() <= 1e-9 * value.abs().max(1.0));
            // A scaled monomial and a sum of distinct ones, as the constructors build them.
            let k = Rational::integer(-3);
            let scaled = a.scaled_monomial(k, m1);
            prop_assert_eq!(scaled, a.scale_monomial(k, m1));
        }
    }

    #[test]
    fn sums_of_distinct_terms_are_the_constructors() {
        let mut a = Arena::new();
        let atoms = atoms(&mut a);
        let one = a.one();
        let terms: Vec<(Rational, ExprId)> = vec![
            (Rational::integer(2), atoms[0]),
            (Rational::integer(-1), one),
            (Rational::ONE, atoms[2]),
            (Rational::new(3, 4).expect("a fraction"), atoms[3]),
        ];
        let parts: Vec<ExprId> = terms.iter().map(|&(c, m)| a.scale_monomial(c, m)).collect();
        let want = a.sum(&parts);
        assert_eq!(a.sum_of_terms(&terms), want);
    }
}
