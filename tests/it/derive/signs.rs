//! Signs in printed LaTeX: random expression trees with negative factors, negative and
//! long rationals (the exact values of f64s, whose products overflow into several constant
//! factors), quotients, powers, sines and cosines are printed by `latex` and `paper_latex`,
//! read back by the test's own reader and evaluated against the arena at random points; a
//! negative factor that reads as a subtraction changes the value read. Concrete cases the
//! issue names (`a·(−b)/c`, `(−a)/(b − c)`, `−(a − b) c / d`) are checked the same way and
//! for where the minus sign stands.

use crate::common;

use std::collections::HashMap;

use common::latex::evaluate;
use common::tree::close;
use precess_core::codegen::{latex, paper_latex};
use precess_core::sym::{Arena, ExprId, Node, Rational, SymError};
use proptest::prelude::*;

/// The parameters of the trees, with the LaTeX they print as.
const VARS: [(&str, &str); 4] = [("a", "a"), ("b", "b"), ("c", "c"), ("theta", "\\theta")];

#[derive(Clone, Debug)]
enum Tree {
    Var(usize),
    /// `n / d`.
    Small(i64, i64),
    /// The exact value of an f64 of 53 significant bits: products of three overflow an i128.
    Long(f64),
    Add(Box<Tree>, Box<Tree>),
    Sub(Box<Tree>, Box<Tree>),
    Mul(Box<Tree>, Box<Tree>),
    Div(Box<Tree>, Box<Tree>),
    Neg(Box<Tree>),
    Pow(Box<Tree>, i64),
    Sin(Box<Tree>),
    Cos(Box<Tree>),
    /// √(t² + 1), defined everywhere.
    Root(Box<Tree>),
}

fn tree() -> impl Strategy<Value = Tree> {
    let leaf = prop_oneof![
        4 => (0..VARS.len()).prop_map(Tree::Var),
        2 => (-5i64..=5, 1i64..=4).prop_map(|(n, d)| Tree::Small(n, d)),
        2 => (-1.0f64..1.0).prop_map(|x| Tree::Long(x * 0.037)),
    ];
    leaf.prop_recursive(5, 32, 2, |inner| {
        let b = || inner.clone().prop_map(Box::new);
        prop_oneof![
            1 => (b(), b()).prop_map(|(x, y)| Tree::Add(x, y)),
            1 => (b(), b()).prop_map(|(x, y)| Tree::Sub(x, y)),
            3 => (b(), b()).prop_map(|(x, y)| Tree::Mul(x, y)),
            2 => (b(), b()).prop_map(|(x, y)| Tree::Div(x, y)),
            2 => b().prop_map(Tree::Neg),
            1 => (b(), -3i64..=3).prop_map(|(x, n)| Tree::Pow(x, n)),
            1 => b().prop_map(Tree::Sin),
            1 => b().prop_map(Tree::Cos),
            1 => b().prop_map(Tree::Root),
        ]
    })
}

impl Tree {
    fn build(&self, a: &mut Arena) -> Result<ExprId, SymError> {
        let two = |a: &mut Arena, x: &Tree, y: &Tree| -> Result<(ExprId, ExprId), SymError> {
            Ok((x.build(a)?, y.build(a)?))
        };
        Ok(match self {
            Tree::Var(i) => a.parameter(VARS[*i].0),
            Tree::Small(n, d) => {
                let r = Rational::new(i128::from(*n), i128::from(*d)).unwrap_or(Rational::ONE);
                a.constant(r)
            }
            Tree::Long(x) => a.constant(Rational::from_f64(*x).unwrap_or(Rational::ONE)),
            Tree::Add(x, y) => {
                let (x, y) = two(a, x, y)?;
                a.add(x, y)
            }
            Tree::Sub(x, y) => {
                let (x, y) = two(a, x, y)?;
                a.sub(x, y)
            }
            Tree::Mul(x, y) => {
                let (x, y) = two(a, x, y)?;
                a.mul(x, y)
            }
            Tree::Div(x, y) => {
                let (x, y) = two(a, x, y)?;
                a.div(x, y)?
            }
            Tree::Neg(x) => {
                let x = x.build(a)?;
                a.neg(x)
            }
            Tree::Pow(x, n) => {
                let x = x.build(a)?;
                a.powi(x, *n)?
            }
            Tree::Sin(x) => {
                let x = x.build(a)?;
                a.sin(x)
            }
            Tree::Cos(x) => {
                let x = x.build(a)?;
                a.cos(x)
            }
            Tree::Root(x) => {
                let x = x.build(a)?;
                let x2 = a.mul(x, x);
                let one = a.one();
                let u = a.add(x2, one);
                a.sqrt(u)?
            }
        })
    }
}

