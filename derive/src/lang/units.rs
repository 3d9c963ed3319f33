//! Units on values: `2 cm`, `12 g`, `20 deg`, `3000 rpm`, `9.81 m/s^2`, `7.8 g/cm^3`,
//! converted to SI at expansion, and the dimensions the checker compares against each key's.
//!
//! Rust has no syntax for `2 cm`, so the parser rewrites a value's tokens before syn reads
//! them ([`attach`]): a unit and what it follows become `__units!((operand) unit)`, an
//! expression syn parses anywhere a value may sit (in a vector, a call, a sum), keeping
//! every original token and so every span. The checker then reads the macro ([`parse_unit`]).

use precess_core::sym::Rational;
use proc_macro2::{Delimiter, Group, Ident, Punct, Spacing, Span, TokenStream, TokenTree};

/// The name of the macro a value with a unit is rewritten to.
pub const UNITS_MACRO: &str = "__units";

pub use super::dim::Dim;
use super::dim::dim;

/// A unit's size in SI: `ratio · π^pi` (π enters only through `deg`, `rev` and `rpm`).
#[derive(Clone, Copy, PartialEq, Debug)]
pub struct Scale {
    /// The exact rational factor.
    pub ratio: Rational,
    /// The power of π.
    pub pi: i32,
}

/// One unit name: its size in SI and its dimension.
struct Unit {
    name: &'static str,
    num: i128,
    den: i128,
    pi: i32,
    dim: Dim,
}

const fn unit(name: &'static str, num: i128, den: i128, pi: i32, dim: Dim) -> Unit {
    Unit {
        name,
        num,
        den,
        pi,
        dim,
    }
}

/// Every unit name, in the order the docs list them.
const UNITS: &[Unit] = &[
    unit("m", 1, 1, 0, Dim::LENGTH),
    unit("km", 1000, 1, 0, Dim::LENGTH),
    unit("cm", 1, 100, 0, Dim::LENGTH),
    unit("mm", 1, 1000, 0, Dim::LENGTH),
    unit("kg", 1, 1, 0, Dim::MASS),
    unit("g", 1, 1000, 0, Dim::MASS),
    unit("mg", 1, 1_000_000, 0, Dim::MASS),
    unit("s", 1, 1, 0, dim(0, 0, 1)),
    unit("ms", 1, 1000, 0, dim(0, 0, 1)),
    unit("min", 60, 1, 0, dim(0, 0, 1)),
    unit("h", 3600, 1, 0, dim(0, 0, 1)),
    unit("rad", 1, 1, 0, Dim::ANGLE),
    unit("deg", 1, 180, 1, Dim::ANGLE),
    unit("rev", 2, 1, 1, Dim::ANGLE),
    unit("rpm", 1, 30, 1, Dim::ANGULAR_RATE),
    unit("N", 1, 1, 0, Dim::FORCE),
];

fn find(name: &str) -> Option<&'static Unit> {
    UNITS.iter().find(|u| u.name == name)
}

/// The unit names as the messages list them.
pub fn unit_list() -> String {
    let names: Vec<&str> = UNITS.iter().map(|u| u.name).collect();
    names.join(", ")
}

