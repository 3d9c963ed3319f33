//! An expression seen as a polynomial over atoms (symbols, sines, cosines, anything else
//! opaque), the view the paper form regroups. Nothing here builds arena nodes: the engine's
//! canonical form keeps the degree in sin at most one, and the paper form needs sin² too.

use crate::sym::{Arena, ExprId, IdMap, Node, Rational, SymbolKind};

/// Past this many terms a product of sums is left unexpanded (an opaque factor).
const MAX_TERMS: usize = 4096;

/// Largest power of an atom the view holds; an expression with a larger one prints in the
/// engine's form (so the arithmetic on powers here never overflows).
const MAX_POWER: i64 = 1 << 20;

/// A factor of a monomial.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub(super) enum Atom {
    /// A symbol: parameter, abbreviation, coordinate or a derivative of one, input, time.
    Sym(crate::sym::SymbolId),
    /// `sin u`.
    Sin(ExprId),
    /// `cos u`.
    Cos(ExprId),
    /// Any other expression, printed by [`crate::codegen::latex`].
    Other(ExprId),
}

/// Atoms with their nonzero integer powers.
pub(super) type Mono = Vec<(Atom, i64)>;

/// One term: a rational coefficient times atoms to nonzero integer powers, the atoms in
/// their canonical (id) order.
#[derive(Clone, PartialEq, Debug)]
pub(super) struct Term {
    pub coef: Rational,
    pub mono: Mono,
}

impl Term {
    /// The term 1.
    pub fn one() -> Term {
        Term::constant(Rational::ONE)
    }

    fn constant(coef: Rational) -> Term {
        Term {
            coef,
            mono: Vec::new(),
        }
    }

    fn atom(atom: Atom, power: i64) -> Term {
        Term {
            coef: Rational::ONE,
            mono: vec![(atom, power)],
        }
    }

    /// The product of two terms; `None` if the coefficient overflows or a power passes
    /// [`MAX_POWER`].
    pub fn times(&self, other: &Term) -> Option<Term> {
        let mut mono = self.mono.clone();
        for &(a, n) in &other.mono {
            match mono.iter_mut().find(|(b, _)| *b == a) {
                Some((_, m)) => *m = bounded(m.checked_add(n)?)?,
                None => mono.push((a, n)),
            }
        }
        mono.retain(|&(_, n)| n != 0);
        mono.sort();
        Some(Term {
            coef: self.coef.checked_mul(other.coef)?,
            mono,
        })
    }

    /// The power of `atom` in the term (0 if absent).
    pub fn power(&self, atom: Atom) -> i64 {
        self.mono
            .iter()
            .find(|(a, _)| *a == atom)
            .map_or(0, |&(_, n)| n)
    }

    /// The term with `atom` to the power `n` (removed for 0).
    pub fn with_power(&self, atom: Atom, n: i64) -> Term {
        let mut mono: Mono = self
            .mono
            .iter()
            .copied()
            .filter(|(a, _)| *a != atom)
            .collect();
        if n != 0 {
            mono.push((atom, n));
            mono.sort();
        }
        Term {
            coef: self.coef,
            mono,
        }
    }
}

/// The product of two sums, collected; `None` past [`MAX_TERMS`] or on overflow.
pub(super) fn product(a: &[Term], b: &[Term]) -> Option<Vec<Term>> {
    if a.len().saturating_mul(b.len()) > MAX_TERMS {
        return None;
    }
    let mut out = Vec::with_capacity(a.len() * b.len());
    for x in a {
        for y in b {
            out.push(x.times(y)?);
        }
    }
    collect(out)
}

/// Like terms merged (their coefficients added), zeros dropped, in canonical order; `None`
/// if a coefficient overflows.
pub(super) fn collect(mut terms: Vec<Term>) -> Option<Vec<Term>> {
    terms.sort_by(|x, y| x.mono.cmp(&y.mono));
    let mut out: Vec<Term> = Vec::with_capacity(terms.len());
    for t in terms {
        match out.last_mut() {
            Some(last) if last.mono == t.mono => last.coef = last.coef.checked_add(t.coef)?,
            _ => out.push(t),
        }
    }
    out.retain(|t| !t.coef.is_zero());
    Some(out)
}

/// `e` as a collected sum of terms, sums inside products multiplied out up to
/// [`MAX_TERMS`] (past that they stay opaque atoms). `None` if a coefficient overflows.
pub(super) fn terms(arena: &Arena, e: ExprId) -> Option<Vec<Term>> {
    // Iterative, so any nesting converts without recursion: a node is converted once its
    // sum, product and power children are; sines, cosines and roots are atoms and their
    // arguments are never visited.
    let mut done: IdMap<ExprId, Vec<Term>> = IdMap::default();
    let mut stack = vec![(e, false)];
    while let Some((id, children_done)) = stack.pop() {
        if done.contains_key(&id) {
            continue;
        }
        let node = arena.node(id);
        let inner: &[ExprId] = match node {
            Node::Add(c) | Node::Mul(c) => c,
            Node::Pow(b, _) => std::slice::from_ref(b),
            _ => &[],
        };
        if !children_done && !inner.is_empty() {
            stack.push((id, true));
            stack.extend(inner.iter().map(|&c| (c, false)));
            continue;
        }
        let value = match node {
            Node::Const(r) => vec![Term::constant(*r)],
            Node::Sym(s) => vec![Term::atom(Atom::Sym(*s), 1)],
            Node::Sin(u) => vec![Term::atom(Atom::Sin(*u), 1)],
            Node::Cos(u) => vec![Term::atom(Atom::Cos(*u), 1)],
            Node::Sqrt(_) | Node::Powr(..) | Node::Func(..) => vec![Term::atom(Atom::Other(id), 1)],
            Node::Add(children) => {
                let mut all = Vec::new();
                for c in children.iter() {
                    all.extend(done.get(c)?.iter().cloned());
                }
                collect(all)?
            }
            Node::Mul(children) => {
                // Multiplied out, or if that is too large, every sum among the factors
                // kept whole.
                let multiplied = children
                    .iter()
                    .try_fold(vec![Term::one()], |acc, c| product(&acc, done.get(c)?));
                match multiplied {
                    Some(p) => p,
                    None => children.iter().try_fold(vec![Term::one()], |acc, c| {
                        match done.get(c)?.as_slice() {
                            [single] => product(&acc, std::slice::from_ref(single)),
                            _ => product(&acc, &[Term::atom(Atom::Other(*c), 1)]),
                        }
                    })?,
                }
            }
            Node::Pow(b, n) => power(arena, *b, *n, done.get(b)?)?,
        };
        done.insert(id, value);
    }
    done.remove(&e)
}