/// The arena's environment and the reader's variables at the point `p`.
fn environment(a: &Arena, p: &[f64; 4]) -> (Vec<f64>, HashMap<String, f64>) {
    let mut env = vec![f64::NAN; a.symbol_count()];
    let mut vars = HashMap::new();
    for (&(name, latex), &v) in VARS.iter().zip(p) {
        if let Some(s) = a.find_parameter(name) {
            env[s.index()] = v;
        }
        vars.insert(latex.to_owned(), v);
    }
    (env, vars)
}

/// Whether `e` holds a product of several constant factors (an overflowed coefficient).
fn has_split_coefficient(a: &Arena, e: ExprId) -> bool {
    let mut stack = vec![e];
    while let Some(e) = stack.pop() {
        match a.node(e) {
            Node::Mul(f) => {
                let consts = f
                    .iter()
                    .filter(|&&x| matches!(a.node(x), Node::Const(_)))
                    .count();
                if consts > 1 {
                    return true;
                }
                stack.extend(f.iter());
            }
            Node::Add(f) => stack.extend(f.iter()),
            Node::Pow(b, _) | Node::Powr(b, _) => stack.push(*b),
            Node::Sin(u) | Node::Cos(u) | Node::Sqrt(u) | Node::Func(_, u) => stack.push(*u),
            Node::Const(_) | Node::Sym(_) => {}
        }
    }
    false
}

/// Whether `e` takes a sine or cosine of an argument beyond 10⁴ in magnitude: there the
/// last bit of the argument (its rounding, computed one way by the arena and another by the
/// reader, as (p/q)⁻³ of a long rational, say) moves the value by |u| ε, past the 10⁻⁷ the
/// read-back is held to (sin(1/0.000144771³) = sin(3.3·10¹¹) read back as −0.2593437 against
/// −0.2593530).
fn wild_phase(a: &Arena, e: ExprId, env: &[f64]) -> bool {
    let mut stack = vec![e];
    while let Some(e) = stack.pop() {
        match a.node(e) {
            Node::Sin(u) | Node::Cos(u) => {
                let phase = a.eval(*u, env).abs();
                if phase.is_nan() || phase > 1e4 {
                    return true;
                }
                stack.push(*u);
            }
            Node::Mul(f) | Node::Add(f) => stack.extend(f.iter()),
            Node::Pow(b, _) | Node::Powr(b, _) => stack.push(*b),
            Node::Sqrt(u) | Node::Func(_, u) => stack.push(*u),
            Node::Const(_) | Node::Sym(_) => {}
        }
    }
    false
}

/// Both printers' LaTeX of `e` read back at `p` agree with the arena's value of `e`.
fn check_read_back(a: &Arena, e: ExprId, p: &[f64; 4]) -> Result<(), TestCaseError> {
    let (env, vars) = environment(a, p);
    let expected = a.eval(e, &env);
    if !expected.is_finite() || expected.abs() > 1e6 || wild_phase(a, e, &env) {
        return Ok(());
    }
    for (printer, text) in [("latex", latex(a, e)), ("paper_latex", paper_latex(a, e))] {
        let read = evaluate(&text, &vars)
            .map_err(|m| TestCaseError::fail(format!("{printer}: {m} in {text}")))?;
        prop_assert!(
            close(read, expected, 1e-7),
            "{printer} reads {read}, the arena gives {expected}: {text}"
        );
    }
    Ok(())
}

