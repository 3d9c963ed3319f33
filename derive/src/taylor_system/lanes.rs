//! `impl TaylorLanes<N, L>` of a `taylor_system!`: the same tape as its `impl TaylorSystem<N>`
//! emitted on `Lanes<L>` (precess-core's `Tape::to_lane_tokens`), each parameter read from
//! the lane's own system, for every `L` at once (a const generic).

use precess_core::codegen::Program;
use precess_core::sym::{Arena, ExprId, SymbolId};
use precess_core::taylor::Tape;
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

use crate::lang::private::Private;

/// The `impl<const __L: usize> TaylorLanes<N, __L>`, or nothing when the tape has no lane
/// form (a primitive function, or a tape too large: the system then steps in scalar only)
/// or the state is not a list of symbols (the scalar impl has reported that already).
/// `fields` pairs each parameter's expression with its field.
pub fn lane_impl(
    ident: &Ident,
    arena: &Arena,
    state: &[ExprId],
    fields: &[(ExprId, &Ident)],
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
    // Each parameter as the lanes of the systems' fields; the time is the tape's series.
    let lookup: Vec<(SymbolId, TokenStream)> = fields
        .iter()
        .filter_map(|&(e, field)| {
            let s = arena.as_symbol(e)?;
            Some((s, quote!(#p::Lanes::<__L>(systems.map(|__s| __s.#field)))))
        })
        .collect();
    let code = tape.to_lane_tokens(order, &mut |s| {
        lookup
            .iter()
            .find(|(k, _)| *k == s)
            .map(|(_, t)| t.clone())
            .unwrap_or_else(|| quote!(#p::Lanes::<__L>::splat(0.0)))
    });
    let Some(code) = code else {
        return TokenStream::new();
    };
    let (body, workspace) = (code.body, code.workspace);
    quote! {
        #[automatically_derived]
        #[allow(unused_variables, unused_mut, clippy::all, clippy::pedantic, clippy::nursery, unused_parens)]
        impl<const __L: usize> #p::TaylorLanes<#n, __L> for #ident {
            type LaneWorkspace = #workspace;

            fn lane_coefficients_into(
                systems: [&Self; __L],
                ws: &mut Self::LaneWorkspace,
                t: #p::Lanes<__L>,
                y: &[#p::Lanes<__L>; #n],
                order: usize,
                coeffs: &mut [[#p::Lanes<__L>; #n]],
            ) {
                #body
            }
        }
    }
}