/// Reads a unit, `name (^ -? n)? ((/ | * | ) name (^ -? n)?)*`: its size and dimension, or
/// the message and the tokens it is about.
pub fn parse_unit(tokens: &[TokenTree]) -> Result<(Scale, Dim), (TokenStream, String)> {
    let whole: TokenStream = tokens.iter().cloned().collect();
    let mut scale = Scale {
        ratio: Rational::ONE,
        pi: 0,
    };
    let mut total = Dim::NONE;
    let mut i = 0;
    let overflow = |t: &TokenTree| {
        (
            t.clone().into(),
            "the unit's powers are too large".to_owned(),
        )
    };
    while i < tokens.len() {
        // `/` divides by the one unit after it; `*` or nothing multiplies.
        let mut sign = 1;
        if let TokenTree::Punct(p) = &tokens[i] {
            match p.as_char() {
                '/' => sign = -1,
                '*' => {}
                _ => return Err((TokenTree::Punct(p.clone()).into(), syntax_message())),
            }
            i += 1;
        }
        let Some(TokenTree::Ident(name)) = tokens.get(i) else {
            return Err((whole, syntax_message()));
        };
        if name == "Hz" {
            return Err((TokenTree::Ident(name.clone()).into(), hertz_message()));
        }
        let Some(u) = find(&name.to_string()) else {
            let known = UNITS.iter().map(|u| u.name);
            return Err((
                TokenTree::Ident(name.clone()).into(),
                format!(
                    "unknown unit `{name}`: the units are {}{}",
                    unit_list(),
                    super::keys::did_you_mean(&name.to_string(), known)
                ),
            ));
        };
        i += 1;
        let mut power: i64 = 1;
        if matches!(tokens.get(i), Some(TokenTree::Punct(p)) if p.as_char() == '^') {
            i += 1;
            let negative = matches!(tokens.get(i), Some(TokenTree::Punct(p)) if p.as_char() == '-');
            if negative {
                i += 1;
            }
            let n = match tokens.get(i) {
                Some(TokenTree::Literal(l)) => l.to_string().parse::<i64>().ok(),
                _ => None,
            };
            let Some(n) = n.filter(|n| (1..=9).contains(n)) else {
                let t = tokens.get(i).map_or(whole.clone(), |t| t.clone().into());
                return Err((
                    t,
                    "expected a whole power from 1 to 9 after `^` (or its negative), as in `m/s^2` or `s^-1`".to_owned(),
                ));
            };
            i += 1;
            power = if negative { -n } else { n };
        }
        let power = power * sign;
        let base = Rational::new(u.num, u.den).unwrap_or(Rational::ONE);
        let factor = base
            .checked_pow(power)
            .ok_or_else(|| overflow(&tokens[i - 1]))?;
        scale.ratio = scale
            .ratio
            .checked_mul(factor)
            .ok_or_else(|| overflow(&tokens[i - 1]))?;
        scale.pi += u.pi * power as i32;
        total = u
            .dim
            .pow(power)
            .and_then(|d| total.times(d))
            .ok_or_else(|| overflow(&tokens[i - 1]))?;
    }
    Ok((scale, total))
}

/// Why `Hz` is no unit: every rate a key takes is an angular one, and 1 Hz is read as one
/// turn a second (2π rad/s, as `rpm` counts turns) as often as SI's 1/s (so that
/// `TAU * 50 Hz` is the usual ω = 2πf); either reading would be silently wrong for someone.
fn hertz_message() -> String {
    "`Hz` is refused: a rate here is an angular rate, and 1 Hz reads as one turn a second (2π rad/s) or as SI's 1/s (1 rad/s); write `rev/s` for turns a second, `rpm`, or `rad/s`".to_owned()
}

fn syntax_message() -> String {
    format!(
        "expected a unit such as `cm`, `g/cm^3` or `m/s^2`: unit names ({}) joined by a space or `*`, `/` before a unit divides by it, `^n` raises it to a whole power",
        unit_list()
    )
}

/// True for a name that may start a unit after a value other than a number.
fn is_unit(t: &TokenTree) -> bool {
    matches!(t, TokenTree::Ident(i) if find(&i.to_string()).is_some())
}

/// A value's tokens with every unit attached to what it follows, as `__units!((x) unit)`;
/// `None` if the value holds no unit (it is then parsed as written). A unit follows a number
/// literal, a name or path (`PI`, a field) or a parenthesised value; after a number, any
/// name starts one (`2 furlong` is an unknown unit, not a syntax error), elsewhere only a
/// unit name, since `x y` is no Rust either way.
pub fn attach(tokens: Vec<TokenTree>) -> Option<TokenStream> {
    let mut found = false;
    let out = rewrite(tokens, &mut found);
    found.then(|| out.into_iter().collect())
}

