//! Canonical constructors: every way to build a sum, product or power goes through here.
//!
//! Invariants kept (see `docs/symbolic.md`):
//! - sums and products are flat, their children sorted by id, with at most one rational
//!   constant, placed first (two only when folding them would overflow);
//! - like terms `c·m` are collected into one term, like factors `b^n` into one power;
//! - a constant times a single sum is distributed, so `2(x + y) − 2x − 2y` is zero;
//! - `sin^n u` with `n ≥ 2` becomes `sin^(n mod 2) u · (1 − cos² u)^(n div 2)`, which keeps
//!   the degree in sin at most one and makes `sin² + cos² − 1` the zero node.

use super::arena::{Arena, ExprId, Node};
use super::error::SymError;
use super::rational::Rational;

impl Arena {
    /// `a + b`.
    pub fn add(&mut self, a: ExprId, b: ExprId) -> ExprId {
        self.sum(&[a, b])
    }

    /// `a − b`.
    pub fn sub(&mut self, a: ExprId, b: ExprId) -> ExprId {
        let nb = self.neg(b);
        self.sum(&[a, nb])
    }

    /// `−a`.
    pub fn neg(&mut self, a: ExprId) -> ExprId {
        let m1 = self.constant(Rational::MINUS_ONE);
        self.product(&[m1, a])
    }

    /// `a · b`.
    pub fn mul(&mut self, a: ExprId, b: ExprId) -> ExprId {
        self.product(&[a, b])
    }

    /// `a / b`.
    ///
    /// # Errors
    /// [`SymError::DivisionByZero`] if `b` is identically zero, tested on its expanded,
    /// trig-canonical form, so `(sin x + cos x)² − 1 − 2 sin x cos x` is caught too.
    pub fn div(&mut self, a: ExprId, b: ExprId) -> Result<ExprId, SymError> {
        let r = self.recip(b)?;
        Ok(self.mul(a, r))
    }

    /// `1 / a`.
    ///
    /// # Errors
    /// [`SymError::DivisionByZero`] if `a` is identically zero ([`Arena::is_zero`]);
    /// [`SymError::ForeignExpression`] for an id of another arena.
    pub fn recip(&mut self, a: ExprId) -> Result<ExprId, SymError> {
        if self.is_zero(a)? {
            return Err(SymError::DivisionByZero {
                divisor: self.display(a),
            });
        }
        self.powi(a, -1)
    }

    /// `a · c` for a rational `c`.
    pub fn scale(&mut self, c: Rational, a: ExprId) -> ExprId {
        let k = self.constant(c);
        self.mul(k, a)
    }

    /// The sum of `terms` (zero for none).
    pub fn sum(&mut self, terms: &[ExprId]) -> ExprId {
        // Flatten, then split every term into (coefficient, monomial).
        let mut consts: Vec<Rational> = Vec::new();
        // (monomial, coefficient, the term as given).
        let mut split: Vec<(ExprId, Rational, ExprId)> = Vec::with_capacity(terms.len());
        let mut stack: Vec<ExprId> = terms.iter().rev().copied().collect();
        while let Some(t) = stack.pop() {
            match self.node(t) {
                Node::Add(children) => stack.extend(children.iter().rev()),
                Node::Const(r) => fold_into(&mut consts, *r, Rational::checked_add),
                _ => {
                    let (c, m) = self.split_coefficient(t);
                    split.push((m, c, t));
                }
            }
        }
        // Collect like terms: sort by monomial, then add coefficients of equal monomials.
        split.sort_by_key(|&(m, _, _)| m);
        let mut out: Vec<ExprId> = Vec::with_capacity(split.len() + 1);
        let mut i = 0;
        while i < split.len() {
            let m = split[i].0;
            // A monomial met once keeps its (canonical) term: c·m rebuilt is that node.
            if split.get(i + 1).is_none_or(|next| next.0 != m) {
                out.push(split[i].2);
                i += 1;
                continue;
            }
            let mut coeffs = vec![split[i].1];
            i += 1;
            while i < split.len() && split[i].0 == m {
                fold_into(&mut coeffs, split[i].1, Rational::checked_add);
                i += 1;
            }
            for c in coeffs.into_iter().filter(|c| !c.is_zero()) {
                let term = self.scale_monomial(c, m);
                out.push(term);
            }
        }
        // Scaling can itself produce a sum (a constant times a single sum), so re-run
        // when that happens; it cannot recur further because the inner sum is canonical.
        if out.iter().any(|&t| matches!(self.node(t), Node::Add(_))) {
            let mut all: Vec<ExprId> = consts.iter().map(|&c| self.constant(c)).collect();
            all.extend(out);
            return self.sum(&all);
        }
        out.sort();
        let mut children: Vec<ExprId> = consts
            .into_iter()
            .filter(|c| !c.is_zero())
            .map(|c| self.constant(c))
            .collect();
        children.extend(out);
        match children.len() {
            0 => self.zero(),
            1 => children[0],
            _ => self.intern(Node::Add(children.into_boxed_slice())),
        }
    }

