//! `impl TaylorLanes<N, L>` of every Taylor system the macros emit (`taylor_system!` and each
//! scene's `taylor = K`): the same tape as its `impl TaylorSystem<N>` emitted on `Lanes<L>`
//! (precess-core's `Tape::to_lane_tokens`), for every `L` at once (a const generic).
//!
//! The parameters the recurrences read are computed per lane by a hidden method holding the
//! scalar impl's prelude and symbol reads unchanged, so a lane reads the bits its scalar run
//! reads, whatever the scene derives from its fields (`m g l / I₁`, a frame's products).

use precess_core::codegen::Program;
use precess_core::sym::{Arena, ExprId, SymbolId};
use precess_core::taylor::Tape;
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

use crate::lang::private::Private;
use crate::lang::symbols::SymbolTokens;

/// The `impl<const __L: usize> TaylorLanes<N, __L>` with its hidden
/// `__precess_lane_symbols` method, or nothing when the tape has no lane form (a primitive
/// function, or a tape too large: the system then steps in scalar only), the state is not a
/// list of symbols, or a symbol has no value (the scalar impl has reported those already).
///
/// `symbols` and `prelude` are those of the scalar impl: the method runs `prelude` on
/// `&self` (with the lane's `t` and `y`, which a prelude may read) and returns every symbol
/// the tape reads, in the tape's order.
pub fn lane_impl(
    ident: &Ident,
    arena: &Arena,
    symbols: &SymbolTokens,
    prelude: &TokenStream,
    state: &[ExprId],
    rhs: &[ExprId],
    order: usize,
) -> TokenStream {
    let p = Private;
    let n = state.len();
    let state: Option<Vec<SymbolId>> = state.iter().map(|&e| arena.as_symbol(e)).collect();
    let Some(state) = state.filter(|s| s.len() == rhs.len()) else {
        return TokenStream::new();
    };
    let program = Program::lower(arena, rhs);
    let time = arena.time_symbol().filter(|s| program.inputs().contains(s));
    let tape = Tape::from_program(&program, &state, time);
    // The symbols in the order the tape asks for them; symbol i is entry i of each lane's
    // array.
    let mut read: Vec<SymbolId> = Vec::new();
    let code = tape.to_lane_tokens(order, &mut |s| {
        let i = read.iter().position(|&k| k == s).unwrap_or_else(|| {
            read.push(s);
            read.len() - 1
        });
        quote!(#p::Lanes::<__L>(::core::array::from_fn(|__l| __symbols[__l][#i])))
    });
    let Some(code) = code else {
        return TokenStream::new();
    };
    let reads: Option<Vec<TokenStream>> = read.iter().map(|&s| symbols.get(s)).collect();
    let Some(reads) = reads else {
        return TokenStream::new();
    };
    let m = reads.len();
    let (body, workspace) = (code.body, code.workspace);
    quote! {
        #[automatically_derived]
        #[allow(unused_variables, unused_mut, clippy::all, clippy::pedantic, clippy::nursery, unused_parens)]
        impl #ident {
            /// The symbols the lanes' recurrences read, as the scalar recurrences read them.
            #[doc(hidden)]
            #[inline(always)]
            fn __precess_lane_symbols(&self, t: f64, y: &[f64; #n]) -> [f64; #m] {
                #prelude
                [#(#reads),*]
            }
        }

        #[automatically_derived]
        #[allow(unused_variables, unused_mut, clippy::all, clippy::pedantic, clippy::nursery, unused_parens)]
        impl<const __L: usize> #p::TaylorLanes<#n, __L> for #ident {
            type LaneWorkspace = #workspace;

            // Inlined into the batch's stepping, which is compiled once per instruction set
            // and chosen at run time (`BatchTaylor::advance_until`): out of line, the jets
            // would be compiled for the target's baseline alone.
            #[inline(always)]
            fn lane_coefficients_into(
                systems: [&Self; __L],
                ws: &mut Self::LaneWorkspace,
                t: #p::Lanes<__L>,
                y: &[#p::Lanes<__L>; #n],
                order: usize,
                coeffs: &mut [[#p::Lanes<__L>; #n]],
            ) {
                let __symbols: [[f64; #m]; __L] = ::core::array::from_fn(|__l| {
                    let __y: [f64; #n] = ::core::array::from_fn(|__i| y[__i].0[__l]);
                    systems[__l].__precess_lane_symbols(t.0[__l], &__y)
                });
                #body
            }
        }
    }
}
