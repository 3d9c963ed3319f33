//! The paper form: an expression printed as a paper would print it, rather than in the
//! engine's canonical form.
//!
//! - Terms are grouped by their parameters (the symbols constant in time: fields, moments,
//!   M, g, l), each group's common factor taken out: `I₃ φ̇ sin θ (ψ̇ + φ̇ cos θ)`.
//! - The engine keeps sin u to degree at most one, so sin² u prints as 1 − cos² u; here each
//!   group is printed in both forms of each angle and the shorter kept: `φ̈ sin² θ`, not
//!   `φ̈ − φ̈ cos² θ`.
//! - A group that is a perfect square prints as one: `½ I₃ (ψ̇ + φ̇ cos θ)²`.
//! - A quotient of sums prints as one fraction, numerator and denominator in paper form.
//!
//! The rewrites are identities (sums multiplied out, like terms collected, sin² + cos² = 1),
//! so the value printed is the value of the expression. Anything the view cannot hold (a
//! coefficient that overflows) prints in the plain form of [`super::latex()`].

mod layout;
mod poly;
mod print;
mod square;
#[cfg(test)]
mod tests;

use layout::Group;
use poly::{Term, power, product, terms};
use print::Printer;

use super::latex::latex;
use crate::sym::{Arena, ExprId, Node, SymbolId};

/// `e` in paper form as LaTeX: terms grouped by parameter with each group's common factor
/// outside, the shorter of sin² u and 1 − cos² u per group, perfect squares and quotients
/// printed whole, everything ordered by name (`docs/equations.md` has the rules in full).
///
/// ```
/// use precess_core::{codegen::paper_latex, sym::Arena};
/// let mut a = Arena::new();
/// let (i1, th) = (a.parameter("I_1"), a.coordinate("theta"));
/// let (phi, _) = (a.coordinate("phi"), ());
/// let phi_dot = a.rate(phi).unwrap();
/// // I₁ φ̇² − I₁ φ̇² cos² θ, the engine's form of I₁ φ̇² sin² θ.
/// let c = a.cos(th);
/// let c2 = a.powi(c, 2).unwrap();
/// let w2 = a.powi(phi_dot, 2).unwrap();
/// let t = a.product(&[i1, w2, c2]);
/// let head = a.mul(i1, w2);
/// let e = a.sub(head, t);
/// assert_eq!(paper_latex(&a, e), r"I_{1} \dot{\phi}^{2} \sin^{2}\theta");
/// ```
pub fn paper_latex(arena: &Arena, e: ExprId) -> String {
    Paper::new(arena).latex(e)
}

/// `lhs = rhs` in paper form.
///
/// ```
/// use precess_core::{codegen::paper_equation, sym::Arena};
/// let mut a = Arena::new();
/// let (m, g, l, th) = (a.parameter("m"), a.parameter("g"), a.parameter("l"), a.coordinate("theta"));
/// let th_dd = { let r = a.rate(th).unwrap(); a.rate(r).unwrap() };
/// // The pendulum: m l² θ̈ = −m g l sin θ.
/// let l2 = a.powi(l, 2).unwrap();
/// let lhs = a.product(&[m, l2, th_dd]);
/// let s = a.sin(th);
/// let w = a.product(&[m, g, l, s]);
/// let rhs = a.neg(w);
/// assert_eq!(paper_equation(&a, lhs, rhs), r"l^{2} m \ddot{\theta} = -g l m \sin\theta");
/// ```
pub fn paper_equation(arena: &Arena, lhs: ExprId, rhs: ExprId) -> String {
    Paper::new(arena).equation(lhs, rhs)
}

/// Printing in paper form, some symbols shown under names the caller gives (a scene shows
/// the inputs of a user torque as τ whatever the inputs are called). One printer for many
/// lines computes each atom's display key once.
pub(crate) struct Paper<'a> {
    printer: Printer<'a>,
}

impl<'a> Paper<'a> {
    pub(crate) fn new(arena: &'a Arena) -> Paper<'a> {
        Paper {
            printer: Printer::new(arena),
        }
    }

    /// Shows the symbol `s` as `latex`.
    pub(crate) fn rename(mut self, s: SymbolId, latex: String) -> Paper<'a> {
        self.printer.names.insert(s, latex);
        self
    }

    /// `e` in paper form.
    pub(crate) fn latex(&self, e: ExprId) -> String {
        let p = &self.printer;
        let arena = p.arena;
        if let Some((num, den)) = quotient(arena, e) {
            let n = p.layout(&num);
            let d = p.sum(&p.layout(&den));
            return match n.as_slice() {
                [single] if single.negative => {
                    let positive = Group {
                        negative: false,
                        ..single.clone()
                    };
                    format!("-\\frac{{{}}}{{{d}}}", p.group(&positive))
                }
                _ => format!("\\frac{{{}}}{{{d}}}", p.sum(&n)),
            };
        }
        match terms(arena, e) {
            Some(t) => p.sum(&p.layout(&t)),
            None => latex(arena, e),
        }
    }

    /// `lhs = rhs` in paper form.
    pub(crate) fn equation(&self, lhs: ExprId, rhs: ExprId) -> String {
        format!("{} = {}", self.latex(lhs), self.latex(rhs))
    }
}

/// A product with a sum among its factors and negative powers among them, split into the
/// terms of its numerator and of its denominator.
fn quotient(arena: &Arena, e: ExprId) -> Option<(Vec<Term>, Vec<Term>)> {
    let Node::Mul(factors) = arena.node(e) else {
        return None;
    };
    let below = |f: ExprId| matches!(arena.node(f), Node::Pow(_, n) if *n < 0);
    let has_sum = factors
        .iter()
        .any(|&f| matches!(arena.node(f), Node::Add(_)));
    if !has_sum || !factors.iter().any(|&f| below(f)) {
        return None;
    }
    let mut num = vec![Term::one()];
    let mut den = vec![Term::one()];
    for &f in factors.iter() {
        match arena.node(f) {
            Node::Pow(b, n) if *n < 0 => {
                let base = terms(arena, *b)?;
                den = product(&den, &power(arena, *b, n.checked_neg()?, &base)?)?;
            }
            _ => num = product(&num, &terms(arena, f)?)?,
        }
    }
    Some((num, den))
}
