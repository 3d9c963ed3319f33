//! LaTeX rendering of expressions, for printing derivations.
//!
//! Written from an explicit stack of tasks (no recursion), so any depth of nesting prints.

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
    let mut out = String::new();
    let mut stack = vec![Task::Expr(e)];
    while let Some(task) = stack.pop() {
        if let Task::Text(t) = task {
            out.push_str(&t);
            continue;
        }
        let parts = Latex { arena }.expand(task);
        stack.extend(parts.into_iter().rev());
    }
    out
}

/// A piece of LaTeX still to write.
enum Task {
    Text(String),
    /// A whole expression.
    Expr(ExprId),
    /// The terms of a sum, constant last and negative terms as subtractions.
    Sum(ExprId),
    /// A term with its sign.
    Term(ExprId),
    /// A term without its sign.
    TermBody(ExprId),
    /// A factor of a product, parenthesised if it is a sum or product.
    Factor(ExprId),
    /// `b^n`.
    Power(ExprId, i64),
    /// The argument of sin or cos: bare for a symbol, parenthesised otherwise.
    Argument(ExprId),
}

struct Latex<'a> {
    arena: &'a Arena,
}

fn text(s: impl Into<String>) -> Task {
    Task::Text(s.into())
}

impl Latex<'_> {
    /// The tasks that write `task`, in order.
    fn expand(&self, task: Task) -> Vec<Task> {
        match task {
            Task::Text(t) => vec![Task::Text(t)],
            Task::Expr(e) => match self.arena.node(e) {
                Node::Add(_) => vec![Task::Sum(e)],
                _ => vec![Task::Term(e)],
            },
            Task::Sum(e) => self.sum(e),
            Task::Term(e) => {
                if self.negative(e) {
                    vec![text("-"), Task::TermBody(e)]
                } else {
                    vec![Task::TermBody(e)]
                }
            }
            Task::TermBody(e) => self.term_body(e),
            Task::Factor(e) => self.factor(e),
            Task::Power(b, n) => self.power(b, n),
            Task::Argument(u) => match self.arena.node(u) {
                Node::Sym(s) => {
                    let l = &self.arena.symbol(*s).latex;
                    vec![text(if l.starts_with('\\') {
                        l.clone()
                    } else {
                        format!(" {l}")
                    })]
                }
                _ => vec![text("\\left("), Task::Expr(u), text("\\right)")],
            },
        }
    }

    fn sum(&self, e: ExprId) -> Vec<Task> {
        let Node::Add(terms) = self.arena.node(e) else {
            return vec![Task::Term(e)];
        };
        let mut ordered: Vec<ExprId> = terms.to_vec();
        ordered.sort_by_key(|&t| matches!(self.arena.node(t), Node::Const(_)));
        let mut out = Vec::with_capacity(2 * ordered.len());
        for (i, &t) in ordered.iter().enumerate() {
            if i == 0 {
                out.push(Task::Term(t));
            } else {
                let sign = if self.negative(t) { " - " } else { " + " };
                out.push(text(sign));
                out.push(Task::TermBody(t));
            }
        }
        out
    }

    /// The constant factors of a term: the constant itself, or every constant factor of a
    /// product. A product holds several when multiplying them out overflowed (the exact
    /// values of f64s, as a body of literal parts has), and any of them may be negative.
    fn constants(&self, e: ExprId) -> Vec<Rational> {
        match self.arena.node(e) {
            Node::Const(r) => vec![*r],
            Node::Mul(f) => f
                .iter()
                .filter_map(|&x| match self.arena.node(x) {
                    Node::Const(r) => Some(*r),
                    _ => None,
                })
                .collect(),
            _ => Vec::new(),
        }
    }

    /// Whether a term is negative: an odd number of its constant factors are. The sign is
    /// written once, before the term, so no factor inside it reads as a subtraction.
    fn negative(&self, e: ExprId) -> bool {
        self.constants(e).iter().filter(|r| r.is_negative()).count() % 2 == 1
    }

    /// A term without its sign, as `c \frac{num}{den}`; several constant factors join with
    /// `\cdot`, their numerators above the bar and their denominators below it.
    fn term_body(&self, e: ExprId) -> Vec<Task> {
        let factors: Vec<ExprId> = match self.arena.node(e) {
            Node::Const(r) => return vec![text(rational(r.abs_value()))],
            Node::Mul(f) => f
                .iter()
                .copied()
                .filter(|&x| !matches!(self.arena.node(x), Node::Const(_)))
                .collect(),
            _ => vec![e],
        };
        let (mut num, mut den) = (Vec::new(), Vec::new());
        for &f in &factors {
            match self.arena.node(f) {
                Node::Pow(b, n) if *n < 0 => den.push((*b, -*n)),
                _ => num.push((f, 1)),
            }
        }
        let (tops, bottoms): (Vec<String>, Vec<String>) = self
            .constants(e)
            .into_iter()
            .map(|c| fraction(c.abs_value()))
            .unzip();
        let (c_top, c_bottom) = (dot_product(tops), dot_product(bottoms));
        let in_frac = !den.is_empty() || c_bottom != "1";
        if !in_frac {
            return self.render(&num, &c_top, false);
        }
        let mut out = vec![text("\\frac{")];
        out.extend(self.render(&num, &c_top, true));
        out.push(text("}{"));
        out.extend(self.render(&den, &c_bottom, true));
        out.push(text("}"));
        out
    }

    /// Factors joined by spaces after a number `k` (shown unless 1); a lone sum needs no
    /// parentheses as a whole numerator or denominator of `\frac`.
    fn render(&self, list: &[(ExprId, i64)], k: &str, alone: bool) -> Vec<Task> {
        let mut out = Vec::new();
        let with_number = k != "1" || list.is_empty();
        if with_number {
            out.push(text(k));
        }
        for (i, &(e, n)) in list.iter().enumerate() {
            if i > 0 || with_number {
                out.push(text(" "));
            }
            let lone = alone && !with_number && list.len() == 1;
            out.push(match (self.arena.node(e), n, lone) {
                (Node::Add(_), 1, true) => Task::Sum(e),
                (_, 1, _) => Task::Factor(e),
                _ => Task::Power(e, n),
            });
        }
        out
    }

    fn power(&self, b: ExprId, n: i64) -> Vec<Task> {
        if n == 1 {
            return vec![Task::Factor(b)];
        }
        match self.arena.node(b) {
            Node::Sin(u) => vec![text(format!("\\sin^{{{n}}}")), Task::Argument(*u)],
            Node::Cos(u) => vec![text(format!("\\cos^{{{n}}}")), Task::Argument(*u)],
            _ => vec![text("{"), Task::Factor(b), text(format!("}}^{{{n}}}"))],
        }
    }

    fn factor(&self, e: ExprId) -> Vec<Task> {
        match self.arena.node(e) {
            Node::Const(r) => vec![text(rational(*r))],
            Node::Sym(s) => vec![text(self.arena.symbol(*s).latex.clone())],
            Node::Add(_) => vec![text("\\left("), Task::Sum(e), text("\\right)")],
            Node::Mul(_) => vec![text("\\left("), Task::Term(e), text("\\right)")],
            Node::Pow(b, n) if *n < 0 => {
                vec![text("\\frac{1}{"), Task::Power(*b, -*n), text("}")]
            }
            Node::Pow(b, n) => vec![Task::Power(*b, *n)],
            Node::Sqrt(u) => vec![text("\\sqrt{"), Task::Expr(*u), text("}")],
            // x^{p/q}: the exponent as a slashed fraction, legible in a superscript.
            Node::Powr(b, r) => vec![text("{"), Task::Factor(*b), text(format!("}}^{{{r}}}"))],
            Node::Sin(u) => vec![text("\\sin"), Task::Argument(*u)],
            Node::Cos(u) => vec![text("\\cos"), Task::Argument(*u)],
            Node::Func(f, u) => vec![text(f.latex()), Task::Argument(*u)],
        }
    }
}