    /// `c · m` for a monomial `m` (no coefficient of its own).
    pub(crate) fn scale_monomial(&mut self, c: Rational, m: ExprId) -> ExprId {
        if c.is_one() {
            return m;
        }
        let k = self.constant(c);
        self.product(&[k, m])
    }

    /// Splits a term into its rational coefficient and the rest: `3xy → (3, xy)`.
    pub fn split_coefficient(&mut self, t: ExprId) -> (Rational, ExprId) {
        match self.node(t) {
            Node::Const(r) => (*r, self.one()),
            Node::Mul(f) => match self.node(f[0]) {
                Node::Const(r) if f.len() == 2 || !matches!(self.node(f[1]), Node::Const(_)) => {
                    let r = *r;
                    let rest: Vec<ExprId> = f[1..].to_vec();
                    let m = if rest.len() == 1 {
                        rest[0]
                    } else {
                        self.intern(Node::Mul(rest.into_boxed_slice()))
                    };
                    (r, m)
                }
                _ => (Rational::ONE, t),
            },
            _ => (Rational::ONE, t),
        }
    }

    /// The product of `factors` (one for none).
    pub fn product(&mut self, factors: &[ExprId]) -> ExprId {
        let mut coeffs: Vec<Rational> = Vec::new();
        let mut powers: Vec<(ExprId, i64)> = Vec::with_capacity(factors.len());
        let mut stack: Vec<ExprId> = factors.to_vec();
        while let Some(f) = stack.pop() {
            match self.node(f) {
                Node::Mul(children) => stack.extend(children.iter()),
                Node::Const(r) => fold_into(&mut coeffs, *r, Rational::checked_mul),
                Node::Pow(b, n) => powers.push((*b, *n)),
                _ => powers.push((f, 1)),
            }
        }
        if coeffs.iter().any(|c| c.is_zero()) {
            return self.zero();
        }
        powers.sort_by_key(|&(b, _)| b);
        let mut out: Vec<ExprId> = Vec::with_capacity(powers.len());
        let mut renormalise = false;
        let mut i = 0;
        while i < powers.len() {
            let (b, mut n) = powers[i];
            i += 1;
            while i < powers.len() && powers[i].0 == b {
                match n.checked_add(powers[i].1) {
                    Some(s) => n = s,
                    None => {
                        // Keep the overflowing power as its own factor: exact, unfolded.
                        out.push(self.intern(Node::Pow(b, n)));
                        n = powers[i].1;
                    }
                }
                i += 1;
            }
            if n == 0 {
                continue;
            }
            let p = self.pow_nonzero_base(b, n);
            renormalise |= matches!(self.node(p), Node::Mul(_) | Node::Const(_));
            out.push(p);
        }
        if renormalise {
            // A power rule produced a constant or a product (√u² = u with u a product):
            // fold it in once more.
            let mut all: Vec<ExprId> = coeffs.iter().map(|&c| self.constant(c)).collect();
            all.extend(out);
            return self.product(&all);
        }
        out.sort();
        let coeff = match coeffs.as_slice() {
            [] => Rational::ONE,
            [c] => *c,
            _ => {
                let mut children: Vec<ExprId> = coeffs.iter().map(|&c| self.constant(c)).collect();
                children.extend(out);
                return self.intern(Node::Mul(children.into_boxed_slice()));
            }
        };
        match (coeff.is_one(), out.len()) {
            (_, 0) => self.constant(coeff),
            (true, 1) => out[0],
            (false, 1) if matches!(self.node(out[0]), Node::Add(_)) => {
                // Distribute a constant over a single sum.
                let Node::Add(terms) = self.node(out[0]).clone() else {
                    unreachable!("matched just above")
                };
                let scaled: Vec<ExprId> = terms.iter().map(|&t| self.scale(coeff, t)).collect();
                self.sum(&scaled)
            }
            _ => {
                let mut children = Vec::with_capacity(out.len() + 1);
                if !coeff.is_one() {
                    children.push(self.constant(coeff));
                }
                children.extend(out);
                self.intern(Node::Mul(children.into_boxed_slice()))
            }
        }
    }

