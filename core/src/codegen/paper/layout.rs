//! The layout of a sum as a paper prints it: terms grouped by their parameters, each group's
//! common factor taken out, sin² u or 1 − cos² u whichever prints shorter, a perfect square
//! shown as one.

use std::cmp::Ordering;
use std::rc::Rc;

use super::poly::{Atom, Mono, Reduce, Term, angles, is_parameter, reduce};
use super::print::Printer;
use super::square::{perfect_square, square_modulo_trig};
use crate::sym::{Rational, SymbolKind};

/// Largest coefficient left inside a group's parentheses when a rational factor is taken
/// out; past it the factor stays with the terms (`½ (a + b)` yes, `1/1000 (30 a + 7 b)` no).
const MAX_INNER_COEFFICIENT: u128 = 64;

/// How many angles have both of their forms tried together (2ⁿ layouts); past it each angle
/// is chosen on its own.
const MAX_JOINT_ANGLES: usize = 3;

/// One group of a sum: `± coef · prefix · (inner)`.
#[derive(Clone, Debug)]
pub(super) struct Group {
    pub negative: bool,
    /// The magnitude of the group's rational factor.
    pub coef: Rational,
    /// Parameters, then the common kinematic factors, in display order.
    pub prefix: Mono,
    pub inner: Inner,
}

/// What follows a group's prefix.
#[derive(Clone, Debug)]
pub(super) enum Inner {
    /// Nothing: the group is one term.
    One,
    /// A parenthesised sum (first term positive), in display order.
    Sum(Vec<Term>),
    /// `(a ± b)²`.
    Square(Term, Term),
}

/// The sort key of an atom for display: its rank (parameters, accelerations, rates,
/// coordinates, inputs and time, sines, cosines, anything else), the index of its
/// coordinate, its name.
pub(super) type AtomKey = (u8, usize, Rc<str>);

/// The sort key of a term in a sum: fewer sines and cosines first, then lower degree, then
/// its atoms in display order (`ψ̇ + φ̇ cos θ`, `θ̇² + φ̇² sin² θ`).
type TermKey = (i64, i64, Vec<(AtomKey, i64)>);