fn rewrite(tokens: Vec<TokenTree>, found: &mut bool) -> Vec<TokenTree> {
    let mut out: Vec<TokenTree> = Vec::with_capacity(tokens.len());
    let mut rest = tokens.into_iter().peekable();
    while let Some(t) = rest.next() {
        let t = match t {
            TokenTree::Group(g) => {
                let inner = rewrite(g.stream().into_iter().collect(), found);
                let mut ng = Group::new(g.delimiter(), inner.into_iter().collect());
                ng.set_span(g.span());
                TokenTree::Group(ng)
            }
            other => other,
        };
        let ahead: Vec<TokenTree> = rest.clone().take(2).collect();
        let starts_unit = match (&t, ahead.first()) {
            // A name followed by `=` or `(` is the next setting with its comma forgotten.
            (TokenTree::Literal(_), Some(next @ TokenTree::Ident(name))) => {
                let setting = match ahead.get(1) {
                    Some(TokenTree::Punct(p)) => p.as_char() == '=',
                    Some(TokenTree::Group(g)) => g.delimiter() == Delimiter::Parenthesis,
                    _ => false,
                };
                name != "as" && (is_unit(next) || !setting)
            }
            (TokenTree::Ident(_), Some(next)) => is_unit(next),
            (TokenTree::Group(g), Some(next)) => {
                g.delimiter() == Delimiter::Parenthesis && is_unit(next)
            }
            _ => false,
        };
        out.push(t);
        if !starts_unit {
            continue;
        }
        *found = true;
        let operand_len = operand_len(&out);
        let operand: Vec<TokenTree> = out.split_off(out.len() - operand_len);
        let mut unit: Vec<TokenTree> = Vec::new();
        // The first name, then powers, `/`, `*` and further unit names.
        if let Some(first) = rest.next() {
            unit.push(first);
        }
        loop {
            match rest.peek() {
                Some(TokenTree::Punct(p)) if p.as_char() == '^' => {
                    unit.extend(rest.next());
                    if matches!(rest.peek(), Some(TokenTree::Punct(p)) if p.as_char() == '-') {
                        unit.extend(rest.next());
                    }
                    // The power, whatever it is: `parse_unit` says what is allowed.
                    if !matches!(rest.peek(), Some(TokenTree::Punct(p)) if p.as_char() == ',') {
                        unit.extend(rest.next());
                    }
                }
                Some(TokenTree::Punct(p)) if matches!(p.as_char(), '/' | '*') => {
                    // A unit name after it continues the unit; anything else is arithmetic.
                    let mut ahead = rest.clone();
                    ahead.next();
                    if !ahead.peek().is_some_and(is_unit) {
                        break;
                    }
                    unit.extend(rest.next());
                    unit.extend(rest.next());
                }
                Some(next) if is_unit(next) => unit.extend(rest.next()),
                _ => break,
            }
        }
        out.extend(units_macro(operand, unit));
    }
    out
}

/// How many of the last tokens of `out` form the operand a unit follows: one token, or a
/// path `a::b::C`.
fn operand_len(out: &[TokenTree]) -> usize {
    let mut n = 1;
    if !matches!(out.last(), Some(TokenTree::Ident(_))) {
        return n;
    }
    // `::` is two joint colons before each further segment.
    while out.len() >= n + 2 {
        let k = out.len() - n;
        let colons = matches!(&out[k - 1], TokenTree::Punct(p) if p.as_char() == ':')
            && matches!(&out[k - 2], TokenTree::Punct(p) if p.as_char() == ':');
        if !colons {
            break;
        }
        n += 2;
        if out.len() > n && matches!(&out[out.len() - n - 1], TokenTree::Ident(_)) {
            n += 1;
        } else {
            break;
        }
    }
    n
}

