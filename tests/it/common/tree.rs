//! Random expression trees for property tests: evaluated naively in f64 (the reference) and
//! built through the engine's canonical constructors (the code under test).

use precess_core::sym::{Arena, ExprId, Rational, SymError};
use proptest::prelude::*;

/// Symbols the trees use; environments index them by position.
pub const VARS: [&str; 3] = ["x", "y", "z"];

#[derive(Clone, Debug)]
pub enum Tree {
    Var(usize),
    Const(i64, i64),
    Add(Box<Tree>, Box<Tree>),
    Sub(Box<Tree>, Box<Tree>),
    Mul(Box<Tree>, Box<Tree>),
    Div(Box<Tree>, Box<Tree>),
    Pow(Box<Tree>, i64),
    Sin(Box<Tree>),
    Cos(Box<Tree>),
    /// √(t² + 1): a root that is defined everywhere.
    SqrtPos(Box<Tree>),
}

pub fn tree() -> impl Strategy<Value = Tree> {
    let leaf = prop_oneof![
        3 => (0..VARS.len()).prop_map(Tree::Var),
        1 => (-4i64..=4, 1i64..=3).prop_map(|(n, d)| Tree::Const(n, d)),
    ];
    leaf.prop_recursive(5, 40, 2, |inner| {
        let b = || inner.clone().prop_map(Box::new);
        prop_oneof![
            (b(), b()).prop_map(|(a, c)| Tree::Add(a, c)),
            (b(), b()).prop_map(|(a, c)| Tree::Sub(a, c)),
            (b(), b()).prop_map(|(a, c)| Tree::Mul(a, c)),
            (b(), b()).prop_map(|(a, c)| Tree::Div(a, c)),
            (b(), -3i64..=4).prop_map(|(a, n)| Tree::Pow(a, n)),
            b().prop_map(Tree::Sin),
            b().prop_map(Tree::Cos),
            b().prop_map(Tree::SqrtPos),
        ]
    })
}

impl Tree {
    /// Naive evaluation, plus the smallest |divisor| met (to skip near-singular points; an
    /// ill-conditioned sine or cosine counts as one).
    pub fn eval(&self, env: &[f64], min_div: &mut f64) -> f64 {
        match self {
            Tree::Var(i) => env[*i],
            Tree::Const(n, d) => *n as f64 / *d as f64,
            Tree::Add(a, b) => a.eval(env, min_div) + b.eval(env, min_div),
            Tree::Sub(a, b) => a.eval(env, min_div) - b.eval(env, min_div),
            Tree::Mul(a, b) => a.eval(env, min_div) * b.eval(env, min_div),
            Tree::Div(a, b) => {
                let d = b.eval(env, min_div);
                *min_div = min_div.min(d.abs());
                a.eval(env, min_div) / d
            }
            Tree::Pow(a, n) => {
                let v = a.eval(env, min_div);
                if *n < 0 {
                    *min_div = min_div.min(v.abs());
                }
                v.powi(*n as i32)
            }
            Tree::Sin(a) => trig(a.eval(env, min_div), min_div).sin(),
            Tree::Cos(a) => trig(a.eval(env, min_div), min_div).cos(),
            Tree::SqrtPos(a) => {
                let v = a.eval(env, min_div);
                (v * v + 1.0).sqrt()
            }
        }
    }

    /// The same expression through the engine's constructors.
    pub fn build(&self, a: &mut Arena) -> Result<ExprId, SymError> {
        Ok(match self {
            Tree::Var(i) => a.parameter(VARS[*i]),
            Tree::Const(n, d) => a.constant(Rational::new(*n as i128, *d as i128).unwrap()),
            Tree::Add(x, y) => {
                let (x, y) = (x.build(a)?, y.build(a)?);
                a.add(x, y)
            }
            Tree::Sub(x, y) => {
                let (x, y) = (x.build(a)?, y.build(a)?);
                a.sub(x, y)
            }
            Tree::Mul(x, y) => {
                let (x, y) = (x.build(a)?, y.build(a)?);
                a.mul(x, y)
            }
            Tree::Div(x, y) => {
                let (x, y) = (x.build(a)?, y.build(a)?);
                a.div(x, y)?
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
            Tree::SqrtPos(x) => {
                let x = x.build(a)?;
                let x2 = a.mul(x, x);
                let one = a.one();
                let u = a.add(x2, one);
                a.sqrt(u)?
            }
        })
    }
}

/// Passes a trig argument through, flagging a huge one as ill-conditioned: sin(1e10) changes
/// in the sixth digit when its argument is rounded differently, so two correct evaluation
/// orders need not agree there.
fn trig(x: f64, min_div: &mut f64) -> f64 {
    if x.abs() > 1e3 {
        *min_div = 0.0;
    }
    x
}

/// The environment for the arena: symbol `VARS[i]` at its symbol index.
pub fn arena_env(a: &Arena, vals: &[f64]) -> Vec<f64> {
    let mut env = vec![f64::NAN; a.symbol_count()];
    for (i, name) in VARS.iter().enumerate() {
        if let Some(s) = a.find_parameter(name) {
            env[s.index()] = vals[i];
        }
    }
    env
}

/// `|a − b|` small against the size of the values involved.
pub fn close(a: f64, b: f64, rel: f64) -> bool {
    if a.is_nan() || b.is_nan() {
        return a.is_nan() && b.is_nan();
    }
    (a - b).abs() <= rel * (1.0 + a.abs().max(b.abs()))
}
