//! Perfect squares in a sum: `a² ± 2ab + b²` as written, and `c (a ± b)²` that shows only
//! modulo sin² u + cos² u = 1 (a kinetic energy's ½ I₁ ω₁², ω₁ = θ̇ cos ψ + φ̇ sin θ sin ψ).

use super::poly::{Reduce, Term, collect, reduce};
use crate::sym::{ExprId, Rational};

/// Past this many candidate roots the modular search is skipped (it tries every pair).
const MAX_ROOTS: usize = 16;

/// `(a, ±b)` with `a² ± 2ab + b²` equal to the three terms, a and b with positive
/// coefficients.
pub(super) fn perfect_square(terms: &[Term]) -> Option<(Term, Term)> {
    let [x, y, z] = terms else {
        return None;
    };
    let root = |t: &Term| -> Option<Term> {
        let coef = t.coef.sqrt_exact()?;
        Some(Term {
            coef,
            mono: root_mono(t)?,
        })
    };
    for (p, q, cross) in [(x, y, z), (x, z, y), (y, z, x)] {
        let (Some(a), Some(b)) = (root(p), root(q)) else {
            continue;
        };
        let ab = a.times(&b)?;
        let two_ab = Term {
            coef: ab.coef.checked_mul(Rational::integer(2))?,
            mono: ab.mono,
        };
        if two_ab.mono == cross.mono && two_ab.coef == cross.coef {
            return Some((a, b));
        }
        if two_ab.mono == cross.mono && two_ab.coef == -cross.coef {
            return Some((a, Term { coef: -b.coef, ..b }));
        }
    }
    None
}

/// The square root of a term's atoms, if every power is even and positive.
fn root_mono(t: &Term) -> Option<super::poly::Mono> {
    t.mono
        .iter()
        .map(|&(a, n)| (n > 0 && n % 2 == 0).then_some((a, n / 2)))
        .collect()
}

/// `(c, a, ±b)` with `c (a ± b)²` equal to `engine` (a sum in the engine's form: sin of
/// each angle in `angles` to degree at most one) modulo sin² + cos² = 1, for monomials a
/// and b (coefficient one) whose squares are terms of one of `forms` (the same sum in its
/// other sine and cosine forms).
pub(super) fn square_modulo_trig(
    engine: &[Term],
    forms: &[Vec<Term>],
    angles: &[ExprId],
) -> Option<(Rational, Term, Term)> {
    if engine.len() < 3 {
        return None;
    }
    // Collected, so in the canonical order of monomials the square is compared in.
    let engine = collect(engine.to_vec())?;
    let mut roots: Vec<Term> = Vec::new();
    for t in forms.iter().flatten() {
        if let Some(mono) = root_mono(t) {
            let r = Term {
                coef: Rational::ONE,
                mono,
            };
            if !roots.contains(&r) {
                roots.push(r);
            }
        }
    }
    if roots.len() > MAX_ROOTS {
        return None;
    }
    for (i, a) in roots.iter().enumerate() {
        for b in &roots[i + 1..] {
            for sign in [Rational::ONE, Rational::MINUS_ONE] {
                let b = Term {
                    coef: sign,
                    mono: b.mono.clone(),
                };
                let Some(c) = multiple_of_square(&engine, a, &b, angles) else {
                    continue;
                };
                return Some((c, a.clone(), b));
            }
        }
    }
    None
}

/// The rational c with `engine = c (a + b)²` in the engine's form, if there is one.
fn multiple_of_square(engine: &[Term], a: &Term, b: &Term, angles: &[ExprId]) -> Option<Rational> {
    let ab = a.times(b)?;
    let two_ab = Term {
        coef: ab.coef.checked_mul(Rational::integer(2))?,
        mono: ab.mono,
    };
    let mut square = collect(vec![a.times(a)?, two_ab, b.times(b)?])?;
    for &u in angles {
        square = reduce(&square, u, Reduce::Sines)?;
    }
    // Both are collected, so in the same canonical order of monomials.
    if square.len() != engine.len() {
        return None;
    }
    let (first_e, first_s) = (engine.first()?, square.first()?);
    let c = first_e.coef.checked_mul(first_s.coef.recip()?)?;
    let same = engine
        .iter()
        .zip(&square)
        .all(|(e, s)| e.mono == s.mono && s.coef.checked_mul(c).is_some_and(|v| v == e.coef));
    same.then_some(c)
}
