//! A scene's equations typeset for a reader, with the cost of the code generated for them:
//! what a derived struct returns as `'static` data and a scene built at run time computes.

use std::borrow::Cow;
use std::fmt;

use super::OpCount;

/// Lines of LaTeX: borrowed from `'static` data in generated code, owned at run time.
pub type Lines = Cow<'static, [Cow<'static, str>]>;

/// The operation count of one generated method.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MethodCost {
    /// The method, by its name in the scene's trait.
    pub method: Cow<'static, str>,
    /// What its straight-line code executes.
    pub ops: OpCount,
}

/// A scene's equations of motion as a paper prints them, one string per equation, and the
/// operation counts of the code generated for them.
///
/// Each string is a whole equation in LaTeX (`I_{1} \ddot{\theta} = …`), in the paper form
/// of [`super::paper_latex`]: grouped by parameter, sin² θ where it prints shorter.
/// [`Typeset::align`] sets them in one `align` environment, long lines broken.
///
/// A derived struct returns one built when the macro expanded (the fields borrow
/// `'static` strings, so it costs nothing at run time); the scene's run-time API builds an
/// equal one with owned strings, so the two compare equal with `==`.
///
/// # Examples
///
/// ```
/// use precess_core::sym::Arena;
/// use precess_core::top::TopScene;
///
/// let mut a = Arena::new();
/// let (i1, i3) = (a.parameter("I_1"), a.parameter("I_3"));
/// let z = a.zero();
/// let mut scene = TopScene::free(&mut a, [[i1, z, z], [z, i1, z], [z, z, i3]]);
/// scene.mass = a.parameter("M");
/// scene.center = [z, z, a.parameter("l")];
/// scene.gravity = Some(a.parameter("g"));
/// let eq = scene.typeset(&mut a)?;
/// assert_eq!(
///     eq.equations[1],
///     r"I_{1} \ddot{\theta} = I_{1} \dot{\phi}^{2} \sin\theta \cos\theta - I_{3} \dot{\phi} \sin\theta \left(\dot{\psi} + \dot{\phi} \cos\theta\right) + M g l \sin\theta"
/// );
/// assert_eq!(eq.cost("accelerations").map(|c| c.divs), Some(2));
/// assert!(eq.align().starts_with(r"\begin{align}"));
/// # Ok::<(), precess_core::lagrange::LagrangeError>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Typeset {
    /// `L = T − V`.
    pub lagrangian: Cow<'static, str>,
    /// The equations of motion, one per coordinate, `Σⱼ Mᵢⱼ q̈ⱼ = fᵢ`.
    pub equations: Lines,
    /// Their solution, `q̈ᵢ = …`.
    pub accelerations: Lines,
    /// The conserved momenta, `p_q = ∂L/∂q̇` for each coordinate L does not depend on.
    pub conserved: Lines,
    /// What the named quantities in the lines above stand for (`I_{xx} = …`), for a body
    /// whose mass properties depend on fields; for a body of literal parts, the decimal
    /// value of each named mass property to six significant digits (`I_{1} = 7.27512 \cdot
    /// 10^{-6}`), the table a paper prints beside its equations.
    pub definitions: Lines,
    /// The exact values behind the decimal ones in `definitions`: each named constant's
    /// LaTeX and the `f64` the generated code uses, written so it reads back bit for bit
    /// (`("I_{1}", "7.275118530795e-6")`). Empty when no constant is named.
    pub values: Cow<'static, [(Cow<'static, str>, Cow<'static, str>)]>,
    /// The operation count of each generated method.
    pub costs: Cow<'static, [MethodCost]>,
}

/// Display width, in glyphs, past which [`Typeset::align`] breaks a line.
pub const ALIGN_WIDTH: usize = 64;

impl Typeset {
    /// The operation count of the generated method `method`, if the scene has it.
    pub fn cost(&self, method: &str) -> Option<OpCount> {
        self.costs
            .iter()
            .find(|c| c.method == method)
            .map(|c| c.ops)
    }

    /// The exact value of the named constant printed as `symbol` (`"I_{1}"`), if one is.
    pub fn value(&self, symbol: &str) -> Option<f64> {
        self.values
            .iter()
            .find(|(s, _)| s == symbol)
            .and_then(|(_, v)| v.parse().ok())
    }

    /// Every line, in order: L, the equations, the accelerations, the conserved momenta and
    /// the definitions.
    pub fn lines(&self) -> impl Iterator<Item = &str> + '_ {
        std::iter::once(self.lagrangian.as_ref())
            .chain(self.equations.iter().map(AsRef::as_ref))
            .chain(self.accelerations.iter().map(AsRef::as_ref))
            .chain(self.conserved.iter().map(AsRef::as_ref))
            .chain(self.definitions.iter().map(AsRef::as_ref))
    }

    /// Every line in one LaTeX `align` environment, aligned at `=`, lines wider than
    /// [`ALIGN_WIDTH`] glyphs broken between terms.
    pub fn align(&self) -> String {
        self.align_width(ALIGN_WIDTH)
    }

    /// As [`Typeset::align`], breaking lines wider than `width` glyphs.
    pub fn align_width(&self, width: usize) -> String {
        let rows: Vec<String> = self.lines().map(|l| align_row(l, width)).collect();
        format!("\\begin{{align}}\n{}\n\\end{{align}}", rows.join(" \\\\\n"))
    }
}

impl fmt::Display for Typeset {
    /// The [`Typeset::align`] environment.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.align())
    }
}

