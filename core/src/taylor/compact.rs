//! The extended mode of generated systems: a [`Tape`] as two constant tables the derive
//! macros embed in the generated `coefficients_extended_into` ([`Tape::extended_tokens`]),
//! and the interpreter of its double-double low orders ([`low_orders`]) that code calls.
//!
//! Why an interpreter and not emitted code: the double-double orders are a few (L ≈ 6) and
//! cost what they cost in any form, while a second emitted copy of every recurrence, in
//! double-double, would double the code the compiler chews on for every scene (which is
//! already what bounds the build of large mechanisms). Two integer and float tables are a
//! few tokens per step and nothing to optimise.
//!
//! The encoding (all `u32`): a header `[n, time or u32::MAX, series, scalars, steps,
//! outputs]`, then three words per scalar `[op, a, b]`, four per step `[op, out, a, b]`
//! and two per output `[series?, index]`; a literal or a real power's exponent is an index
//! into the float table, a parameter an index into the values the generated code passes in
//! the order of [`Tape::scalar_symbols`].

use proc_macro2::{Literal, TokenStream};
use quote::quote;

use super::recurrence_dd::{self, DdTable};
use super::tape::{ScalarOp, SeriesOp, SeriesStep, Tape, Value};
use crate::codegen::f64_literal;
use crate::exact::Dd;
use crate::sym::{Func, SymbolId};

const HEADER: usize = 6;
const NO_TIME: u32 = u32::MAX;

impl Tape {
    /// The tape as the word and float tables [`low_orders`] reads (see the module's docs).
    pub fn compact(&self) -> (Vec<u32>, Vec<f64>) {
        let mut floats = Vec::new();
        let mut float = |x: f64| {
            floats.push(x);
            floats.len() as u32 - 1
        };
        let mut w = vec![
            self.dimension as u32,
            self.time.unwrap_or(NO_TIME),
            self.series_count,
            self.scalars.len() as u32,
            self.steps.len() as u32,
            self.outputs.len() as u32,
        ];
        let mut symbols = 0u32;
        for op in &self.scalars {
            w.extend_from_slice(&match *op {
                ScalarOp::Const(c) => [0, float(c), 0],
                ScalarOp::Symbol(_) => {
                    symbols += 1;
                    [1, symbols - 1, 0]
                }
                ScalarOp::Add(a, b) => [2, a, b],
                ScalarOp::Sub(a, b) => [3, a, b],
                ScalarOp::Mul(a, b) => [4, a, b],
                ScalarOp::Div(a, b) => [5, a, b],
                ScalarOp::Neg(a) => [6, a, 0],
                ScalarOp::Sqrt(a) => [7, a, 0],
                ScalarOp::Powf(a, r) => [8, a, float(r)],
                ScalarOp::Sin(a) => [9, a, 0],
                ScalarOp::Cos(a) => [10, a, 0],
                ScalarOp::Func(f, a) => [11, a, f.index() as u32],
            });
        }
        for st in &self.steps {
            let (op, a, b) = match st.op {
                SeriesOp::Add(a, b) => (0, a, b),
                SeriesOp::AddScalar(a, b) => (1, a, b),
                SeriesOp::Sub(a, b) => (2, a, b),
                SeriesOp::SubScalar(a, b) => (3, a, b),
                SeriesOp::ScalarSub(a, b) => (4, a, b),
                SeriesOp::Mul(a, b) => (5, a, b),
                SeriesOp::Square(a) => (6, a, 0),
                SeriesOp::Scale(a, b) => (7, a, b),
                SeriesOp::Div(a, b) => (8, a, b),
                SeriesOp::DivScalar(a, b) => (9, a, b),
                SeriesOp::ScalarDiv(a, b) => (10, a, b),
                SeriesOp::Neg(a) => (11, a, 0),
                SeriesOp::Sqrt(a) => (12, a, 0),
                SeriesOp::Powf(a, r) => (13, a, float(r)),
                SeriesOp::SinCos(a) => (14, a, 0),
                SeriesOp::Func(f, a) => (15, a, f.index() as u32),
            };
            w.extend_from_slice(&[op, st.out, a, b]);
        }
        for out in &self.outputs {
            w.extend_from_slice(&match *out {
                Value::Scalar(x) => [0, x],
                Value::Series(x) => [1, x],
            });
        }
        (w, floats)
    }