    /// `a^n` for an integer `n`.
    ///
    /// # Errors
    /// [`SymError::ZeroToNegativePower`] for `0^n` with `n < 0`;
    /// [`SymError::DivisionByZero`] if `n < 0` and `a` is identically zero;
    /// [`SymError::ForeignExpression`] for an id of another arena.
    pub fn powi(&mut self, a: ExprId, n: i64) -> Result<ExprId, SymError> {
        self.check_owned(&[a])?;
        match (self.node(a), n) {
            (_, 0) => Ok(self.one()),
            (_, 1) => Ok(a),
            (Node::Const(r), _) if r.is_zero() && n < 0 => {
                Err(SymError::ZeroToNegativePower { exponent: n })
            }
            (Node::Const(_), _) => Ok(self.pow_nonzero_base(a, n)),
            (Node::Pow(_, m), _) if m.checked_mul(n).is_none() => {
                Err(SymError::ExponentOverflow { a: *m, b: n })
            }
            _ => {
                if n < 0 && self.is_zero(a)? {
                    return Err(SymError::DivisionByZero {
                        divisor: self.display(a),
                    });
                }
                Ok(self.pow_nonzero_base(a, n))
            }
        }
    }

    /// `b^n` where `b` is not the constant zero when `n < 0` (checked by callers) and
    /// `n != 0`.
    pub(crate) fn pow_nonzero_base(&mut self, b: ExprId, n: i64) -> ExprId {
        if n == 1 {
            return b;
        }
        match self.node(b).clone() {
            Node::Const(r) => match r.checked_pow(n) {
                Some(v) => self.constant(v),
                None => self.intern(Node::Pow(b, n)),
            },
            Node::Pow(base, m) => match m.checked_mul(n) {
                Some(0) => self.one(),
                Some(mn) => self.pow_nonzero_base(base, mn),
                None => self.intern(Node::Pow(b, n)),
            },
            Node::Mul(factors) => {
                let ps: Vec<ExprId> = factors
                    .iter()
                    .map(|&f| self.pow_nonzero_base(f, n))
                    .collect();
                self.product(&ps)
            }
            Node::Sqrt(u) if n % 2 == 0 => self.pow_nonzero_base(u, n / 2),
            Node::Sin(u) if n >= 2 => {
                // sin² u = 1 − cos² u keeps the degree in sin at most one.
                let c = self.cos(u);
                let c2 = self.pow_nonzero_base(c, 2);
                let one = self.one();
                let s2 = self.sub(one, c2);
                let half = self.pow_nonzero_base(s2, n / 2);
                if n % 2 == 1 {
                    let s = self.sin(u);
                    self.product(&[s, half])
                } else {
                    half
                }
            }
            _ => self.intern(Node::Pow(b, n)),
        }
    }
}

/// Folds `r` into the last accumulated constant, or starts a new one if that overflows.
fn fold_into(acc: &mut Vec<Rational>, r: Rational, op: fn(Rational, Rational) -> Option<Rational>) {
    match acc.last_mut() {
        Some(last) => match op(*last, r) {
            Some(v) => *last = v,
            None => acc.push(r),
        },
        None => acc.push(r),
    }
}