/// Numbers multiplied with `\cdot`, ones left out; `1` for none.
fn dot_product(numbers: Vec<String>) -> String {
    let kept: Vec<String> = numbers.into_iter().filter(|n| n != "1").collect();
    if kept.is_empty() {
        "1".to_owned()
    } else {
        kept.join(" \\cdot ")
    }
}

fn rational(r: Rational) -> String {
    let sign = if r.is_negative() { "-" } else { "" };
    match fraction(r) {
        (top, bottom) if bottom == "1" => format!("{sign}{top}"),
        (top, bottom) => format!("{sign}\\frac{{{top}}}{{{bottom}}}"),
    }
}

/// Numerator and denominator of |r|; beyond ratios of i128s, the numerator is a decimal
/// times a power of ten, `7.0505 \cdot 10^{-30}`, the stray powers of 2 or 5 folded into its
/// digits (5⁻² = 4 · 10⁻²), exactly; `n \cdot 2^{a}` only if folding would overflow.
pub(super) fn fraction(r: Rational) -> (String, String) {
    let (n, d, two, five) = r.abs_value().scaled();
    if two == 0 && five == 0 {
        return (n.to_string(), d.to_string());
    }
    // n · 2^two · 5^five = n · 10^ten · (2 or 5)^rest.
    let ten = if two.signum() == five.signum() {
        two.signum() * two.abs().min(five.abs())
    } else {
        0
    };
    let folded = [(2i128, 5i128, two - ten), (5, 2, five - ten)]
        .into_iter()
        .try_fold((n, ten), |(n, ten), (base, other, e)| {
            // base^e for e < 0 is other^|e| · 10^e.
            let (factor, e_abs, shift) = if e >= 0 { (base, e, 0) } else { (other, -e, e) };
            let p = factor.checked_pow(u32::try_from(e_abs).ok()?)?;
            Some((n.checked_mul(p)?, ten + shift))
        });
    if let Some((n, ten)) = folded {
        return (scientific(n, ten), d.to_string());
    }
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

/// The integer `n · 10^k` written exactly: its digits with the point after the first,
/// `\cdot 10^{e}` unless e is 0, trailing zeros dropped.
fn scientific(n: i128, k: i32) -> String {
    let digits = n.unsigned_abs().to_string();
    let digits = digits.trim_end_matches('0');
    let zeros = n.unsigned_abs().to_string().len() - digits.len();
    let e = k + i32::try_from(zeros + digits.len()).unwrap_or(i32::MAX) - 1;
    if digits.is_empty() {
        return "0".to_owned();
    }
    let mantissa = match digits.split_at(1) {
        (head, "") => head.to_owned(),
        (head, tail) => format!("{head}.{tail}"),
    };
    if e == 0 {
        mantissa
    } else {
        format!("{mantissa} \\cdot 10^{{{e}}}")
    }
}

/// `v` as LaTeX to `digits` significant digits, trailing zeros dropped: plainly between
/// 0.001 and 10⁴ (`9.81`, `0.0345`), else as `m \cdot 10^{e}` (`7.27512 \cdot 10^{-6}`).
///
/// ```
/// use precess_core::codegen::decimal;
/// assert_eq!(decimal(9.81, 6), "9.81");
/// assert_eq!(decimal(-0.034_512_345, 3), "-0.0345");
/// assert_eq!(decimal(7.275_118_53e-6, 6), r"7.27512 \cdot 10^{-6}");
/// assert_eq!(decimal(12_345.6, 2), r"1.2 \cdot 10^{4}");
/// ```
pub fn decimal(v: f64, digits: usize) -> String {
    let digits = digits.max(1);
    let sci = format!("{:.*e}", digits - 1, v);
    let Some((mantissa, exponent)) = sci.split_once('e') else {
        return sci;
    };
    let e: i32 = exponent.parse().unwrap_or(0);
    let trim = |m: &str| -> String {
        if m.contains('.') {
            m.trim_end_matches('0').trim_end_matches('.').to_owned()
        } else {
            m.to_owned()
        }
    };
    if v == 0.0 || !v.is_finite() || !(-3..4).contains(&e) {
        let m = trim(mantissa);
        return if e == 0 || v == 0.0 || !v.is_finite() {
            m
        } else {
            format!("{m} \\cdot 10^{{{e}}}")
        };
    }
    // Plain: as many decimals as leave `digits` significant ones.
    let decimals = usize::try_from(i32::try_from(digits).unwrap_or(17) - 1 - e).unwrap_or(0);
    trim(&format!("{v:.decimals$}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 10⁻⁵⁰ · 5⁻² beyond i128s, times `k`.
    fn tiny(k: i128) -> Rational {
        let a = Rational::new(k, 10i128.pow(30)).unwrap_or(Rational::ONE);
        let b = Rational::new(1, 25 * 10i128.pow(20)).unwrap_or(Rational::ONE);
        a.checked_mul(b).unwrap_or(Rational::ONE)
    }

    /// A value only the scaled form holds prints as an exact decimal times a power of ten,
    /// the stray 5⁻² folded (= 4 · 10⁻²), its sign in front and never inside a factor.
    #[test]
    fn scaled_rationals_print_as_exact_decimals() {
        assert_eq!(tiny(1).scaled().1, 1, "the test needs the scaled form");
        assert_ne!(tiny(1).scaled().2, 0, "the test needs the scaled form");
        assert_eq!(rational(tiny(1)), r"4 \cdot 10^{-52}");
        assert_eq!(rational(tiny(7)), r"2.8 \cdot 10^{-51}");
        assert_eq!(rational(tiny(-7)), r"-2.8 \cdot 10^{-51}");
    }

    #[test]
    fn decimals_keep_the_significant_digits_asked() {
        assert_eq!(decimal(0.038_389_412, 6), "0.0383894");
        assert_eq!(decimal(6.617_138e-5, 6), r"6.61714 \cdot 10^{-5}");
        assert_eq!(decimal(-1234.5, 6), "-1234.5");
        assert_eq!(decimal(0.0, 6), "0");
    }
}