/// `b^n` from the terms of `b`: an atom's power when `b` is one term, the sum multiplied
/// out for a small positive power, else an opaque atom.
pub(super) fn power(arena: &Arena, b: ExprId, n: i64, base: &[Term]) -> Option<Vec<Term>> {
    if let [t] = base {
        // (c · Π aᵏ)ⁿ = cⁿ · Π aᵏⁿ, exact.
        let coef = t.coef.checked_pow(n)?;
        let mono = t
            .mono
            .iter()
            .map(|&(a, k)| Some((a, bounded(k.checked_mul(n)?)?)))
            .collect::<Option<_>>()?;
        return Some(vec![Term { coef, mono }]);
    }
    let n = bounded(n)?;
    if (2..=4).contains(&n) {
        let mut acc = base.to_vec();
        for _ in 1..n {
            match product(&acc, base) {
                Some(p) => acc = p,
                None => return Some(vec![Term::atom(opaque(arena, b), n)]),
            }
        }
        return Some(acc);
    }
    Some(vec![Term::atom(opaque(arena, b), n)])
}

/// `n` if it is a power the view holds.
fn bounded(n: i64) -> Option<i64> {
    (n.checked_abs()? <= MAX_POWER).then_some(n)
}

fn opaque(arena: &Arena, b: ExprId) -> Atom {
    match arena.node(b) {
        Node::Sym(s) => Atom::Sym(*s),
        Node::Sin(u) => Atom::Sin(*u),
        Node::Cos(u) => Atom::Cos(*u),
        _ => Atom::Other(b),
    }
}

/// True for an atom that is constant in time: a parameter, an abbreviation of parameters,
/// or an opaque expression of them (the factors the paper form groups terms by).
pub(super) fn is_parameter(arena: &Arena, atom: Atom) -> bool {
    let constant =
        |kind: SymbolKind| matches!(kind, SymbolKind::Parameter | SymbolKind::Abbreviation);
    match atom {
        Atom::Sym(s) => constant(arena.symbol(s).kind),
        Atom::Sin(u) | Atom::Cos(u) | Atom::Other(u) => arena
            .free_symbols(u)
            .into_iter()
            .all(|s| constant(arena.symbol(s).kind)),
    }
}

/// Which of sin u and cos u a sum keeps to degree at most one: the engine keeps sin (the
/// canonical form), the alternative keeps cos and so shows sin² u.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(super) enum Reduce {
    /// Powers sinⁿ u with n ≥ 2 become sinⁿ⁻² u (1 − cos² u): at most one sine.
    Sines,
    /// Powers cosⁿ u with n ≥ 2 become cosⁿ⁻² u (1 − sin² u): at most one cosine.
    Cosines,
}

/// `terms` rewritten modulo sin² u + cos² u = 1 so that the chosen function of `u` appears
/// to degree at most one; `None` on overflow or past [`MAX_TERMS`].
pub(super) fn reduce(terms: &[Term], u: ExprId, keep: Reduce) -> Option<Vec<Term>> {
    let (high, other) = match keep {
        Reduce::Sines => (Atom::Sin(u), Atom::Cos(u)),
        Reduce::Cosines => (Atom::Cos(u), Atom::Sin(u)),
    };
    let mut out = Vec::new();
    for t in terms {
        let n = t.power(high);
        if n < 2 {
            out.push(t.clone());
            continue;
        }
        // fⁿ = f^(n mod 2) (1 − g²)^(n div 2), by the binomial theorem.
        let k = n / 2;
        let base = t.with_power(high, n % 2);
        let mut binomial = Rational::ONE;
        for j in 0..=k {
            let sign = if j % 2 == 0 {
                Rational::ONE
            } else {
                Rational::MINUS_ONE
            };
            let g = base.power(other) + 2 * j;
            let mut term = base.with_power(other, g);
            term.coef = term.coef.checked_mul(binomial)?.checked_mul(sign)?;
            out.push(term);
            // C(k, j+1) = C(k, j) (k − j) / (j + 1).
            let ratio = Rational::new(i128::from(k - j), i128::from(j + 1))?;
            binomial = binomial.checked_mul(ratio)?;
        }
        if out.len() > MAX_TERMS {
            return None;
        }
    }
    collect(out)
}

/// The arguments u of every sin u and cos u in `terms`, in order of first appearance.
pub(super) fn angles(terms: &[Term]) -> Vec<ExprId> {
    let mut out = Vec::new();
    for t in terms {
        for &(a, _) in &t.mono {
            if let Atom::Sin(u) | Atom::Cos(u) = a
                && !out.contains(&u)
            {
                out.push(u);
            }
        }
    }
    out
}
