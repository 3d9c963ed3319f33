//! The code of one step of a [`Tape`](crate::taylor::tape::Tape) at order 0 and at order
//! `__k ≥ 1`, in the names of [`super`]'s emitter: every piece reads the same layout of the
//! series, the same way of summing, and the same scalar operands, which [`StepCode`] holds.

use proc_macro2::TokenStream;
use quote::quote;

use super::{Layout, Sums, binary, fused, interior_id, method, series, value};
use crate::codegen::f64_literal;
use crate::sym::Func;
use crate::sym::functions::{SeriesCode, SeriesNames};
use crate::taylor::tape::SeriesOp;

/// What every step's code reads: where the series live, how the sums are made, and the
/// tokens of scalar operand `i` (a literal or its `let`).
pub(super) struct StepCode<'a, F> {
    pub(super) layout: &'a Layout,
    pub(super) sums: Sums,
    pub(super) scalar: F,
}

impl<F: Fn(u32) -> TokenStream> StepCode<'_, F> {
    /// Stores a step's value at the current order `k`: as its `let`, and into its row if it
    /// has one.
    fn store(&self, out: u32, k: TokenStream, value_expr: TokenStream) -> TokenStream {
        let (layout, sums) = (self.layout, self.sums);
        let (v, num) = (value(out), sums.num());
        if layout.is_local(out) {
            quote!(let #v: #num = #value_expr;)
        } else {
            let o = series(out);
            quote!(let #v: #num = #value_expr; #o[#k] = #v;)
        }
    }

    /// One step's value at order 0 (the values themselves).
    pub(super) fn order_zero(&self, out: u32, op: SeriesOp) -> TokenStream {
        let (layout, sums, s) = (self.layout, self.sums, &self.scalar);
        let x = |i: u32| layout.current(i, quote!(0));
        let value_expr = match op {
            SeriesOp::Func(f, a) => return self.func_code(out, f, a).zero,
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
            SeriesOp::Sqrt(a) => method(x(a), "sqrt", sums),
            SeriesOp::Powf(a, r) => {
                let (a, r, num) = (x(a), f64_literal(r), sums.num());
                quote!(<#num>::powf(#a, #r))
            }
            SeriesOp::SinCos(a) => {
                let (o, c) = (series(out), series(out + 1));
                let (vs, vc) = (value(out), value(out + 1));
                let (a, num) = (x(a), sums.num());
                return quote! {
                    let (#vs, #vc): (#num, #num) = <#num>::sin_cos(#a);
                    #o[0] = #vs;
                    #c[0] = #vc;
                };
            }
        };
        self.store(out, quote!(0), value_expr)
    }

    /// The first phase of one step at the order `__k ≥ 1`: the part of its sum that reads
    /// orders below `__k` only, into `let`s (nothing for a step without a sum).
    pub(super) fn interior(&self, out: u32, op: SeriesOp) -> TokenStream {
        let sums = self.sums;
        let split = sums.split;
        if sums.fused > 0 && !fused::dots(out, op, split).is_empty() {
            // Summed with the order's other dot products in `fused::block`.
            return TokenStream::new();
        }
        let (dot, square_interior, square) = (
            sums.kernel("dot_reversed"),
            sums.kernel("square_interior"),
            sums.kernel("square"),
        );
        let o = series(out);
        let i = interior_id(out, "");
        let num = sums.num();
        match op {
            // Σⱼ₌₁ᵏ⁻¹ a_j b_{k−j}: the Cauchy product less a_0 b_k + a_k b_0.
            SeriesOp::Mul(a, b) if split => {
                let (a, b) = (series(a), series(b));
                quote!(let #i: #num = #dot(&#a[1..__k], &#b[1..__k]);)
            }
            SeriesOp::Square(a) => {
                let a = series(a);
                quote!(let #i: #num = #square_interior(&#a[1..__k]);)
            }
            // Σⱼ₌₁ᵏ⁻¹ b_j c_{k−j}: the quotient's sum less b_k c_0.
            SeriesOp::Div(_, b) | SeriesOp::ScalarDiv(_, b) => {
                let b = series(b);
                quote!(let #i: #num = #dot(&#b[1..__k], &#o[1..__k]);)
            }
            // The root's whole sum Σⱼ₌₁ᵏ⁻¹ c_j c_{k−j} reads lower orders only.
            SeriesOp::Sqrt(_) => quote!(let #i: #num = #square(&#o[1..__k]);),
            // Σⱼ₌₁ᵏ⁻¹ (r(k − j) − j) a_{k−j} c_j: the real power's sum less r k a_k c_0.
            SeriesOp::Powf(a, r) => {
                let (a, r, power) = (series(a), f64_literal(r), sums.kernel("power_interior"));
                quote!(let #i: #num = #power(&#a[1..__k], &#o[1..__k], #r);)
            }
            // Σⱼ₌₁ᵏ⁻¹ d_j C_{k−j} and Σⱼ₌₁ᵏ⁻¹ d_j S_{k−j}, less d_k C_0 and d_k S_0.
            SeriesOp::Func(f, a) => self.func_code(out, f, a).interior,
            SeriesOp::SinCos(_) => {
                let (c, d) = (series(out + 1), series(out + 2));
                let (is, ic) = (interior_id(out, "s"), interior_id(out, "c"));
                quote! {
                    let #is: #num = #dot(&#d[1..__k], &#c[1..__k]);
                    let #ic: #num = #dot(&#d[1..__k], &#o[1..__k]);
                }
            }
            _ => TokenStream::new(),
        }
    }

    /// The second phase of one step at the order `__k ≥ 1` (a `usize` in scope): its value,
    /// from its interior (phase one) and the terms that read order `__k`. The sums round as
    /// the interpreter's ([`super::kernels::cauchy`], [`super::kernels::square`]) do, so both
    /// agree bit for bit, except the products of a tape too large to split them (summed left
    /// to right, [`Tape::split_products`]), which agree to rounding.
    pub(super) fn order_k(&self, out: u32, op: SeriesOp) -> TokenStream {
        let (layout, sums, s) = (self.layout, self.sums, &self.scalar);
        let split = sums.split;
        let o = series(out);
        let i = interior_id(out, "");
        // A read at the current order: the operand's `let`, or its row for the state and time.
        let at = |x: u32| layout.current(x, quote!(__k));
        let value_expr = match op {
            SeriesOp::Func(f, a) => return self.func_code(out, f, a).order_k,
            SeriesOp::Add(a, b) => binary(at(a), quote!(+), at(b)),
            SeriesOp::Sub(a, b) => binary(at(a), quote!(-), at(b)),
            SeriesOp::AddScalar(a, _) | SeriesOp::SubScalar(a, _) => at(a),
            SeriesOp::ScalarSub(_, a) | SeriesOp::Neg(a) => {
                let a = at(a);
                quote!(-#a)
            }
            SeriesOp::Scale(a, c) => binary(s(c), quote!(*), at(a)),
            SeriesOp::DivScalar(a, c) => binary(at(a), quote!(/), s(c)),
            SeriesOp::Mul(a, b) if split => {
                let (ak, bk, a, b) = (at(a), at(b), series(a), series(b));
                quote!(#i + (#a[0] * #bk + #ak * #b[0]))
            }
            SeriesOp::Mul(a, b) => {
                let (a, b, dot) = (series(a), series(b), sums.kernel("dot_reversed"));
                quote!(#dot(&#a[..=__k], &#b[..=__k]))
            }
            SeriesOp::Square(a) => {
                let (ak, a) = (at(a), series(a));
                quote!(#i + 2.0 * #a[0] * #ak)
            }
            SeriesOp::Div(a, b) => {
                let (ak, bk, b) = (at(a), at(b), series(b));
                quote!((#ak - (#i + #bk * #o[0])) / #b[0])
            }
            SeriesOp::ScalarDiv(_, a) => {
                let (ak, a) = (at(a), series(a));
                quote!(-(#i + #ak * #o[0]) / #a[0])
            }
            SeriesOp::Sqrt(a) => {
                let a = at(a);
                quote!((#a - #i) / (2.0 * #o[0]))
            }
            SeriesOp::Powf(a, r) => {
                let (ak, a, r) = (at(a), series(a), f64_literal(r));
                quote!((#i + #r * (__k as f64) * #ak * #o[0]) / ((__k as f64) * #a[0]))
            }
            SeriesOp::SinCos(a) => {
                let (a, c, d) = (at(a), series(out + 1), series(out + 2));
                let (vs, vc) = (value(out), value(out + 1));
                let (is, ic) = (interior_id(out, "s"), interior_id(out, "c"));
                let num = sums.num();
                return quote! {
                    let __dk: #num = (__k as f64) * #a;
                    #d[__k] = __dk;
                    let __inv_k: f64 = 1.0 / (__k as f64);
                    let #vs: #num = (#is + __dk * #c[0]) * __inv_k;
                    let #vc: #num = -(#ic + __dk * #o[0]) * __inv_k;
                    #o[__k] = #vs;
                    #c[__k] = #vc;
                };
            }
        };
        self.store(out, quote!(__k), value_expr)
    }

    /// The emitted code of a primitive's step `out = f(a)`, by the primitive
    /// ([`crate::sym::functions`]), with the names of this emitter.
    fn func_code(&self, out: u32, f: Func, a: u32) -> SeriesCode {
        let (layout, sums) = (self.layout, self.sums);
        let names = SeriesNames {
            out: series(out),
            value: value(out),
            companions: (1..=f.primitive().companions())
                .map(|j| series(out + j))
                .collect(),
            arg_zero: layout.current(a, quote!(0)),
            arg_k: layout.current(a, quote!(__k)),
            interior: interior_id(out, ""),
            dot: sums.kernel("dot_reversed"),
        };
        f.primitive().series_code(&names)
    }
}
