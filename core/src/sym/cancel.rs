//! Cancelling common factors of a quotient in the trig ring.
//!
//! Mass-matrix determinants of Euler-angle tops are `K · sin²θ`, which the canonical form
//! holds as `K − K cos²θ`; the numerators of the solved accelerations carry a factor sin θ
//! that only shows after expansion. Dividing both by sin θ exactly (using sin² = 1 − cos²)
//! and then by their common monomial factor turns `N / (I₁ I₃ (1 − cos²θ))` into the
//! textbook `N' / (I₁ sin θ)`: one factor of the singularity instead of two, and fewer
//! operations.

use std::collections::BTreeMap;

use super::arena::{Arena, ExprId, Node};

/// The highest power of cos u that [`Arena::div_sin`] divides: the quotient by 1 − cos² u of
/// a polynomial of degree d has about d/2 terms, so past this the division is not tried.
pub const MAX_DIVIDED_DEGREE: i64 = 1 << 12;

/// A term split into its factors `(base, exponent)`, the rational coefficient kept as a
/// factor of exponent 1.
type Factors = Vec<(ExprId, i64)>;

impl Arena {
    fn terms_of(&self, p: ExprId) -> Vec<ExprId> {
        match self.node(p) {
            Node::Add(t) => t.to_vec(),
            _ if p == self.zero() => Vec::new(),
            _ => vec![p],
        }
    }

    fn factors_of(&self, t: ExprId) -> Factors {
        match self.node(t) {
            Node::Mul(f) => f.iter().map(|&x| self.base_exp(x)).collect(),
            _ => vec![self.base_exp(t)],
        }
    }

    fn base_exp(&self, x: ExprId) -> (ExprId, i64) {
        match self.node(x) {
            Node::Pow(b, n) => (*b, *n),
            _ => (x, 1),
        }
    }

    fn rebuild(&mut self, f: &Factors) -> ExprId {
        let parts: Vec<ExprId> = f
            .iter()
            .map(|&(b, n)| self.pow_nonzero_base(b, n))
            .collect();
        self.product(&parts)
    }

    /// `p / sin u` if it is exact in the ring of polynomials in sin u and cos u (and other
    /// symbols), for `p` expanded; the result is expanded. `None` if the division leaves a
    /// remainder, `p` holds negative powers of sin u or cos u, or a power of cos u above
    /// [`MAX_DIVIDED_DEGREE`].
    ///
    /// ```
    /// use precess_core::sym::Arena;
    /// let mut a = Arena::new();
    /// let th = a.coordinate("theta");
    /// let (one, c) = (a.one(), a.cos(th));
    /// let c2 = a.mul(c, c);
    /// let s2 = a.sub(one, c2); // sin²θ in canonical form
    /// assert_eq!(a.div_sin(s2, th), Some(a.sin(th)));
    /// assert_eq!(a.div_sin(c, th), None);
    /// ```
    pub fn div_sin(&mut self, p: ExprId, u: ExprId) -> Option<ExprId> {
        let (sin, cos) = (self.sin(u), self.cos(u));
        // p = A(cos) + sin · B: B is read off the terms with sin; A is grouped by cos degree.
        let mut with_sin = Vec::new();
        let mut by_cos_degree: BTreeMap<i64, Vec<ExprId>> = BTreeMap::new();
        for t in self.terms_of(p) {
            let mut f = self.factors_of(t);
            let sin_exp = take(&mut f, sin);
            let cos_exp = take(&mut f, cos);
            if !(0..=1).contains(&sin_exp) || !(0..=MAX_DIVIDED_DEGREE).contains(&cos_exp) {
                return None;
            }
            if sin_exp == 1 {
                if cos_exp > 0 {
                    f.push((cos, cos_exp));
                }
                with_sin.push(self.rebuild(&f));
            } else {
                let rest = self.rebuild(&f);
                by_cos_degree.entry(cos_exp).or_default().push(rest);
            }
        }
        // A / (1 − cos²) by synthetic division from the top degree: the quotient's
        // coefficient of cosᵏ⁻² is −aₖ, and aₖ carries into aₖ₋₂.
        let top = by_cos_degree.keys().next_back().map_or(0, |&k| k as usize);
        let mut a: Vec<ExprId> = vec![self.zero(); top + 1];
        for (k, v) in &by_cos_degree {
            a[*k as usize] = self.sum(v);
        }
        let mut quotient_terms = Vec::new();
        for k in (2..a.len()).rev() {
            let ak = a[k];
            if ak == self.zero() {
                continue;
            }
            let ck = self.pow_nonzero_base_or_one(cos, k as i64 - 2);
            let q = self.mul(ak, ck);
            quotient_terms.push(self.neg(q));
            a[k - 2] = self.add(a[k - 2], ak);
        }
        for r in a.iter().take(2) {
            let r = self.expand(*r);
            if r != self.zero() {
                return None;
            }
        }
        // p / sin = B + sin · Q, since A = (1 − cos²) Q = sin² Q.
        let q = self.sum(&quotient_terms);
        let sq = self.mul(sin, q);
        let b = self.sum(&with_sin);
        let out = self.add(b, sq);
        Some(self.expand(out))
    }

    fn pow_nonzero_base_or_one(&mut self, b: ExprId, n: i64) -> ExprId {
        if n == 0 {
            self.one()
        } else {
            self.pow_nonzero_base(b, n)
        }
    }

    /// Cancels the common factors of `num / den` (both expanded): powers of sin u for each
    /// angle u in the denominator, then the monomial factors every term shares.
    /// Returns the new (numerator, denominator), equal in value wherever both are defined.
    pub fn cancel(&mut self, num: ExprId, den: ExprId) -> (ExprId, ExprId) {
        let (mut num, mut den) = (self.expand(num), self.expand(den));
        if num == self.zero() {
            return (num, self.one());
        }
        let mut angles: Vec<ExprId> = self
            .reachable(den)
            .into_iter()
            .filter_map(|e| match self.node(e) {
                Node::Sin(u) | Node::Cos(u) => Some(*u),
                _ => None,
            })
            .collect();
        angles.sort();
        angles.dedup();
        for u in angles {
            while let (Some(n), Some(d)) = (self.div_sin(num, u), self.div_sin(den, u)) {
                (num, den) = (n, d);
            }
        }
        // The monomial every term of both shares: the smallest positive power of each base
        // present in all terms (rational coefficients stay).
        let all: Vec<Factors> = self
            .terms_of(num)
            .into_iter()
            .chain(self.terms_of(den))
            .map(|t| self.factors_of(t))
            .collect();
        let Some(first) = all.first() else {
            return (num, den);
        };
        let common: Factors = first
            .iter()
            .filter(|(b, _)| !matches!(self.node(*b), Node::Const(_)))
            .filter_map(|&(b, _)| {
                let min = all
                    .iter()
                    .map(|f| {
                        f.iter()
                            .find(|(x, _)| *x == b)
                            .map_or(0, |&(_, n)| n.max(0))
                    })
                    .min()?;
                (min > 0).then_some((b, -min))
            })
            .collect();
        if common.is_empty() {
            return (num, den);
        }
        let inv = self.rebuild(&common);
        let (n, d) = (self.mul(num, inv), self.mul(den, inv));
        (self.expand(n), self.expand(d))
    }
}

/// Removes the factor `base` from `f`, returning its exponent (0 if absent).
fn take(f: &mut Factors, base: ExprId) -> i64 {
    match f.iter().position(|(b, _)| *b == base) {
        Some(i) => f.remove(i).1,
        None => 0,
    }
}