impl Printer<'_> {
    pub(super) fn atom_key(&self, atom: Atom) -> AtomKey {
        if let Some(k) = self.keys.borrow().get(&atom) {
            return k.clone();
        }
        let arena = self.arena;
        let coordinate_index = |u| {
            arena
                .as_symbol(u)
                .map_or(usize::MAX, crate::sym::SymbolId::index)
        };
        let key: AtomKey = match atom {
            Atom::Sym(s) => {
                let symbol = arena.symbol(s);
                let (rank, index) = match symbol.kind {
                    SymbolKind::Parameter | SymbolKind::Abbreviation => (0, 0),
                    SymbolKind::Derivative { of, order } if order >= 2 => (1, of.index()),
                    SymbolKind::Derivative { of, .. } => (2, of.index()),
                    SymbolKind::Coordinate => (3, s.index()),
                    SymbolKind::Input | SymbolKind::Time => (4, 0),
                };
                // A renamed symbol sorts by the name it is shown under.
                let name = match self.names.get(&s) {
                    Some(shown) => shown.as_str(),
                    None => symbol.name.as_str(),
                };
                (rank, index, name.into())
            }
            // sin α of a parameter α is a parameter too.
            _ if is_parameter(arena, atom) => (0, 0, self.atom(atom, 1).into()),
            Atom::Sin(u) => (5, coordinate_index(u), self.atom(atom, 1).into()),
            Atom::Cos(u) => (6, coordinate_index(u), self.atom(atom, 1).into()),
            Atom::Other(_) => (7, 0, self.atom(atom, 1).into()),
        };
        self.keys.borrow_mut().insert(atom, key.clone());
        key
    }

    /// True for an atom constant in time (see [`is_parameter`]).
    fn is_parameter(&self, atom: Atom) -> bool {
        self.atom_key(atom).0 == 0
    }

    /// `mono` in display order.
    pub(super) fn display_order(&self, mono: &[(Atom, i64)]) -> Mono {
        let mut out = mono.to_vec();
        out.sort_by_cached_key(|&(a, _)| self.atom_key(a));
        out
    }

    fn term_key(&self, t: &Term) -> TermKey {
        let trig: i64 = t
            .mono
            .iter()
            .filter(|(a, _)| matches!(a, Atom::Sin(_) | Atom::Cos(_)))
            .map(|(_, n)| n.abs())
            .sum();
        let degree: i64 = t.mono.iter().map(|(_, n)| n.abs()).sum();
        let mut atoms: Vec<(AtomKey, i64)> = t
            .mono
            .iter()
            .map(|&(a, n)| (self.atom_key(a), -n))
            .collect();
        atoms.sort();
        (trig, degree, atoms)
    }

    /// `terms` in the order of [`TermKey`].
    fn sort_terms(&self, terms: &mut [Term]) {
        terms.sort_by_cached_key(|t| self.term_key(t));
    }

    /// The groups of a sum, in print order: one group per set of parameter factors (fewest
    /// parameters first), then the terms without parameters one by one.
    pub(super) fn layout(&self, terms: &[Term]) -> Vec<Group> {
        let mut buckets: Vec<(Mono, Vec<Term>)> = Vec::new();
        for t in terms {
            let (params, kinematic): (Mono, Mono) =
                t.mono.iter().partition(|&&(a, _)| self.is_parameter(a));
            let rest = Term {
                coef: t.coef,
                mono: kinematic,
            };
            match buckets.iter_mut().find(|(p, _)| *p == params) {
                Some((_, list)) => list.push(rest),
                None => buckets.push((params, vec![rest])),
            }
        }
        let bucket_key = |params: &[(Atom, i64)]| {
            let degree: i64 = params.iter().map(|(_, n)| n.abs()).sum();
            let mut atoms: Vec<(AtomKey, i64)> = params
                .iter()
                .map(|&(a, n)| (self.atom_key(a), -n))
                .collect();
            atoms.sort();
            (params.is_empty(), degree, atoms)
        };
        buckets.sort_by_cached_key(|(p, _)| bucket_key(p));
        buckets
            .into_iter()
            .flat_map(|(params, list)| self.shortest(&params, &list))
            .collect()
    }

    /// The groups of one bucket in the shortest of its sine and cosine forms.
    fn shortest(&self, params: &[(Atom, i64)], terms: &[Term]) -> Vec<Group> {
        let us = angles(terms);
        // The engine's form first (sums multiplied out here may hold sin² u again).
        let mut engine = Some(terms.to_vec());
        for &u in &us {
            engine = engine.and_then(|f| reduce(&f, u, Reduce::Sines));
        }
        let engine = engine.unwrap_or_else(|| terms.to_vec());
        let terms = engine.as_slice();
        let mut candidates = vec![engine.clone()];
        if us.len() <= MAX_JOINT_ANGLES {
            for mask in 1..(1usize << us.len()) {
                let mut form = Some(terms.to_vec());
                for (i, &u) in us.iter().enumerate() {
                    if mask & (1 << i) != 0 {
                        form = form.and_then(|f| reduce(&f, u, Reduce::Cosines));
                    }
                }
                candidates.extend(form);
            }
        } else {
            // Greedy, angle by angle: keep each rewrite that shortens the print.
            let mut best = terms.to_vec();
            for &u in &us {
                if let Some(f) = reduce(&best, u, Reduce::Cosines)
                    && self.bucket_len(params, &f) < self.bucket_len(params, &best)
                {
                    best = f;
                }
            }
            candidates.push(best);
        }
        // A square that shows only modulo sin² + cos² = 1, (θ̇ cos ψ + φ̇ sin θ sin ψ)² say.
        let square = (!params.is_empty())
            .then(|| square_modulo_trig(terms, &candidates, &us))
            .flatten()
            .map(|(c, a, b)| Group {
                negative: c.is_negative(),
                coef: c.abs_value(),
                prefix: self.display_order(params),
                inner: self.square(a, b),
            });
        // The first of equal lengths wins: the engine's own form unless another is shorter.
        let mut best: Option<(usize, Vec<Group>)> = None;
        let layouts = candidates
            .iter()
            .map(|c| self.bucket_groups(params, c))
            .chain(square.map(|g| vec![g]));
        for groups in layouts {
            let len = self.sum(&groups).len();
            if best.as_ref().is_none_or(|(l, _)| len < *l) {
                best = Some((len, groups));
            }
        }
        best.map(|(_, g)| g).unwrap_or_default()
    }

    /// `(a ± b)²` with the terms in display order and the sign on the second
    /// ((a − b)² = (b − a)²).
    fn square(&self, a: Term, b: Term) -> Inner {
        let minus = b.coef.is_negative();
        let b = Term {
            coef: b.coef.abs_value(),
            ..b
        };
        let (first, mut second) = match self.term_key(&a).cmp(&self.term_key(&b)) {
            Ordering::Greater => (b, a),
            _ => (a, b),
        };
        if minus {
            second.coef = -second.coef;
        }
        Inner::Square(first, second)
    }

    fn bucket_len(&self, params: &[(Atom, i64)], terms: &[Term]) -> usize {
        self.sum(&self.bucket_groups(params, terms)).len()
    }

    /// A bucket's groups: its terms one by one when it has no parameters or one term, else
    /// one group with the common factor taken out.
    fn bucket_groups(&self, params: &[(Atom, i64)], terms: &[Term]) -> Vec<Group> {
        let mut sorted = terms.to_vec();
        self.sort_terms(&mut sorted);
        if params.is_empty() || sorted.len() == 1 {
            return sorted
                .into_iter()
                .map(|t| {
                    let mut mono = params.to_vec();
                    mono.extend(t.mono);
                    Group {
                        negative: t.coef.is_negative(),
                        coef: t.coef.abs_value(),
                        prefix: self.display_order(&mono),
                        inner: Inner::One,
                    }
                })
                .collect();
        }
        vec![self.factored(params, sorted)]
    }

    /// `params · c · common · (Σ terms / (c · common))`, the first inner term positive.
    fn factored(&self, params: &[(Atom, i64)], sorted: Vec<Term>) -> Group {
        let common: Mono = sorted.first().map_or_else(Vec::new, |first| {
            first
                .mono
                .iter()
                .filter_map(|&(a, _)| {
                    let least = sorted.iter().map(|t| t.power(a)).min().unwrap_or(0);
                    (least > 0).then_some((a, least))
                })
                .collect()
        });
        let negative = sorted.first().is_some_and(|t| t.coef.is_negative());
        let content = rational_content(&sorted).unwrap_or(Rational::ONE);
        let signed = if negative { -content } else { content };
        let inner: Option<Vec<Term>> = sorted
            .iter()
            .map(|t| {
                let mut mono = t.mono.clone();
                for &(a, n) in &common {
                    if let Some(entry) = mono.iter_mut().find(|(b, _)| *b == a) {
                        entry.1 -= n;
                    }
                }
                mono.retain(|&(_, n)| n != 0);
                Some(Term {
                    coef: t.coef.checked_mul(signed.recip()?)?,
                    mono,
                })
            })
            .collect();
        let mut prefix = params.to_vec();
        prefix.extend(common.iter().copied());
        let Some(mut inner) = inner else {
            // Unreachable for a content read off these coefficients; print unfactored.
            return Group {
                negative: false,
                coef: Rational::ONE,
                prefix: self.display_order(params),
                inner: Inner::Sum(sorted),
            };
        };
        self.sort_terms(&mut inner);
        let inner = match perfect_square(&inner) {
            Some((a, b)) => self.square(a, b),
            None => Inner::Sum(inner),
        };
        Group {
            negative,
            coef: content,
            prefix: self.display_order(&prefix),
            inner,
        }
    }
}

/// The positive rational c with every coefficient an integer multiple of it and those
/// integers coprime, if they are small (at most [`MAX_INNER_COEFFICIENT`]).
fn rational_content(terms: &[Term]) -> Option<Rational> {
    let mut g: i128 = 0;
    let mut l: i128 = 1;
    for t in terms {
        let (n, d) = t.coef.fraction()?;
        g = gcd(g, n.checked_abs()?);
        l = l.checked_mul(d.checked_div(gcd(l, d))?)?;
    }
    let c = Rational::new(g, l)?;
    let small = terms.iter().all(|t| {
        t.coef
            .checked_mul(c.recip().unwrap_or(Rational::ONE))
            .and_then(Rational::fraction)
            .is_some_and(|(n, d)| d == 1 && n.unsigned_abs() <= MAX_INNER_COEFFICIENT)
    });
    small.then_some(c)
}

fn gcd(mut a: i128, mut b: i128) -> i128 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a.abs()
}
