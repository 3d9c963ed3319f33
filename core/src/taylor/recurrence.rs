//! The recurrences of one [`SeriesStep`] at one order, on coefficients stored series-major
//! (`c[x·stride + k]` is the order-`k` coefficient of series `x`): what the interpreter
//! runs, and the oracle the emitted code is tested against. The sums go through
//! [`super::kernels`], split as in the emitted code: the interior over the lower orders
//! first, the terms that read order k last, so that both round alike.

use super::kernels::{cauchy, dot_reversed, power_interior, square};
use super::tape::{SeriesOp, SeriesStep};
use crate::sym::functions::F64Table;

/// Writes the order-`k` coefficient of `step`'s output, every operand known to order `k`
/// and the output to order `k − 1`. `s` holds the scalars' values.
#[inline]
pub(crate) fn step(c: &mut [f64], st: usize, s: &[f64], step: &SeriesStep, k: usize) {
    let out = step.out as usize;
    if let SeriesOp::Func(f, a) = step.op {
        // A primitive writes its output and companions itself.
        let mut table = F64Table { c, st };
        f.primitive().series(&mut table, a, step.out, k);
        return;
    }
    fn row(c: &[f64], st: usize, x: usize) -> &[f64] {
        &c[x * st..x * st + st]
    }
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
        SeriesOp::Mul(a, b) => cauchy(&row(c, st, a as usize)[..=k], &row(c, st, b as usize)[..=k]),
        SeriesOp::Square(a) => square(&row(c, st, a as usize)[..=k]),
        SeriesOp::Div(a, b) if k == 0 => at(c, a, 0) / at(c, b, 0),
        SeriesOp::Div(a, b) => {
            // Σⱼ₌₁ᵏ b_j c_{k−j}: the interior j < k, then b_k c_0.
            let (bs, cs) = (row(c, st, b as usize), row(c, st, out));
            let sum = dot_reversed(&bs[1..k], &cs[1..k]) + bs[k] * cs[0];
            (at(c, a, k) - sum) / bs[0]
        }
        SeriesOp::ScalarDiv(x, a) if k == 0 => sc(x) / at(c, a, 0),
        SeriesOp::ScalarDiv(_, a) => {
            let (xs, cs) = (row(c, st, a as usize), row(c, st, out));
            -(dot_reversed(&xs[1..k], &cs[1..k]) + xs[k] * cs[0]) / xs[0]
        }
        SeriesOp::Sqrt(a) if k == 0 => at(c, a, 0).sqrt(),
        SeriesOp::Sqrt(a) => (at(c, a, k) - square(&row(c, st, out)[1..k])) / (2.0 * c[out * st]),
        SeriesOp::Powf(a, r) if k == 0 => at(c, a, 0).powf(r),
        SeriesOp::Powf(a, r) => {
            // The interior j = 1 … k − 1, then the term j = 0 that reads a_k.
            let (xs, cs) = (row(c, st, a as usize), row(c, st, out));
            let kf = k as f64;
            (power_interior(&xs[1..k], &cs[1..k], r) + r * kf * xs[k] * cs[0]) / (kf * xs[0])
        }
        SeriesOp::SinCos(a) => {
            let (sin, cos, d) = (out, out + 1, out + 2);
            let (sv, cv) = if k == 0 {
                at(c, a, 0).sin_cos()
            } else {
                // d_k = k a_k: the derivative's coefficients, shared by both sums.
                let dk = k as f64 * at(c, a, k);
                c[d * st + k] = dk;
                let ds = &row(c, st, d)[1..k];
                let (ss, cs) = (row(c, st, sin), row(c, st, cos));
                let inv = 1.0 / k as f64;
                (
                    (dot_reversed(ds, &cs[1..k]) + dk * cs[0]) * inv,
                    -(dot_reversed(ds, &ss[1..k]) + dk * ss[0]) * inv,
                )
            };
            c[cos * st + k] = cv;
            sv
        }
        // Written above, before the match.
        SeriesOp::Func(..) => return,
    };
    c[out * st + k] = v;
}