    /// The body of `TaylorSystem::coefficients_extended_into` for the code
    /// [`Tape::to_tokens`] emits with the same `max_order` and `symbol`: the `f64` table by
    /// `self.coefficients_into`, then the double-double low orders by [`low_orders`] from
    /// the embedded tables. It reads the names `self`, `ws`, `t`, `y`, `order`, `coeffs` and
    /// `low`, and returns the `bool` of the method.
    pub fn extended_tokens(
        &self,
        max_order: usize,
        symbol: &mut dyn FnMut(SymbolId) -> TokenStream,
    ) -> TokenStream {
        let (words, floats) = self.compact();
        let words = words.into_iter().map(Literal::u32_unsuffixed);
        let floats = floats.into_iter().map(f64_literal);
        let values: Vec<TokenStream> = self.scalar_symbols().map(&mut *symbol).collect();
        let n = self.dimension;
        quote! {
            const __WORDS: &[u32] = &[#(#words),*];
            const __FLOATS: &[f64] = &[#(#floats),*];
            let ::core::option::Option::Some(__top) = coeffs.len().checked_sub(1) else {
                return false;
            };
            let __y: [f64; #n] = ::core::array::from_fn(|__i| y[__i].hi + y[__i].lo);
            self.coefficients_into(ws, t.hi + t.lo, &__y, order, coeffs);
            let __n: usize = order.min(#max_order).min(__top);
            let __values: &[f64] = &[#(#values),*];
            ::precess::__private::low_orders(__WORDS, __FLOATS, __values, ws, t, y, __n, low)
        }
    }
}

/// Scalar `i` in double-double from its three words, the scalars before it in `done`;
/// `None` if the words are malformed or read a scalar not yet made.
fn scalar(w: &[u32], floats: &[f64], values: &[f64], done: &DdTable<'_>, i: u32) -> Option<Dd> {
    let x = |j: u32| (j < i).then(|| done.get(j, 0));
    let f = |i: u32| floats.get(i as usize).copied().map(Dd::from);
    Some(match *w {
        [0, a, _] => f(a)?,
        [1, a, _] => Dd::from(*values.get(a as usize)?),
        [2, a, b] => x(a)? + x(b)?,
        [3, a, b] => x(a)? - x(b)?,
        [4, a, b] => x(a)? * x(b)?,
        [5, a, b] => x(a)? / x(b)?,
        [6, a, _] => -x(a)?,
        [7, a, _] => x(a)?.sqrt(),
        [8, a, r] => x(a)?.powf(*floats.get(r as usize)?),
        [9, a, _] => x(a)?.sin_cos().0,
        [10, a, _] => x(a)?.sin_cos().1,
        [11, a, f] => Func::from_index(f as usize)?.value_dd(x(a)?),
        _ => return None,
    })
}

/// One step from its four words, `None` if they are malformed or name a series at or past
/// `series` (or a scalar past `scalars`), so that the recurrences index nothing out of range.
fn series_step(w: &[u32], floats: &[f64], series: u32, scalars: u32) -> Option<SeriesStep> {
    let [op, out, a, b] = *w else { return None };
    let s = |x: u32| (x < series).then_some(x);
    let c = |x: u32| (x < scalars).then_some(x);
    let op = match op {
        0 => SeriesOp::Add(s(a)?, s(b)?),
        1 => SeriesOp::AddScalar(s(a)?, c(b)?),
        2 => SeriesOp::Sub(s(a)?, s(b)?),
        3 => SeriesOp::SubScalar(s(a)?, c(b)?),
        4 => SeriesOp::ScalarSub(c(a)?, s(b)?),
        5 => SeriesOp::Mul(s(a)?, s(b)?),
        6 => SeriesOp::Square(s(a)?),
        7 => SeriesOp::Scale(s(a)?, c(b)?),
        8 => SeriesOp::Div(s(a)?, s(b)?),
        9 => SeriesOp::DivScalar(s(a)?, c(b)?),
        10 => SeriesOp::ScalarDiv(c(a)?, s(b)?),
        11 => SeriesOp::Neg(s(a)?),
        12 => SeriesOp::Sqrt(s(a)?),
        13 => SeriesOp::Powf(s(a)?, *floats.get(b as usize)?),
        14 => SeriesOp::SinCos(s(a)?),
        15 => SeriesOp::Func(Func::from_index(b as usize)?, s(a)?),
        _ => return None,
    };
    // A sine–cosine pair writes three series, a primitive its companions besides.
    let width = op.width();
    (out.checked_add(width)? <= series).then_some(SeriesStep { out, op })
}

/// The double-double low orders of a tape given by [`Tape::compact`]'s tables, with the
/// scalar symbols' values in `values`: `low[k]` for `k = 0, …, min(low.len() − 1, order)`,
/// as [`super::TaylorSystem::coefficients_extended_into`] promises, the scratch in rows
/// appended to the generated workspace `ws` for the call (its length is restored, its
/// capacity kept, so repeated calls allocate nothing). Returns `false`, having written
/// nothing, if the tables are malformed or `N` is not their dimension (which generated code
/// never does).
#[doc(hidden)]
#[allow(clippy::too_many_arguments)]
pub fn low_orders<const N: usize, const R: usize>(
    words: &[u32],
    floats: &[f64],
    values: &[f64],
    ws: &mut Vec<[f64; R]>,
    t: Dd,
    y: &[Dd; N],
    order: usize,
    low: &mut [[Dd; N]],
) -> bool {
    let Some(&[n, time, series, scalars, steps, outputs]) = words.get(..HEADER) else {
        return false;
    };
    let (ns, nt, no) = (scalars as usize, steps as usize, outputs as usize);
    let body = &words[HEADER..];
    if n as usize != N || no != N || body.len() != 3 * ns + 4 * nt + 2 * no || R == 0 {
        return false;
    }
    let (scalar_words, rest) = body.split_at(3 * ns);
    let (step_words, output_words) = rest.split_at(4 * nt);
    let Some(last) = low.len().checked_sub(1).map(|l| l.min(order)) else {
        return true;
    };
    let st = last + 1;
    // The scratch: the scalars (two words each), then the series' table.
    let table = DdTable::len(series as usize, st);
    let need = 2 * ns + table;
    let rows = ws.len();
    ws.resize(rows + need.div_ceil(R), [0.0; R]);
    let ok = run(
        Tables {
            scalar_words,
            step_words,
            output_words,
            floats,
            values,
            time,
            series,
            scalars,
        },
        &mut ws[rows..].as_flattened_mut()[..need],
        t,
        y,
        low,
        last,
    );
    ws.truncate(rows);
    ok
}

/// The tables of [`low_orders`], split.
struct Tables<'a> {
    scalar_words: &'a [u32],
    step_words: &'a [u32],
    output_words: &'a [u32],
    floats: &'a [f64],
    values: &'a [f64],
    time: u32,
    series: u32,
    scalars: u32,
}

fn run<const N: usize>(
    tb: Tables<'_>,
    scratch: &mut [f64],
    t: Dd,
    y: &[Dd; N],
    low: &mut [[Dd; N]],
    last: usize,
) -> bool {
    let (sw, table) = scratch.split_at_mut(2 * tb.scalars as usize);
    // Everything is checked before anything is written to `low`.
    let steps = || {
        tb.step_words
            .chunks_exact(4)
            .map(|w| series_step(w, tb.floats, tb.series, tb.scalars))
    };
    let outputs_ok = tb.output_words.chunks_exact(2).all(|w| match *w {
        [1, x] => x < tb.series,
        [0, x] => x < tb.scalars,
        _ => false,
    });
    let time_ok = tb.time == NO_TIME || tb.time < tb.series;
    if !outputs_ok || !time_ok || steps().any(|s| s.is_none()) {
        return false;
    }
    // The scalars in double-double, a table of one order.
    let mut sdd = DdTable { w: sw, st: 1 };
    for (i, w) in tb.scalar_words.chunks_exact(3).enumerate() {
        let Some(v) = scalar(w, tb.floats, tb.values, &sdd, i as u32) else {
            return false;
        };
        sdd.set(i as u32, 0, v);
    }
    let s = |x: u32| sdd.get(x, 0);
    let st = last + 1;
    let mut c = DdTable { w: table, st };
    for (i, &yi) in y.iter().enumerate() {
        c.set(i as u32, 0, yi);
    }
    if tb.time != NO_TIME {
        for k in 0..st {
            let v = match k {
                0 => t,
                1 => Dd::from(1.0),
                _ => Dd::default(),
            };
            c.set(tb.time, k, v);
        }
    }
    low[0] = *y;
    for k in 0..last {
        for step in steps().flatten() {
            recurrence_dd::step(&mut c, &s, &step, k);
        }
        let div = (k + 1) as f64;
        for (i, w) in tb.output_words.chunks_exact(2).enumerate() {
            let fk = match *w {
                [1, x] => c.get(x, k),
                [_, x] if k == 0 => s(x),
                _ => Dd::default(),
            };
            let v = fk.div_f64(div);
            c.set(i as u32, k + 1, v);
            low[k + 1][i] = v;
        }
    }
    true
}