/// `__units!((operand) unit)`, spanned from the operand's first token to the unit's last,
/// so an error on the whole value underlines both.
fn units_macro(operand: Vec<TokenTree>, unit: Vec<TokenTree>) -> [TokenTree; 3] {
    let first = operand.first().map_or(Span::call_site(), TokenTree::span);
    let last = unit.last().map_or(first, TokenTree::span);
    let mut inner = Group::new(Delimiter::Parenthesis, operand.into_iter().collect());
    inner.set_span(first);
    let mut body: Vec<TokenTree> = vec![TokenTree::Group(inner)];
    body.extend(unit);
    let mut args = Group::new(Delimiter::Parenthesis, body.into_iter().collect());
    args.set_span(last);
    let mut bang = Punct::new('!', Spacing::Alone);
    bang.set_span(first);
    [
        TokenTree::Ident(Ident::new(UNITS_MACRO, first)),
        TokenTree::Punct(bang),
        TokenTree::Group(args),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit_of(text: &str) -> Result<(Scale, Dim), String> {
        let tokens: TokenStream = text.parse().map_err(|_| "lex".to_owned())?;
        let tokens: Vec<TokenTree> = tokens.into_iter().collect();
        parse_unit(&tokens).map_err(|(_, m)| m)
    }

    fn ratio(n: i128, d: i128) -> Rational {
        Rational::new(n, d).unwrap_or(Rational::ZERO)
    }

    #[test]
    fn compound_units_scale_and_dimension() {
        let (s, d) = unit_of("g/cm^3").unwrap_or_else(|e| panic!("{e}"));
        // 1 g/cm³ = 10⁻³ kg / 10⁻⁶ m³ = 1000 kg/m³.
        assert_eq!((s.ratio, s.pi, d), (ratio(1000, 1), 0, Dim::DENSITY));
        let (s, d) = unit_of("m/s^2").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!((s.ratio, d), (ratio(1, 1), Dim::ACCELERATION));
        let (s, d) = unit_of("N m").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!((s.ratio, d), (ratio(1, 1), Dim::TORQUE));
        let (s, d) = unit_of("g * cm^2").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!((s.ratio, d), (ratio(1, 10_000_000), Dim::INERTIA));
        // 1 rpm = 2π/60 rad/s.
        let (s, d) = unit_of("rpm").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!((s.ratio, s.pi, d), (ratio(1, 30), 1, Dim::ANGULAR_RATE));
        let (s, _) = unit_of("deg^2").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!((s.ratio, s.pi), (ratio(1, 32400), 2));
        let (_, d) = unit_of("s^-1").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(d, dim(0, 0, -1));
    }

    #[test]
    fn unknown_units_and_bad_powers_are_refused() {
        let e = unit_of("kgg").err().unwrap_or_default();
        assert!(e.starts_with("unknown unit `kgg`"), "{e}");
        assert!(e.contains("did you mean"), "{e}");
        let e = unit_of("m^x").err().unwrap_or_default();
        assert!(e.contains("whole power"), "{e}");
        // `Hz` is one turn a second to some and 1/s to SI: refused, with both readings.
        let e = unit_of("Hz").err().unwrap_or_default();
        assert!(e.contains("`Hz` is refused") && e.contains("rev/s"), "{e}");
    }

    /// Each unit's size in SI and its (kg, m, s, rad) exponents, written out again as f64s from
    /// the definitions, independently of the table the parser reads.
    const SI: &[(&str, f64, [i8; 4])] = &[
        ("m", 1.0, [0, 1, 0, 0]),
        ("km", 1e3, [0, 1, 0, 0]),
        ("cm", 1e-2, [0, 1, 0, 0]),
        ("mm", 1e-3, [0, 1, 0, 0]),
        ("kg", 1.0, [1, 0, 0, 0]),
        ("g", 1e-3, [1, 0, 0, 0]),
        ("mg", 1e-6, [1, 0, 0, 0]),
        ("s", 1.0, [0, 0, 1, 0]),
        ("ms", 1e-3, [0, 0, 1, 0]),
        ("min", 60.0, [0, 0, 1, 0]),
        ("h", 3600.0, [0, 0, 1, 0]),
        ("rad", 1.0, [0, 0, 0, 1]),
        ("deg", std::f64::consts::PI / 180.0, [0, 0, 0, 1]),
        ("rev", std::f64::consts::TAU, [0, 0, 0, 1]),
        ("rpm", std::f64::consts::TAU / 60.0, [0, 0, -1, 1]),
        ("N", 1.0, [1, 1, -2, 0]),
    ];

    proptest::proptest! {
        // As the crate's other properties: a failure prints its case; no seed file.
        #![proptest_config(proptest::test_runner::Config {
            cases: 256,
            failure_persistence: None,
            ..proptest::test_runner::Config::default()
        })]

        /// Any unit of up to four names, each with a power and joined by a space, `*` or
        /// `/`, has the product of its names' sizes and the sum of their dimensions.
        #[test]
        fn a_compound_unit_is_the_product_of_its_names(
            factors in proptest::collection::vec(
                (0..SI.len(), -3i64..=3, 0..3usize), 1..=4
            )
        ) {
            let mut text = String::new();
            let (mut size, mut dims) = (1.0f64, [0i64; 4]);
            for (k, &(unit, power, join)) in factors.iter().enumerate() {
                let power = if power == 0 { 1 } else { power };
                let (name, si, d) = SI[unit];
                // The first name has no join; `/` divides by the one name after it.
                let sign = if k > 0 && join == 2 { -1 } else { 1 };
                if k > 0 {
                    text.push_str([" ", " * ", " / "][join]);
                }
                text.push_str(&format!("{name}^{power}"));
                size *= si.powi((sign * power) as i32);
                for i in 0..4 {
                    dims[i] += sign * power * i64::from(d[i]);
                }
            }
            let (scale, dim) = unit_of(&text).map_err(proptest::test_runner::TestCaseError::fail)?;
            let ours = scale.ratio.to_f64() * std::f64::consts::PI.powi(scale.pi);
            proptest::prop_assert!(
                ((ours - size) / size).abs() < 1e-13,
                "{text}: {ours} against {size}"
            );
            proptest::prop_assert_eq!([i64::from(dim.m), i64::from(dim.l), i64::from(dim.t), i64::from(dim.a)], dims, "{}", text);
        }
    }

    #[test]
    fn attach_wraps_numbers_constants_and_groups() {
        let wrap = |s: &str| {
            let t: TokenStream = s.parse().unwrap_or_default();
            attach(t.into_iter().collect()).map(|t| t.to_string())
        };
        assert_eq!(wrap("2 * x"), None);
        assert_eq!(wrap("[0, 0, 1]"), None);
        // The next setting after a forgotten comma is no unit.
        assert_eq!(wrap("10 pivot = [0, 0, 1]"), None);
        assert!(wrap("10 furlong").is_some());
        let w = wrap("[2 cm, 0, 1]").unwrap_or_default();
        assert!(w.contains("__units ! ((2) cm)"), "{w}");
        let w = wrap("2 * PI rad / s").unwrap_or_default();
        assert!(w.contains("__units ! ((PI) rad / s)"), "{w}");
        let w = wrap("std::f64::consts::PI rad").unwrap_or_default();
        assert!(
            w.contains("__units ! ((std :: f64 :: consts :: PI) rad)"),
            "{w}"
        );
        let w = wrap("(1 + 2) cm / l").unwrap_or_default();
        // `l` is no unit: the division is arithmetic on the field.
        assert!(w.contains("__units ! (((1 + 2)) cm) / l"), "{w}");
        let w = wrap("7.8 g/cm^3").unwrap_or_default();
        assert!(w.contains("__units ! ((7.8) g / cm ^ 3)"), "{w}");
    }
}
