//! Printing the groups of the paper form as LaTeX.

use std::cell::RefCell;
use std::collections::HashMap;

use super::layout::{AtomKey, Group, Inner};
use super::poly::{Atom, Term};
use crate::codegen::latex::{fraction, latex};
use crate::sym::{Arena, Node, Rational, SymbolId};

/// Prints atoms, terms and groups of one arena's expressions.
pub(super) struct Printer<'a> {
    pub arena: &'a Arena,
    /// The display key of each atom met, computed once.
    pub keys: RefCell<HashMap<Atom, AtomKey>>,
    /// Symbols shown under another name than their own.
    pub names: HashMap<SymbolId, String>,
}

impl<'a> Printer<'a> {
    pub(super) fn new(arena: &'a Arena) -> Printer<'a> {
        Printer {
            arena,
            keys: RefCell::new(HashMap::new()),
            names: HashMap::new(),
        }
    }

    /// `atom^n` (n ≠ 0; negative powers are printed by [`Printer::body`] as fractions).
    pub(super) fn atom(&self, atom: Atom, n: i64) -> String {
        let power = |base: String| {
            if n == 1 {
                base
            } else {
                format!("{base}^{{{n}}}")
            }
        };
        match atom {
            Atom::Sym(s) => {
                let l = self.symbol_latex(s);
                // A name that already carries a superscript (q^{(3)}) is braced first.
                power(if l.contains('^') && n != 1 {
                    format!("{{{l}}}")
                } else {
                    l.to_owned()
                })
            }
            Atom::Sin(u) | Atom::Cos(u) => {
                let f = if matches!(atom, Atom::Sin(_)) {
                    "\\sin"
                } else {
                    "\\cos"
                };
                let f = if n == 1 {
                    f.to_owned()
                } else {
                    format!("{f}^{{{n}}}")
                };
                format!("{f}{}", self.argument(u))
            }
            Atom::Other(e) => {
                let l = latex(self.arena, e);
                match self.arena.node(e) {
                    Node::Add(_) | Node::Mul(_) => power(format!("\\left({l}\\right)")),
                    _ if n == 1 => l,
                    _ => power(format!("{{{l}}}")),
                }
            }
        }
    }

    /// The LaTeX of the symbol `s`: the name given to the printer, else its own.
    pub(super) fn symbol_latex(&self, s: SymbolId) -> &str {
        self.names
            .get(&s)
            .map_or(self.arena.symbol(s).latex.as_str(), String::as_str)
    }

    /// The argument of sin or cos: a command bare (`\sin\theta`), a letter after a space
    /// (`\sin x`), anything else in parentheses.
    fn argument(&self, u: crate::sym::ExprId) -> String {
        match self.arena.node(u) {
            Node::Sym(s) => {
                let l = self.symbol_latex(*s);
                if l.starts_with('\\') {
                    l.to_owned()
                } else {
                    format!(" {l}")
                }
            }
            _ => format!("\\left({}\\right)", latex(self.arena, u)),
        }
    }

    /// `|coef| · mono` without its sign, negative powers below a fraction bar; a coefficient
    /// of one is left out before atoms, and altogether when `bare_one` allows an empty
    /// string (a prefix before parentheses).
    pub(super) fn body(&self, coef: Rational, mono: &[(Atom, i64)], bare_one: bool) -> String {
        let (top, bottom) = fraction(coef.abs_value());
        let num: Vec<String> = mono
            .iter()
            .filter(|(_, n)| *n > 0)
            .map(|&(a, n)| self.atom(a, n))
            .collect();
        let den: Vec<String> = mono
            .iter()
            .filter(|(_, n)| *n < 0)
            .map(|&(a, n)| self.atom(a, -n))
            .collect();
        let join = |number: &str, atoms: &[String], keep_one: bool| {
            let mut parts = Vec::with_capacity(atoms.len() + 1);
            if number != "1" || (atoms.is_empty() && keep_one) {
                parts.push(number.to_owned());
            }
            parts.extend(atoms.iter().cloned());
            parts.join(" ")
        };
        if den.is_empty() {
            if bottom == "1" {
                return join(&top, &num, !bare_one);
            }
            let number = format!("\\frac{{{top}}}{{{bottom}}}");
            return join(&number, &num, true);
        }
        format!(
            "\\frac{{{}}}{{{}}}",
            join(&top, &num, true),
            join(&bottom, &den, false)
        )
    }

    /// A group without its sign.
    pub(super) fn group(&self, g: &Group) -> String {
        match &g.inner {
            Inner::One => self.body(g.coef, &g.prefix, false),
            Inner::Sum(terms) => {
                let prefix = self.body(g.coef, &g.prefix, true);
                let inner = self.terms(terms);
                join_prefix(&prefix, &format!("\\left({inner}\\right)"))
            }
            Inner::Square(a, b) => {
                let prefix = self.body(g.coef, &g.prefix, true);
                let inner = self.terms(&[a.clone(), b.clone()]);
                join_prefix(&prefix, &format!("\\left({inner}\\right)^{{2}}"))
            }
        }
    }

    /// Terms joined by their signs.
    fn terms(&self, terms: &[Term]) -> String {
        let groups: Vec<Group> = terms
            .iter()
            .map(|t| Group {
                negative: t.coef.is_negative(),
                coef: t.coef.abs_value(),
                prefix: self.display_order(&t.mono),
                inner: Inner::One,
            })
            .collect();
        self.sum(&groups)
    }

    /// Groups joined by their signs; `0` for none.
    pub(super) fn sum(&self, groups: &[Group]) -> String {
        if groups.is_empty() {
            return "0".to_owned();
        }
        let mut out = String::new();
        for (i, g) in groups.iter().enumerate() {
            let sign = match (i, g.negative) {
                (0, false) => "",
                (0, true) => "-",
                (_, false) => " + ",
                (_, true) => " - ",
            };
            out.push_str(sign);
            out.push_str(&self.group(g));
        }
        out
    }
}

fn join_prefix(prefix: &str, rest: &str) -> String {
    if prefix.is_empty() {
        rest.to_owned()
    } else {
        format!("{prefix} {rest}")
    }
}