/// One equation as rows of an `align`: `lhs &= t₁ + t₂ \\ &\quad + t₃ …`.
fn align_row(line: &str, width: usize) -> String {
    let Some((lhs, rhs)) = split_top_level(line, " = ") else {
        return line.to_owned();
    };
    // A long quotient is set as 1/D times its numerator, so the numerator can break.
    let (head, body, tail) = match as_fraction(rhs) {
        Some((sign, num, den)) if glyphs(rhs) > width => (
            format!("{sign}\\frac{{1}}{{{den}}} \\Bigl("),
            num,
            "\\Bigr)",
        ),
        _ => (String::new(), rhs, ""),
    };
    let mut rows = vec![format!("{lhs} &= {head}")];
    let mut used = glyphs(lhs) + glyphs(&head);
    for (i, term) in terms(body).into_iter().enumerate() {
        let g = glyphs(term);
        if i > 0 && used + g > width {
            rows.push("&\\quad".to_owned());
            used = 0;
        }
        if let Some(last) = rows.last_mut() {
            last.push_str(term);
        }
        used += g;
    }
    if let Some(last) = rows.last_mut() {
        last.push_str(tail);
    }
    rows.join(" \\\\\n")
}

/// `s` split at the first `sep` outside braces and `\left … \right` pairs.
fn split_top_level<'a>(s: &'a str, sep: &str) -> Option<(&'a str, &'a str)> {
    let mut depth = 0i32;
    let bytes = s.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        let rest = &s[i..];
        if depth == 0 && rest.starts_with(sep) {
            return Some((&s[..i], &s[i + sep.len()..]));
        }
        depth += depth_change(rest);
        i += rest.chars().next().map_or(1, char::len_utf8);
    }
    None
}

/// How the text starting at `rest` changes the nesting depth.
fn depth_change(rest: &str) -> i32 {
    if rest.starts_with('{') || rest.starts_with("\\left") {
        1
    } else if rest.starts_with('}') || rest.starts_with("\\right") {
        -1
    } else {
        0
    }
}

/// The terms of a sum at the top level, each with its leading ` + ` or ` - `.
fn terms(s: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let mut depth = 0i32;
    let mut start = 0;
    let mut i = 0;
    while i < s.len() {
        let rest = &s[i..];
        if depth == 0 && i > start && (rest.starts_with(" + ") || rest.starts_with(" - ")) {
            out.push(&s[start..i]);
            start = i;
            i += 3;
            continue;
        }
        depth += depth_change(rest);
        i += rest.chars().next().map_or(1, char::len_utf8);
    }
    out.push(&s[start..]);
    out
}

/// `(sign, numerator, denominator)` if `s` is one `\frac{…}{…}`, optionally negated.
fn as_fraction(s: &str) -> Option<(&str, &str, &str)> {
    let (sign, rest) = match s.strip_prefix('-') {
        Some(r) => ("-", r),
        None => ("", s),
    };
    let rest = rest.strip_prefix("\\frac")?;
    let (num, rest) = braced(rest)?;
    let (den, rest) = braced(rest)?;
    rest.is_empty().then_some((sign, num, den))
}

/// The contents of the brace group `s` starts with, and what follows it.
fn braced(s: &str) -> Option<(&str, &str)> {
    let inner = s.strip_prefix('{')?;
    let mut depth = 1i32;
    for (i, c) in inner.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return Some((&inner[..i], &inner[i + 1..]));
                }
            }
            _ => {}
        }
    }
    None
}

/// A rough count of the glyphs `s` prints: a command is one glyph (spacing and
/// structure commands none), braces, spaces and script marks none.
fn glyphs(s: &str) -> usize {
    const SILENT: [&str; 7] = ["left", "right", "frac", "dot", "ddot", "Bigl", "Bigr"];
    let mut count = 0;
    let mut chars = s.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' => {
                let mut name = String::new();
                while let Some(&n) = chars.peek().filter(|n| n.is_ascii_alphabetic()) {
                    name.push(n);
                    chars.next();
                }
                if !SILENT.contains(&name.as_str()) {
                    count += 1;
                }
            }
            '{' | '}' | ' ' | '^' | '_' | '&' => {}
            _ => count += 1,
        }
    }
    count
}

#[cfg(test)]
mod tests {
    use super::*;

    fn typeset(lines: &[&'static str]) -> Typeset {
        Typeset {
            lagrangian: Cow::Borrowed("L = a"),
            equations: lines.iter().map(|&l| Cow::Borrowed(l)).collect(),
            accelerations: Cow::Borrowed(&[]),
            conserved: Cow::Borrowed(&[]),
            definitions: Cow::Borrowed(&[]),
            values: Cow::Borrowed(&[]),
            costs: Cow::Borrowed(&[]),
        }
    }

    /// A long sum breaks between top-level terms, never inside a group, and every piece of
    /// the line is kept in order.
    #[test]
    fn long_sums_break_between_terms() {
        let line = r"x = a_{1} + \left(b + c\right) - \frac{d}{e} + f g h + k";
        let t = typeset(&[line]);
        let text = t.align_width(6);
        assert_eq!(
            text,
            "\\begin{align}\nL &= a \\\\\nx &= a_{1} \\\\\n&\\quad + \\left(b + c\\right) \\\\\n&\\quad - \\frac{d}{e} \\\\\n&\\quad + f g h + k\n\\end{align}"
        );
    }

    /// A long quotient becomes 1/D times its numerator, which then breaks.
    #[test]
    fn long_quotients_break_in_the_numerator() {
        let t = typeset(&[r"y = -\frac{a b c + d e f}{g}"]);
        let text = t.align_width(4);
        assert!(
            text.contains("y &= -\\frac{1}{g} \\Bigl(a b c \\\\\n&\\quad + d e f\\Bigr)"),
            "{text}"
        );
    }

    #[test]
    fn glyph_count_ignores_structure() {
        assert_eq!(glyphs(r"\frac{I_{1}}{2} \left(\dot{\theta}^{2}\right)"), 7);
    }
}
