//! The recurrences of one [`SeriesStep`] at one order, on coefficients stored series-major
//! (`c[x·stride + k]` is the order-`k` coefficient of series `x`): what the interpreter
//! runs, and the oracle the emitted code is tested against.

use super::tape::{SeriesOp, SeriesStep};

/// `Σⱼ₌lo^hi a_j b_{k−j}` over the series `a` and `b` (both of stride `st`).
#[inline]
fn cauchy(c: &[f64], st: usize, a: usize, b: usize, k: usize, lo: usize, hi: usize) -> f64 {
    let a = &c[a * st..a * st + k + 1];
    let b = &c[b * st..b * st + k + 1];
    let mut acc = 0.0;
    for j in lo..=hi {
        acc += a[j] * b[k - j];
    }
    acc
}

/// `Σⱼ₌lo^{k−lo} a_j a_{k−j}`, folded on its symmetry.
#[inline]
fn folded(c: &[f64], st: usize, a: usize, k: usize, lo: usize) -> f64 {
    let x = &c[a * st..a * st + k + 1];
    let mut acc = 0.0;
    for j in lo..k.div_ceil(2) {
        acc += x[j] * x[k - j];
    }
    acc *= 2.0;
    if k.is_multiple_of(2) {
        acc += x[k / 2] * x[k / 2];
    }
    acc
}

/// Writes the order-`k` coefficient of `step`'s output, every operand known to order `k`
/// and the output to order `k − 1`. `s` holds the scalars' values.
#[inline]
pub(crate) fn step(c: &mut [f64], st: usize, s: &[f64], step: &SeriesStep, k: usize) {
    let out = step.out as usize * st + k;
    let at = |c: &[f64], x: u32, j: usize| c[x as usize * st + j];
    let sc = |x: u32| s[x as usize];
    let v = match step.op {
        SeriesOp::Add(a, b) => at(c, a, k) + at(c, b, k),
        SeriesOp::Sub(a, b) => at(c, a, k) - at(c, b, k),
        SeriesOp::AddScalar(a, x) if k == 0 => at(c, a, 0) + sc(x),
        SeriesOp::SubScalar(a, x) if k == 0 => at(c, a, 0) - sc(x),
        SeriesOp::ScalarSub(x, a) if k == 0 => sc(x) - at(c, a, 0),
        SeriesOp::AddScalar(a, _) | SeriesOp::SubScalar(a, _) => at(c, a, k),
        SeriesOp::ScalarSub(_, a) | SeriesOp::Neg(a) => -at(c, a, k),
        SeriesOp::Scale(a, x) => sc(x) * at(c, a, k),
        SeriesOp::DivScalar(a, x) => at(c, a, k) / sc(x),
        SeriesOp::Mul(a, b) => cauchy(c, st, a as usize, b as usize, k, 0, k),
        SeriesOp::Square(a) => folded(c, st, a as usize, k, 0),
        SeriesOp::Div(a, b) if k == 0 => at(c, a, 0) / at(c, b, 0),
        SeriesOp::Div(a, b) => {
            let sum = cauchy(c, st, b as usize, step.out as usize, k, 1, k);
            (at(c, a, k) - sum) / at(c, b, 0)
        }
        SeriesOp::ScalarDiv(x, a) if k == 0 => sc(x) / at(c, a, 0),
        SeriesOp::ScalarDiv(_, a) => {
            -cauchy(c, st, a as usize, step.out as usize, k, 1, k) / at(c, a, 0)
        }
        SeriesOp::Sqrt(a) if k == 0 => at(c, a, 0).sqrt(),
        SeriesOp::Sqrt(a) => {
            let own = step.out as usize;
            (at(c, a, k) - folded(c, st, own, k, 1)) / (2.0 * c[own * st])
        }
        SeriesOp::SinCos(a) => {
            let (sin, cos) = (step.out as usize, step.out as usize + 1);
            let (sv, cv) = if k == 0 {
                at(c, a, 0).sin_cos()
            } else {
                let x = &c[a as usize * st..a as usize * st + k + 1];
                let sn = &c[sin * st..sin * st + k];
                let cs = &c[cos * st..cos * st + k];
                let (mut ss, mut cc) = (0.0, 0.0);
                for j in 1..=k {
                    let ja = j as f64 * x[j];
                    ss += ja * cs[k - j];
                    cc += ja * sn[k - j];
                }
                let inv = 1.0 / k as f64;
                (ss * inv, -cc * inv)
            };
            c[cos * st + k] = cv;
            sv
        }
    };
    c[out] = v;
}
