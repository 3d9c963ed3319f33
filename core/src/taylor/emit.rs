//! Emission of a [`Tape`] as Rust: the body of [`super::TaylorSystem::coefficients`]
//! specialised to one right-hand side, which the derive macros splice into
//! `impl TaylorSystem<N>` for a scene that asks (`taylor = K`).
//!
//! The code has one `[f64; K + 1]` array per series on the stack (`K` a constant), the
//! scalars as `let`s computed once (literals inlined, so the compiler folds them), and one
//! loop over the orders whose body runs every step's recurrence; the sums of the Cauchy
//! products are loops over slices of those arrays.

use proc_macro2::{Ident, Span, TokenStream};
use quote::quote;

use super::tape::{ScalarOp, SeriesOp, Tape, Value};
use crate::codegen::f64_literal;
use crate::sym::SymbolId;

fn series(x: u32) -> Ident {
    Ident::new(&format!("__x{x}"), Span::call_site())
}

/// The emitted code of a tape, with its size for the price reports.
#[derive(Clone, Debug)]
pub struct TaylorTokens {
    /// The body of `fn coefficients(&self, t: f64, y: &[f64; N], order: usize, coeffs:
    /// &mut [[f64; N]])`: it reads those four names.
    pub body: TokenStream,
    /// The number of series arrays the body keeps on the stack.
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
    /// let code = tape.to_tokens(20, &mut |_| quote::quote!(0.0)).body.to_string();
    /// assert!(code.contains("20usize"));
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
        let arrays = (0..self.series_count).map(|x| {
            let id = series(x);
            quote!(let mut #id = [0.0f64; __K + 1];)
        });
        let load = (0..self.dimension).map(|i| {
            let id = series(i as u32);
            quote!(#id[0] = y[#i];)
        });
        let time = self.time.map(|ti| {
            let id = series(ti);
            quote!(#id[0] = t; #id[1] = 1.0;)
        });
        let steps = self
            .steps
            .iter()
            .map(|st| step_tokens(st.out, st.op, scalar_operand));
        let outputs = self.outputs.iter().enumerate().map(|(i, out)| {
            let state = series(i as u32);
            let f = match *out {
                Value::Series(x) => {
                    let id = series(x);
                    quote!(#id[__k])
                }
                Value::Scalar(x) => {
                    let v = scalar_operand(x);
                    quote!(if __k == 0 { #v } else { 0.0 })
                }
            };
            quote!(#state[__k + 1] = #f * __inv;)
        });
        let next = (0..self.dimension).map(|i| {
            let id = series(i as u32);
            quote!(#id[__k + 1])
        });
        let body = quote! {
            const __K: usize = #max_order;
            let ::core::option::Option::Some(__top) = coeffs.len().checked_sub(1) else {
                return;
            };
            let __n: usize = if order < __K { order } else { __K };
            let __n: usize = if __n < __top { __n } else { __top };
            #scalars
            #(#arrays)*
            #(#load)*
            #time
            coeffs[0] = *y;
            for __k in 0..__n {
                #(#steps)*
                let __inv: f64 = 1.0 / ((__k + 1) as f64);
                #(#outputs)*
                coeffs[__k + 1] = [#(#next),*];
            }
        };
        TaylorTokens {
            body,
            series: self.series_count as usize,
        }
    }
}

/// One step's recurrence at the order `__k` (a `usize` in scope).
fn step_tokens(out: u32, op: SeriesOp, s: impl Fn(u32) -> TokenStream) -> TokenStream {
    let o = series(out);
    let x = series;
    let value = match op {
        SeriesOp::Add(a, b) => {
            let (a, b) = (x(a), x(b));
            quote!(#a[__k] + #b[__k])
        }
        SeriesOp::Sub(a, b) => {
            let (a, b) = (x(a), x(b));
            quote!(#a[__k] - #b[__k])
        }
        SeriesOp::AddScalar(a, c) => {
            let (a, c) = (x(a), s(c));
            quote!(if __k == 0 { #a[0] + #c } else { #a[__k] })
        }
        SeriesOp::SubScalar(a, c) => {
            let (a, c) = (x(a), s(c));
            quote!(if __k == 0 { #a[0] - #c } else { #a[__k] })
        }
        SeriesOp::ScalarSub(c, a) => {
            let (a, c) = (x(a), s(c));
            quote!(if __k == 0 { #c - #a[0] } else { -#a[__k] })
        }
        SeriesOp::Neg(a) => {
            let a = x(a);
            quote!(-#a[__k])
        }
        SeriesOp::Scale(a, c) => {
            let (a, c) = (x(a), s(c));
            quote!(#c * #a[__k])
        }
        SeriesOp::DivScalar(a, c) => {
            let (a, c) = (x(a), s(c));
            quote!(#a[__k] / #c)
        }
        SeriesOp::Mul(a, b) => {
            let (a, b) = (x(a), x(b));
            quote!({
                let mut __acc = 0.0f64;
                for __j in 0..=__k { __acc += #a[__j] * #b[__k - __j]; }
                __acc
            })
        }
        SeriesOp::Square(a) => {
            let a = x(a);
            quote!({
                let mut __acc = 0.0f64;
                for __j in 0..(__k + 1) / 2 { __acc += #a[__j] * #a[__k - __j]; }
                __acc *= 2.0;
                if __k % 2 == 0 { __acc += #a[__k / 2] * #a[__k / 2]; }
                __acc
            })
        }
        SeriesOp::Div(a, b) => {
            let (a, b) = (x(a), x(b));
            quote!({
                let mut __acc = #a[__k];
                for __j in 1..=__k { __acc -= #b[__j] * #o[__k - __j]; }
                __acc / #b[0]
            })
        }
        SeriesOp::ScalarDiv(c, a) => {
            let (a, c) = (x(a), s(c));
            quote!(if __k == 0 { #c / #a[0] } else {
                let mut __acc = 0.0f64;
                for __j in 1..=__k { __acc -= #a[__j] * #o[__k - __j]; }
                __acc / #a[0]
            })
        }
        SeriesOp::Sqrt(a) => {
            let a = x(a);
            quote!(if __k == 0 { f64::sqrt(#a[0]) } else {
                let mut __acc = 0.0f64;
                for __j in 1..(__k + 1) / 2 { __acc += #o[__j] * #o[__k - __j]; }
                __acc *= 2.0;
                if __k % 2 == 0 { __acc += #o[__k / 2] * #o[__k / 2]; }
                (#a[__k] - __acc) / (2.0 * #o[0])
            })
        }
        SeriesOp::SinCos(a) => {
            let (a, c) = (x(a), series(out + 1));
            return quote! {
                if __k == 0 {
                    let (__sv, __cv) = f64::sin_cos(#a[0]);
                    #o[0] = __sv;
                    #c[0] = __cv;
                } else {
                    let (mut __ss, mut __cc) = (0.0f64, 0.0f64);
                    for __j in 1..=__k {
                        let __ja = (__j as f64) * #a[__j];
                        __ss += __ja * #c[__k - __j];
                        __cc += __ja * #o[__k - __j];
                    }
                    let __inv_k = 1.0 / (__k as f64);
                    #o[__k] = __ss * __inv_k;
                    #c[__k] = -__cc * __inv_k;
                }
            };
        }
    };
    quote!(#o[__k] = #value;)
}

fn binary(a: TokenStream, op: TokenStream, b: TokenStream) -> TokenStream {
    quote!(#a #op #b)
}

fn method(a: TokenStream, name: &str) -> TokenStream {
    let f = Ident::new(name, Span::call_site());
    quote!(f64::#f(#a))
}
