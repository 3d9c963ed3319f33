//! The `event Name = g;` statements of `taylor_system!`: each g lowered into the system's
//! arena and emitted as a type `Name<'s>(&'s System)` implementing
//! `precess_core::taylor::EventSeries`, its coefficients the compiled recurrences of g over
//! the state's series read from the step's jet (`Tape::to_event_tokens`, bit for bit the
//! interpreted `TaylorEvent` of the same expression), or, when g is a state variable, the
//! jet's column copied with no recurrence.

use precess_core::codegen::Program;
use precess_core::sym::{Arena, ExprId, SymbolId};
use precess_core::taylor::Tape;
use proc_macro2::TokenStream;
use quote::quote;
use syn::{Ident, ItemStruct};

use crate::lang::ctxt::Ctxt;
use crate::lang::private::Private;
use crate::lang::symbols::SymbolTokens;

/// The declaration of event `name`'s type (emitted after an error too, so that its uses
/// raise no errors of their own).
pub fn declaration(item: &ItemStruct, name: &Ident) -> TokenStream {
    let (vis, system) = (&item.vis, &item.ident);
    let doc = format!(
        "An event function of [`{system}`] declared by `event {name} = …;`, its Taylor coefficients compiled (`EventSeries`): pass it to `Run::taylor_event`. It reads the system's fields through the reference it holds."
    );
    quote! {
        #[doc = #doc]
        #[derive(Clone, Copy)]
        #vis struct #name<'s>(pub &'s #system);
    }
}

/// The type of event `name` with g = `g` and its `impl EventSeries<N>`: `state` the state
/// symbols, `fields` the parameters' symbols and field names, `order` the system's maximum
/// Taylor order (the rows of the workspace).
#[allow(clippy::too_many_arguments)]
pub fn expand(
    cx: &Ctxt,
    item: &ItemStruct,
    name: &Ident,
    arena: &Arena,
    state: &[ExprId],
    fields: &[(&Ident, ExprId)],
    g: ExprId,
    order: usize,
) -> TokenStream {
    let p = Private;
    let n = state.len();
    let declaration = declaration(item, name);
    let (workspace, body) = if let Some(i) = state.iter().position(|&s| s == g) {
        // g = yᵢ: the jet's column i itself.
        let body = quote! {
            #p::StateEvent::<#n>::column_into(#i, y, rows, out);
        };
        (quote!(()), body)
    } else {
        let Some(symbols) = state
            .iter()
            .map(|&e| arena.as_symbol(e))
            .collect::<Option<Vec<SymbolId>>>()
        else {
            cx.error_spanned_by(
                name,
                "internal error of the macro: the state is not a list of symbols; please report this",
            );
            return declaration;
        };
        let program = Program::lower(arena, &[g]);
        let time = arena.time_symbol().filter(|s| program.inputs().contains(s));
        let tape = Tape::from_program(&program, &symbols, time);
        let mut reads = SymbolTokens::default();
        for (field, e) in fields {
            reads.insert_expr(arena, *e, quote!(self.0.#field));
        }
        let code = tape.to_event_tokens(order, &mut |s| match reads.get(s) {
            Some(tokens) => tokens,
            None => {
                cx.error_spanned_by(
                    name,
                    format!(
                        "internal error of the macro: the event reads the symbol `{}`, which has no value; please report this",
                        arena.symbol(s).name
                    ),
                );
                quote!(0.0)
            }
        });
        let Some(code) = code else {
            cx.error_spanned_by(
                name,
                "internal error of the macro: an event's tape has one output; please report this",
            );
            return declaration;
        };
        (code.workspace, code.body)
    };
    quote! {
        #declaration

        #[automatically_derived]
        #[allow(unused_variables, unused_mut, clippy::all, clippy::pedantic, clippy::nursery, unused_parens)]
        impl<'s> #p::EventSeries<#n> for #name<'s> {
            type Workspace = #workspace;

            fn coefficients_into(
                &self,
                ws: &mut Self::Workspace,
                t: f64,
                y: &[f64; #n],
                rows: &[[f64; #n]],
                out: &mut [f64],
            ) {
                #body
            }
        }
    }
}
