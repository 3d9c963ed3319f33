//! Emission of a [`Tape`] as Rust: the body of [`super::TaylorSystem::coefficients`]
//! specialised to one right-hand side, which the derive macros splice into
//! `impl TaylorSystem<N>` for a scene that asks (`taylor = K`).
//!
//! The series live in the caller's workspace, `Vec<[f64; K + 1]>` (one row per series, `K`
//! a constant), bound row by row with one slice pattern so that every index is checked
//! against a length the compiler knows; nothing is zeroed or allocated per call (the rows
//! are sized once, on the first call). The scalars are `let`s computed once (literals
//! inlined, so the compiler folds them); order 0 (the values themselves: `sin_cos`, `sqrt`,
//! quotients) is straight-line code before the loop, and the loop over the orders k ≥ 1 runs
//! each step's recurrence, its sums through [`super::kernels`].

use proc_macro2::{Ident, Span, TokenStream};
use quote::quote;

use super::tape::{ScalarOp, SeriesOp, Tape, Value};
use crate::codegen::f64_literal;
use crate::sym::SymbolId;

fn series(x: u32) -> Ident {
    Ident::new(&format!("__x{x}"), Span::call_site())
}

/// The path generated code reaches the kernels by: the facade re-exports precess-core.
fn kernel(name: &str) -> TokenStream {
    let f = Ident::new(name, Span::call_site());
    quote!(::precess::taylor::kernels::#f)
}

/// The emitted code of a tape, with its size for the price reports.
#[derive(Clone, Debug)]
pub struct TaylorTokens {
    /// The body of `fn coefficients(&self, ws: &mut Self::Workspace, t: f64, y: &[f64; N],
    /// order: usize, coeffs: &mut [[f64; N]])`: it reads those five names.
    pub body: TokenStream,
    /// The type of `TaylorSystem::Workspace` the body expects (`Vec<[f64; K + 1]>`).
    pub workspace: TokenStream,
    /// The number of series rows the workspace holds (the tape's series less those the code
    /// keeps in `let`s).
    pub series: usize,
}

impl TaylorTokens {
    /// The number of tokens of the body (a delimited group counts its two delimiters): the
    /// size the compiler parses, for the price reports.
    pub fn token_count(&self) -> usize {
        fn count(ts: TokenStream) -> usize {
            ts.into_iter()
                .map(|t| match t {
                    proc_macro2::TokenTree::Group(g) => 2 + count(g.stream()),
                    _ => 1,
                })
                .sum()
        }
        count(self.body.clone())
    }
}

impl Tape {
    /// The code [`Tape::to_tokens`] emits up to `max_order`, with every scalar symbol read
    /// as one field access: its size is the scene's (for the price reports).
    pub fn emitted(&self, max_order: usize) -> TaylorTokens {
        self.to_tokens(max_order, &mut |_| quote!(self.p))
    }

    /// Emits the coefficients' body up to the compile-time order bound `max_order`; `symbol`
    /// gives the Rust expression of each symbol read as a scalar (e.g. `self.m`).
    ///
    /// ```
    /// use precess_core::sym::Arena;
    /// use precess_core::taylor::Tape;
    /// let mut a = Arena::new();
    /// let x = a.coordinate("x");
    /// let rhs = a.mul(x, x); // x' = x²
    /// let tape = Tape::new(&a, &[x], None, &[rhs]).unwrap();
    /// let code = tape.to_tokens(20, &mut |_| quote::quote!(0.0));
    /// assert!(code.body.to_string().contains("20usize"));
    /// assert_eq!(code.series, 1); // x; x² is read once, at its own order: a `let`
    /// ```
    pub fn to_tokens(
        &self,
        max_order: usize,
        symbol: &mut dyn FnMut(SymbolId) -> TokenStream,
    ) -> TaylorTokens {
        let scalar_operand = |i: u32| -> TokenStream {
            match self.scalars.get(i as usize) {
                Some(ScalarOp::Const(c)) => f64_literal(*c),
                _ => {
                    let id = Ident::new(&format!("__s{i}"), Span::call_site());
                    quote!(#id)
                }
            }
        };
        let mut scalars = TokenStream::new();
        for (i, op) in self.scalars.iter().enumerate() {
            let s = scalar_operand;
            let rhs = match *op {
                ScalarOp::Const(_) => continue,
                ScalarOp::Symbol(sym) => symbol(sym),
                ScalarOp::Add(a, b) => binary(s(a), quote!(+), s(b)),
                ScalarOp::Sub(a, b) => binary(s(a), quote!(-), s(b)),
                ScalarOp::Mul(a, b) => binary(s(a), quote!(*), s(b)),
                ScalarOp::Div(a, b) => binary(s(a), quote!(/), s(b)),
                ScalarOp::Neg(a) => {
                    let a = s(a);
                    quote!(-#a)
                }
                ScalarOp::Sqrt(a) => method(s(a), "sqrt"),
                ScalarOp::Sin(a) => method(s(a), "sin"),
                ScalarOp::Cos(a) => method(s(a), "cos"),
            };
            let id = Ident::new(&format!("__s{i}"), Span::call_site());
            scalars.extend(quote!(let #id: f64 = #rhs;));
        }
        let local = self.local_series();
        let is_local = |x: u32| local.get(x as usize).copied().unwrap_or(false);
        // Only the series that are not `let`s get a row: fewer rows, a smaller workspace.
        let with_row: Vec<u32> = (0..self.series_count).filter(|&x| !is_local(x)).collect();
        let rows = with_row.len();
        let bindings = with_row.iter().map(|&x| series(x));
        let load = (0..self.dimension).map(|i| {
            let id = series(i as u32);
            quote!(#id[0] = y[#i];)
        });
        // A workspace of the same type may have served another system: the time's row is
        // the only one read beyond what this call writes, so it is written whole.
        let time = self.time.map(|ti| {
            let id = series(ti);
            quote!(*#id = [0.0f64; __K + 1]; #id[0] = t; #id[1] = 1.0;)
        });
        let first = self
            .steps
            .iter()
            .map(|st| order_zero(st.out, st.op, scalar_operand, &is_local));
        let steps = self
            .steps
            .iter()
            .map(|st| order_k(st.out, st.op, scalar_operand, &is_local));
        // f's order-k coefficient into the state's order k + 1: at order 0 as it is, at
        // order k ≥ 1 divided by k + 1 (`__inv`); a scalar output has order 0 only.
        let output = |order_zero: bool| {
            let f = self.outputs.iter().enumerate().map(move |(i, out)| {
                let state = series(i as u32);
                match (*out, order_zero) {
                    (Value::Series(x), true) => {
                        let v = pointwise(x, &is_local, quote!(0));
                        quote!(#state[1] = #v;)
                    }
                    (Value::Series(x), false) => {
                        let v = pointwise(x, &is_local, quote!(__k));
                        quote!(#state[__k + 1] = #v * __inv;)
                    }
                    (Value::Scalar(x), true) => {
                        let v = scalar_operand(x);
                        quote!(#state[1] = #v;)
                    }
                    (Value::Scalar(_), false) => quote!(#state[__k + 1] = 0.0;),
                }
            });
            quote!(#(#f)*)
        };
        let (outputs_zero, outputs_k) = (output(true), output(false));
        let next = |k: TokenStream| {
            let ids = (0..self.dimension).map(|i| {
                let id = series(i as u32);
                quote!(#id[#k + 1])
            });
            quote!([#(#ids),*])
        };
        let (next_zero, next_k) = (next(quote!(0)), next(quote!(__k)));
        let body = quote! {
            const __K: usize = #max_order;
            let ::core::option::Option::Some(__top) = coeffs.len().checked_sub(1) else {
                return;
            };
            let __n: usize = if order < __K { order } else { __K };
            let __n: usize = if __n < __top { __n } else { __top };
            if ws.len() != #rows {
                ws.clear();
                ws.resize(#rows, [0.0f64; __K + 1]);
            }
            let [#(#bindings),*] = &mut ws[..] else {
                return;
            };
            #scalars
            #(#load)*
            #time
            coeffs[0] = *y;
            if __n == 0 {
                return;
            }
            #(#first)*
            #outputs_zero
            coeffs[1] = #next_zero;
            for __k in 1..__n {
                #(#steps)*
                let __inv: f64 = 1.0 / ((__k + 1) as f64);
                #outputs_k
                coeffs[__k + 1] = #next_k;
            }
        };
        TaylorTokens {
            body,
            workspace: quote!(::std::vec::Vec<[f64; #max_order + 1]>),
            series: rows,
        }
    }
}

impl Tape {
    /// The series that need no row: made by a step whose recurrence does not read its own
    /// lower orders, and read once, at the current order only (by a sum, a scaling, the
    /// numerator of a quotient, a root's or a sine's argument, or an output). Such a
    /// series is a `let` at each order, e.g. the product in `−0.51 y₁ y₂`.
    fn local_series(&self) -> Vec<bool> {
        let n = self.series_count as usize;
        let mut reads = vec![0u32; n];
        let mut ranged = vec![false; n];
        let mut count = |x: u32, whole: bool| {
            if let Some(r) = reads.get_mut(x as usize) {
                *r += 1;
            }
            if whole && let Some(r) = ranged.get_mut(x as usize) {
                *r = true;
            }
        };
        for st in &self.steps {
            match st.op {
                SeriesOp::Add(a, b) | SeriesOp::Sub(a, b) => {
                    count(a, false);
                    count(b, false);
                }
                SeriesOp::AddScalar(a, _)
                | SeriesOp::SubScalar(a, _)
                | SeriesOp::ScalarSub(_, a)
                | SeriesOp::Neg(a)
                | SeriesOp::Scale(a, _)
                | SeriesOp::DivScalar(a, _)
                | SeriesOp::Sqrt(a)
                | SeriesOp::SinCos(a) => count(a, false),
                SeriesOp::Div(a, b) => {
                    count(a, false);
                    count(b, true);
                }
                SeriesOp::Mul(a, b) => {
                    count(a, true);
                    count(b, true);
                }
                SeriesOp::Square(a) | SeriesOp::ScalarDiv(_, a) => count(a, true),
            }
        }
        for out in &self.outputs {
            if let Value::Series(x) = *out {
                count(x, false);
            }
        }
        let mut local = vec![false; n];
        for st in &self.steps {
            let own_history = matches!(
                st.op,
                SeriesOp::Div(..)
                    | SeriesOp::ScalarDiv(..)
                    | SeriesOp::Sqrt(_)
                    | SeriesOp::SinCos(_)
            );
            let x = st.out as usize;
            if !own_history && reads.get(x) == Some(&1) && ranged.get(x) == Some(&false) {
                local[x] = true;
            }
        }
        local
    }
}

/// Series `x` at the current order `k`: its row's entry, or its `let` if it has no row.
fn pointwise(x: u32, is_local: &dyn Fn(u32) -> bool, k: TokenStream) -> TokenStream {
    if is_local(x) {
        let v = Ident::new(&format!("__v{x}"), Span::call_site());
        quote!(#v)
    } else {
        let id = series(x);
        quote!(#id[#k])
    }
}

/// Stores a step's value at the current order `k`: into its row, or as its `let`.
fn store(
    out: u32,
    is_local: &dyn Fn(u32) -> bool,
    k: TokenStream,
    value: TokenStream,
) -> TokenStream {
    if is_local(out) {
        let v = Ident::new(&format!("__v{out}"), Span::call_site());
        quote!(let #v: f64 = #value;)
    } else {
        let o = series(out);
        quote!(let __v: f64 = #value; #o[#k] = __v;)
    }
}

/// One step's value at order 0 (the values themselves).
fn order_zero(
    out: u32,
    op: SeriesOp,
    s: impl Fn(u32) -> TokenStream,
    is_local: &dyn Fn(u32) -> bool,
) -> TokenStream {
    let o = series(out);
    let x = |i: u32| pointwise(i, is_local, quote!(0));
    let value = match op {
        SeriesOp::Add(a, b) => binary(x(a), quote!(+), x(b)),
        SeriesOp::Sub(a, b) => binary(x(a), quote!(-), x(b)),
        SeriesOp::AddScalar(a, c) => binary(x(a), quote!(+), s(c)),
        SeriesOp::SubScalar(a, c) => binary(x(a), quote!(-), s(c)),
        SeriesOp::ScalarSub(c, a) => binary(s(c), quote!(-), x(a)),
        SeriesOp::Neg(a) => {
            let a = x(a);
            quote!(-#a)
        }
        SeriesOp::Scale(a, c) => binary(s(c), quote!(*), x(a)),
        SeriesOp::DivScalar(a, c) => binary(x(a), quote!(/), s(c)),
        SeriesOp::Mul(a, b) => binary(x(a), quote!(*), x(b)),
        SeriesOp::Square(a) => binary(x(a), quote!(*), x(a)),
        SeriesOp::Div(a, b) => binary(x(a), quote!(/), x(b)),
        SeriesOp::ScalarDiv(c, a) => binary(s(c), quote!(/), x(a)),
        SeriesOp::Sqrt(a) => method(x(a), "sqrt"),
        SeriesOp::SinCos(a) => {
            let (a, c) = (x(a), series(out + 1));
            return quote! {
                (#o[0], #c[0]) = f64::sin_cos(#a);
            };
        }
    };
    store(out, is_local, quote!(0), value)
}

/// One step's recurrence at the order `__k ≥ 1` (a `usize` in scope).
fn order_k(
    out: u32,
    op: SeriesOp,
    s: impl Fn(u32) -> TokenStream,
    is_local: &dyn Fn(u32) -> bool,
) -> TokenStream {
    let o = series(out);
    let x = series;
    // A pointwise read: the operand's row at k, or its `let`.
    let at = |i: u32| pointwise(i, is_local, quote!(__k));
    let (cauchy, square) = (kernel("cauchy"), kernel("square"));
    let value = match op {
        SeriesOp::Add(a, b) => binary(at(a), quote!(+), at(b)),
        SeriesOp::Sub(a, b) => binary(at(a), quote!(-), at(b)),
        SeriesOp::AddScalar(a, _) | SeriesOp::SubScalar(a, _) => at(a),
        SeriesOp::ScalarSub(_, a) | SeriesOp::Neg(a) => {
            let a = at(a);
            quote!(-#a)
        }
        SeriesOp::Scale(a, c) => binary(s(c), quote!(*), at(a)),
        SeriesOp::DivScalar(a, c) => binary(at(a), quote!(/), s(c)),
        SeriesOp::Mul(a, b) => {
            let (a, b) = (x(a), x(b));
            quote!(#cauchy(&#a[..=__k], &#b[..=__k]))
        }
        SeriesOp::Square(a) => {
            let a = x(a);
            quote!(#square(&#a[..=__k]))
        }
        SeriesOp::Div(a, b) => {
            let (a, b) = (at(a), x(b));
            quote!((#a - #cauchy(&#b[1..=__k], &#o[..__k])) / #b[0])
        }
        SeriesOp::ScalarDiv(_, a) => {
            let a = x(a);
            quote!(-#cauchy(&#a[1..=__k], &#o[..__k]) / #a[0])
        }
        SeriesOp::Sqrt(a) => {
            let a = at(a);
            quote!((#a - #square(&#o[1..__k])) / (2.0 * #o[0]))
        }
        SeriesOp::SinCos(a) => {
            let (a, c, d) = (at(a), series(out + 1), series(out + 2));
            return quote! {
                #d[__k] = (__k as f64) * #a;
                let __inv_k = 1.0 / (__k as f64);
                let __sv = #cauchy(&#d[1..=__k], &#c[..__k]) * __inv_k;
                let __cv = -#cauchy(&#d[1..=__k], &#o[..__k]) * __inv_k;
                #o[__k] = __sv;
                #c[__k] = __cv;
            };
        }
    };
    store(out, is_local, quote!(__k), value)
}

fn binary(a: TokenStream, op: TokenStream, b: TokenStream) -> TokenStream {
    quote!(#a #op #b)
}

fn method(a: TokenStream, name: &str) -> TokenStream {
    let f = Ident::new(name, Span::call_site());
    quote!(f64::#f(#a))
}
