//! LaTeX rendering of expressions, for printing derivations.

use crate::sym::{Arena, ExprId, Node, Rational};

/// `e` as LaTeX: fractions for rational coefficients and negative powers, `\sin^{2}\theta`
/// for powers of trigonometric functions, dotted rates.
///
/// ```
/// use precess_core::{codegen::latex, sym::Arena};
/// let mut a = Arena::new();
/// let th = a.coordinate("theta");
/// let s = a.sin(th);
/// let half = a.number("0.5").unwrap();
/// let e = a.mul(half, s);
/// assert_eq!(latex(&a, e), r"\frac{\sin\theta}{2}");
/// ```
pub fn latex(arena: &Arena, e: ExprId) -> String {
    Latex { arena }.expr(e)
}

struct Latex<'a> {
    arena: &'a Arena,
}

impl Latex<'_> {
    fn expr(&self, e: ExprId) -> String {
        match self.arena.node(e) {
            Node::Add(terms) => self.sum(terms),
            _ => self.term(e),
        }
    }

    /// A sum, constant last and negative coefficients as subtractions.
    fn sum(&self, terms: &[ExprId]) -> String {
        let mut ordered: Vec<ExprId> = terms.to_vec();
        ordered.sort_by_key(|&t| matches!(self.arena.node(t), Node::Const(_)));
        let mut out = String::new();
        for (i, &t) in ordered.iter().enumerate() {
            let s = self.term(t);
            match (i, s.strip_prefix('-')) {
                (0, _) => out.push_str(&s),
                (_, Some(rest)) => {
                    out.push_str(" - ");
                    out.push_str(rest);
                }
                (_, None) => {
                    out.push_str(" + ");
                    out.push_str(&s);
                }
            }
        }
        out
    }

    /// A product as `c \frac{num}{den}`, with a leading `-` when negative.
    fn term(&self, e: ExprId) -> String {
        let (coeff, factors): (Rational, Vec<ExprId>) = match self.arena.node(e) {
            Node::Const(r) => return rational(*r),
            Node::Mul(f) => match self.arena.node(f[0]) {
                Node::Const(r) => (*r, f[1..].to_vec()),
                _ => (Rational::ONE, f.to_vec()),
            },
            _ => (Rational::ONE, vec![e]),
        };
        let (mut num, mut den) = (Vec::new(), Vec::new());
        for &f in &factors {
            match self.arena.node(f) {
                Node::Pow(b, n) if *n < 0 => den.push((*b, -*n)),
                _ => num.push((f, 1)),
            }
        }
        let sign = if coeff.is_negative() { "-" } else { "" };
        let c = coeff.abs_value();
        // A lone sum needs no parentheses as a whole numerator or denominator of \frac.
        let render = |list: &[(ExprId, i64)], k: &str, alone: bool| -> String {
            let mut parts: Vec<String> = Vec::new();
            if k != "1" || list.is_empty() {
                parts.push(k.to_owned());
            }
            for &(e, n) in list {
                parts.push(
                    match (
                        self.arena.node(e),
                        n,
                        alone && parts.is_empty() && list.len() == 1,
                    ) {
                        (Node::Add(t), 1, true) => self.sum(t),
                        (_, 1, _) => self.factor(e),
                        _ => self.power(e, n),
                    },
                );
            }
            parts.join(" ")
        };
        let (c_top, c_bottom) = fraction(c);
        let in_frac = !den.is_empty() || c_bottom != "1";
        let top = render(&num, &c_top, in_frac);
        if !in_frac {
            return format!("{sign}{top}");
        }
        let bottom = render(&den, &c_bottom, true);
        format!("{sign}\\frac{{{top}}}{{{bottom}}}")
    }

    fn power(&self, b: ExprId, n: i64) -> String {
        if n == 1 {
            return self.factor(b);
        }
        match self.arena.node(b) {
            Node::Sin(u) => format!("\\sin^{{{n}}}{}", self.argument(*u)),
            Node::Cos(u) => format!("\\cos^{{{n}}}{}", self.argument(*u)),
            _ => format!("{{{}}}^{{{n}}}", self.factor(b)),
        }
    }

    /// A factor of a product, parenthesised if it is a sum.
    fn factor(&self, e: ExprId) -> String {
        match self.arena.node(e) {
            Node::Const(r) => rational(*r),
            Node::Sym(s) => self.arena.symbol(*s).latex.clone(),
            Node::Add(t) => format!("\\left({}\\right)", self.sum(t)),
            Node::Mul(_) => format!("\\left({}\\right)", self.term(e)),
            Node::Pow(b, n) if *n < 0 => format!("\\frac{{1}}{{{}}}", self.power(*b, -*n)),
            Node::Pow(b, n) => self.power(*b, *n),
            Node::Sqrt(u) => format!("\\sqrt{{{}}}", self.expr(*u)),
            Node::Sin(u) => format!("\\sin{}", self.argument(*u)),
            Node::Cos(u) => format!("\\cos{}", self.argument(*u)),
        }
    }

    /// The argument of sin or cos: bare for a symbol, parenthesised otherwise.
    fn argument(&self, u: ExprId) -> String {
        match self.arena.node(u) {
            Node::Sym(s) => {
                let l = &self.arena.symbol(*s).latex;
                if l.starts_with('\\') {
                    l.clone()
                } else {
                    format!(" {l}")
                }
            }
            _ => format!("\\left({}\\right)", self.expr(u)),
        }
    }
}

fn rational(r: Rational) -> String {
    let sign = if r.is_negative() { "-" } else { "" };
    match fraction(r) {
        (top, bottom) if bottom == "1" => format!("{sign}{top}"),
        (top, bottom) => format!("{sign}\\frac{{{top}}}{{{bottom}}}"),
    }
}

/// Numerator and denominator of |r|; beyond ratios of i128s, the numerator carries the
/// powers: n · 10^k · 2^a (or 5^b).
fn fraction(r: Rational) -> (String, String) {
    let (n, d, two, five) = r.abs_value().scaled();
    let ten = if two.signum() == five.signum() {
        two.signum() * two.abs().min(five.abs())
    } else {
        0
    };
    let mut top = vec![n.to_string()];
    for (base, e) in [(10, ten), (2, two - ten), (5, five - ten)] {
        if e != 0 {
            top.push(format!("{base}^{{{e}}}"));
        }
    }
    if top.len() > 1 && n == 1 {
        top.remove(0);
    }
    (top.join(" \\cdot "), d.to_string())
}
