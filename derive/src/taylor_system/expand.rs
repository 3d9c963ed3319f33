//! Expansion of `taylor_system!`: the checked equations lowered into the arena, emitted as
//! the struct with `impl System<N>` (the right-hand side as straight-line code) and
//! `impl TaylorSystem<N>` (the recurrences, by `lang::taylor`, as for `taylor = K` on the
//! derives), and `impl Export` (the right-hand side and its Jacobian as C and Python).

use precess_core::sym::{Arena, ExprId};
use proc_macro2::TokenStream;
use quote::{ToTokens, quote};
use syn::LitStr;

use super::attr::SystemInput;
use super::check::CheckedSystem;
use super::values::{Lowerer, Names};
use crate::lang::ctxt::Ctxt;
use crate::lang::private::Private;
use crate::lang::symbols::{Lowering, SymbolTokens};

/// The whole macro: the struct and its impls, or the struct and every error.
pub fn expand(input: TokenStream) -> TokenStream {
    let input: SystemInput = match syn::parse2(input) {
        Ok(input) => input,
        Err(e) => return e.to_compile_error(),
    };
    let cx = Ctxt::new();
    let impls = super::check::check(&cx, &input).and_then(|c| impls(&cx, &input, &c));
    let item = input.item.to_token_stream();
    let expanded = impls.map(|impls| quote!(#item #impls));
    // After an error the struct and the events' types are still emitted, so their uses
    // raise no errors of their own.
    cx.finish(&input.item.ident, expanded, || {
        // Each name once, and none the struct's (the refused ones, reported above).
        let mut names: Vec<&syn::Ident> = Vec::new();
        for s in &input.statements {
            if let super::attr::Statement::Event { name, .. } = s
                && *name != input.item.ident
                && !names.contains(&name)
            {
                names.push(name);
            }
        }
        let events = names
            .into_iter()
            .map(|name| super::events::declaration(&input.item, name));
        quote!(#item #(#events)*)
    })
}

/// `impl System<N>`, `impl TaylorSystem<N>` and the names of the state, or `None` after
/// recording why a right-hand side could not be read.
fn impls(cx: &Ctxt, input: &SystemInput, checked: &CheckedSystem) -> Option<TokenStream> {
    let p = Private;
    let ident = &input.item.ident;
    let mut arena = Arena::new();
    let state: Vec<ExprId> = checked
        .state
        .iter()
        .map(|s| arena.coordinate(&s.to_string()))
        .collect();
    let fields: Vec<ExprId> = checked
        .fields
        .iter()
        .map(|f| arena.parameter(&f.to_string()))
        .collect();
    let mut lowerer = Lowerer {
        cx,
        arena: &mut arena,
        names: Names {
            state: checked
                .state
                .iter()
                .map(|&s| s.clone())
                .zip(state.clone())
                .collect(),
            fields: checked
                .fields
                .iter()
                .map(|&f| f.clone())
                .zip(fields.clone())
                .collect(),
            time: None,
        },
    };
    let rhs: Vec<Option<ExprId>> = checked.equations.iter().map(|e| lowerer.expr(e)).collect();
    let rhs: Vec<ExprId> = rhs.into_iter().collect::<Option<_>>()?;
    let events: Vec<Option<ExprId>> = checked
        .events
        .iter()
        .map(|(_, g)| lowerer.expr(g))
        .collect();
    let events: Vec<ExprId> = events.into_iter().collect::<Option<_>>()?;
    let time = lowerer.names.time;
    let mut symbols = SymbolTokens::default();
    for (field, &e) in checked.fields.iter().zip(&fields) {
        symbols.insert_expr(&arena, e, quote!(self.#field));
    }
    // The time is the `t` argument of `System::rhs`; in the recurrences it is the tape's time
    // series (t₀, 1, 0, …), which `crate::lang::taylor::expand` makes of the arena's time symbol.
    if let Some(time) = time {
        symbols.insert_expr(&arena, time, quote!(t));
    }
    let n = state.len();
    let reads: Vec<(ExprId, TokenStream)> = (0..n)
        .zip(&state)
        .map(|(i, &s)| (s, quote!(y[#i])))
        .collect();
    let emitted = Lowering::new(cx, ident, symbols.clone()).lower_reading(&arena, &rhs, &reads);
    let (lets, outputs) = (emitted.lets, emitted.outputs);
    let taylor = crate::lang::taylor::expand(
        cx,
        ident,
        &arena,
        &symbols,
        &state,
        &rhs,
        TokenStream::new(),
        checked.order,
        None,
    );
    let taylor = crate::lang::export::system(ident, &mut arena, &state, &rhs, taylor);
    let field_symbols: Vec<(&syn::Ident, ExprId)> =
        checked.fields.iter().copied().zip(fields.clone()).collect();
    let events = checked.events.iter().zip(&events).map(|((name, _), &g)| {
        super::events::expand(
            cx,
            &input.item,
            name,
            &arena,
            &state,
            &field_symbols,
            g,
            checked.order,
        )
    });
    let events: TokenStream = events.collect();
    let names = checked
        .state
        .iter()
        .map(|s| LitStr::new(&s.to_string(), s.span()));
    Some(quote! {
        #[automatically_derived]
        impl #ident {
            /// The state variables, in the order of the state vector.
            pub const STATE: [&'static str; #n] = [#(#names),*];
        }

        #[automatically_derived]
        #[allow(unused_variables, clippy::all, clippy::pedantic, clippy::nursery, unused_parens)]
        impl #p::System<#n> for #ident {
            #[inline]
            fn rhs(&self, t: f64, y: &[f64; #n], dydt: &mut [f64; #n]) {
                #lets
                *dydt = [#(#outputs),*];
            }
        }

        #taylor

        #events
    })
}