fn point() -> impl Strategy<Value = [f64; 4]> {
    [0.3f64..1.7, -1.7f64..-0.3, 0.4f64..1.9, -3.0f64..3.0]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Every random tree prints as LaTeX that reads back to its value.
    #[test]
    fn printed_expressions_read_back_to_their_value(t in tree(), p in point()) {
        let mut a = Arena::new();
        let Ok(e) = t.build(&mut a) else { return Ok(()) };
        check_read_back(&a, e, &p)?;
    }

    /// Products of three long constants with a negative one among them (an overflowed
    /// coefficient, as a top of literal parts has) and a quotient read back, whatever the
    /// order and signs of the constants.
    #[test]
    fn split_coefficients_read_back(
        x in prop::array::uniform3(-1.0f64..1.0),
        p in point(),
        var in 0..VARS.len(),
    ) {
        let mut a = Arena::new();
        let mut e = a.parameter(VARS[var].0);
        for v in x {
            let k = a.constant(Rational::from_f64(v * 0.037 + 1e-9).unwrap_or(Rational::ONE));
            e = a.mul(k, e);
        }
        let c = a.parameter("c");
        let b = a.parameter("b");
        let d = a.sub(b, c);
        let Ok(q) = a.div(e, d) else { return Ok(()) };
        check_read_back(&a, e, &p)?;
        check_read_back(&a, q, &p)?;
    }
}

/// The trees do reach the case the filer met: a product whose coefficient overflowed into
/// several constant factors, one of them negative.
#[test]
fn the_trees_reach_split_coefficients() {
    let mut a = Arena::new();
    let x = a.parameter("a");
    let mut e = x;
    for v in [0.0123456789012345, -0.0234567890123456, 0.0345678901234567] {
        let k = a.constant(Rational::from_f64(v).unwrap_or(Rational::ONE));
        e = a.mul(k, e);
    }
    assert!(has_split_coefficient(&a, e), "{}", a.display(e));
}

/// A product of a positive and a negative long constant prints with its one minus sign in
/// front, never between the factors, and a quotient of it as `-\frac{…}{…}`.
#[test]
fn a_negative_long_factor_prints_in_front() {
    let mut a = Arena::new();
    let x = a.parameter("a");
    let y = a.parameter("b");
    let mut e = x;
    for v in [0.0123456789012345, -0.0234567890123456, 0.0345678901234567] {
        let k = a.constant(Rational::from_f64(v).unwrap_or(Rational::ONE));
        e = a.mul(k, e);
    }
    let Ok(q) = a.div(e, y) else {
        panic!("b is not zero")
    };
    for (what, text) in [("product", latex(&a, e)), ("quotient", latex(&a, q))] {
        assert!(text.starts_with('-'), "{what}: {text}");
        assert_eq!(
            text.matches('-').count(),
            1 + text.matches("^{-").count(),
            "{what}: {text}"
        );
    }
    let p = [1.1, -0.7, 0.9, 0.3];
    check_read_back(&a, e, &p).unwrap_or_else(|m| panic!("{m}"));
    check_read_back(&a, q, &p).unwrap_or_else(|m| panic!("{m}"));
}

/// `a·(−b)/c`, `(−a)/(b − c)` and `−(a − b) c / d` print with the sign in front of the
/// fraction (or inside the difference), and read back.
#[test]
fn the_issues_quotients_print_their_sign_in_front() {
    let mut ar = Arena::new();
    let [a, b, c, d] = ["a", "b", "c", "theta"].map(|n| ar.parameter(n));
    let minus_b = ar.neg(b);
    let ab = ar.mul(a, minus_b);
    let first = ar.div(ab, c).unwrap_or(a);
    let minus_a = ar.neg(a);
    let b_c = ar.sub(b, c);
    let second = ar.div(minus_a, b_c).unwrap_or(a);
    let a_b = ar.sub(a, b);
    let minus_ab = ar.neg(a_b);
    let times_c = ar.mul(minus_ab, c);
    let third = ar.div(times_c, d).unwrap_or(a);
    assert_eq!(latex(&ar, first), r"-\frac{a b}{c}");
    assert_eq!(latex(&ar, second), r"-\frac{a}{b - c}");
    assert_eq!(latex(&ar, third), r"\frac{c \left(b - a\right)}{\theta}");
    let p = [1.3, -0.4, 0.8, 0.6];
    for e in [first, second, third] {
        check_read_back(&ar, e, &p).unwrap_or_else(|m| panic!("{m}"));
    }
}
