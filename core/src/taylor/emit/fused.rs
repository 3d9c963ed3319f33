//! The interiors of an order's dot products, fused: every plain `dot_reversed` interior of
//! the jet at order k (the Cauchy products' Σⱼ₌₁ᵏ⁻¹ a_j b_{k−j}, the quotients' and the
//! sine–cosine pairs') has the same length k − 1, so they are summed in one loop over j
//! rather than one kernel call each.
//!
//! Why: callgrind on the Euler–Poisson heavy top at order 13 (eight products) counted 4 741
//! instructions a jet, 6.5 a term of the sums: each call set up its own short loop (slices,
//! the length test, the odd term, two exits per pass of a zip with a reversed iterator), and
//! at these orders a sum has 1–12 terms, so the set-up cost as much as the terms. One loop
//! pays its set-up once for all the sums and runs their chains side by side.
//!
//! The bits are the kernel's: each sum adds the same terms in the same order as
//! [`crate::taylor::kernels::dot_reversed`] — one accumulator, j ascending, below
//! [`LANES_FROM`](crate::taylor::kernels::LANES_FROM) terms; from there on, the even and odd j
//! in two accumulators, the odd last term after them, `(even + odd) + last` — so the emitted
//! code, the interpreter and hand-written systems agree bit for bit, and a lane (the same
//! loop on `Lanes<L>`) is its scalar run.

use proc_macro2::{Ident, Span, TokenStream};
use quote::quote;

use super::{Sums, interior_id, series};
use crate::taylor::tape::SeriesOp;

/// One interior Σⱼ₌₁ᵏ⁻¹ a_j b_{k−j}: the `let` that holds it and its two series.
pub(super) struct Dot {
    acc: Ident,
    a: Ident,
    b: Ident,
}

/// The interiors of step `out` that are plain dot products of two rows (as `interior`
/// would emit through the `dot_reversed` kernel), in the order `interior` emits them; empty
/// for every other step.
pub(super) fn dots(out: u32, op: SeriesOp, split: bool) -> Vec<Dot> {
    let dot = |acc: Ident, a: u32, b: u32| Dot {
        acc,
        a: series(a),
        b: series(b),
    };
    match op {
        SeriesOp::Mul(a, b) if split => vec![dot(interior_id(out, ""), a, b)],
        SeriesOp::Div(_, b) | SeriesOp::ScalarDiv(_, b) => {
            vec![dot(interior_id(out, ""), b, out)]
        }
        SeriesOp::SinCos(_) => vec![
            dot(interior_id(out, "s"), out + 2, out + 1),
            dot(interior_id(out, "c"), out + 2, out),
        ],
        _ => Vec::new(),
    }
}

/// The code that computes `dots` at order `__k`: loops of at most `group` sums each. In
/// the lanes the loops are taken only where [`fuse_sums`](crate::taylor::batch::kernels::fuse_sums)
/// says a lane value fits the registers, and each sum is its kernel call otherwise.
pub(super) fn block(dots: &[Dot], sums: Sums, group: usize) -> TokenStream {
    let num = sums.num();
    let zero = sums.value(quote!(0.0f64));
    let accs = dots.iter().map(|d| &d.acc);
    let mut loops = TokenStream::new();
    for (g, chunk) in dots.chunks(group.max(1)).enumerate() {
        loops.extend(chunk_loops(g, chunk, &num, &zero));
    }
    // Declared here, assigned once on every path below.
    let declared = quote!(#(let #accs: #num;)*);
    if !sums.lanes {
        return quote!(#declared #loops);
    }
    let dot = sums.kernel("dot_reversed");
    let calls = dots
        .iter()
        .map(|Dot { acc, a, b }| quote!(#acc = #dot(&#a[1..__k], &#b[1..__k]);));
    quote! {
        #declared
        if ::precess::__private::lane_kernels::fuse_sums(__L) {
            #loops
        } else {
            #(#calls)*
        }
    }
}

/// One loop's sums, into their `let`s (declared, not yet assigned).
fn chunk_loops(g: usize, chunk: &[Dot], num: &TokenStream, zero: &TokenStream) -> TokenStream {
    let tag = |t: &str, n: usize| Ident::new(&format!("__{t}{g}_{n}"), Span::call_site());
    let evens: Vec<Ident> = (0..chunk.len()).map(|n| tag("even", n)).collect();
    let odds: Vec<Ident> = (0..chunk.len()).map(|n| tag("odd", n)).collect();
    let accs = chunk.iter().map(|d| &d.acc);
    let short = chunk
        .iter()
        .zip(&evens)
        .map(|(Dot { a, b, .. }, e)| quote!(#e += #a[__j] * #b[__k - __j];));
    let paired = chunk
        .iter()
        .zip(&evens)
        .zip(&odds)
        .map(|((Dot { a, b, .. }, e), o)| {
            quote! {
                #e += #a[__j] * #b[__k - __j];
                #o += #a[__j + 1] * #b[__k - __j - 1];
            }
        });
    let close = chunk
        .iter()
        .zip(&evens)
        .zip(&odds)
        .map(|((Dot { acc, a, b }, e), o)| {
            quote! {
                #acc = (#e + #o) + if __odd { #a[__k - 1] * #b[1] } else { #zero };
            }
        });
    quote! {
        if __k - 1 < ::precess::__private::kernels::LANES_FROM {
            #(let mut #evens: #num = #zero;)*
            for __j in 1..__k {
                #(#short)*
            }
            #(#accs = #evens;)*
        } else {
            #(let mut #evens: #num = #zero;)*
            #(let mut #odds: #num = #zero;)*
            for __p in 0..(__k - 1) / 2 {
                let __j = 1 + 2 * __p;
                #(#paired)*
            }
            let __odd = (__k - 1) % 2 == 1;
            #(#close)*
        }
    }
}
