//! The `taylor = K` key, in one place for every attribute and macro that takes it
//! (`#[rigid]`, `#[top]`, `#[free]`, `#[mechanism]`, `taylor_system!`): found among the
//! attribute's settings ([`TaylorKey::find`], a repeat an error), its order checked
//! ([`TaylorKey::order`]), and the `impl TaylorSystem<N>` emitted from the scene's right-hand
//! side through precess-core's Taylor tape (`precess_core::taylor::Tape::to_tokens`), so the
//! generated and the interpreted recurrences are one decomposition ([`expand`]), with its
//! `impl TaylorLanes<N, L>` for the batch lanes beside it (`taylor_system/lanes.rs`). Scenes
//! without the key emit nothing here.

use precess_core::codegen::Program;
use precess_core::sym::{Arena, ExprId, SymbolId};
use precess_core::taylor::{MAX_TAYLOR_ORDER, Tape};
use proc_macro2::TokenStream;
use quote::quote;
use syn::{Expr, ExprLit, Ident, Lit};

use super::ctxt::Ctxt;
use super::keys;
use super::private::Private;
use super::symbols::SymbolTokens;

/// The value of the `taylor = K` key of one attribute, if it has one.
pub struct TaylorKey<'a> {
    value: Option<&'a Expr>,
}

impl<'a> TaylorKey<'a> {
    /// The first `taylor = K` among `settings` (`(key, value)` pairs); each repeat is an error
    /// on its key, `in_what` naming the attribute (`` `#[free]` ``). The attribute's own
    /// check passes over the key.
    pub fn find(
        cx: &Ctxt,
        settings: impl IntoIterator<Item = (&'a Ident, &'a Expr)>,
        in_what: &str,
    ) -> TaylorKey<'a> {
        let mut value = None;
        for (key, v) in settings {
            if key != keys::TAYLOR {
                continue;
            }
            // One order: two would leave the generated recurrences ambiguous.
            if value.is_some() {
                cx.error_spanned_by(key, format!("duplicate key `{key}` in {in_what}"));
            } else {
                value = Some(v);
            }
        }
        TaylorKey { value }
    }

    /// True if the attribute has the key.
    pub fn is_given(&self) -> bool {
        self.value.is_some()
    }

    /// The order asked for, checked as [`check`] does; `None` without the key or after
    /// recording its error.
    pub fn order(&self, cx: &Ctxt, user_fns: &[(&str, bool)]) -> Option<usize> {
        check(cx, self.value?, user_fns)
    }
}

/// The maximum order of `taylor = K`: an integer literal in `2 ..= MAX_TAYLOR_ORDER` (the
/// integrator's step needs two orders to estimate its size, so order 1 could never run), and no
/// user function among `user_fns` (`(key, declared)`): a function's value has no Taylor
/// coefficients the recurrences could know. `None` after recording the error on `value`.
fn check(cx: &Ctxt, value: &Expr, user_fns: &[(&str, bool)]) -> Option<usize> {
    let order = match value {
        Expr::Lit(ExprLit {
            lit: Lit::Int(i), ..
        }) => i.base10_parse::<usize>().ok(),
        _ => None,
    };
    let Some(order) = order.filter(|k| (2..=MAX_TAYLOR_ORDER).contains(k)) else {
        cx.error_spanned_by(
            value,
            format!(
                "`{}` expects the maximum Taylor order, an integer from 2 to {MAX_TAYLOR_ORDER} (about 20 reaches double precision)",
                keys::TAYLOR
            ),
        );
        return None;
    };
    if let Some((name, _)) = user_fns.iter().find(|(_, declared)| *declared) {
        cx.error_spanned_by(
            value,
            format!(
                "`{}` cannot be combined with `{name} = …`: the Taylor recurrences need the right-hand side as expressions, and a user function's derivatives are unknown",
                keys::TAYLOR
            ),
        );
        return None;
    }
    Some(order)
}

/// The complete `impl TaylorSystem<N> for ident` with `N = state.len()`: `y' = rhs(t, y)`
/// over the state symbols and the arena's time symbol (a series, read from the `t` argument,
/// when `rhs` reads it), the other symbols read through `symbols` after `prelude`
/// (statements binding what those read, which may use `self`). Its `Workspace` is the
/// emitted rows (`Vec<[f64; K + 1]>`), its `coefficients_into` the emitted recurrences and
/// its `coefficients_extended_into` their double-double low orders (`Tape::extended_tokens`).
/// `check_parameters` is the body of `TaylorSystem::check_parameters`, an expression of type
/// `Result<(), OdeError>` reading `self` (a scene's own checks of its field values, which
/// the Taylor integrator calls once when it is built or restarted), `Ok(())` if `None`. A
/// symbol the map does not know is an internal error spanned on `ident`, as in `symbols.rs`.
/// The one entry point of every scene's `taylor = K`.
#[allow(clippy::too_many_arguments)]
pub fn expand(
    cx: &Ctxt,
    ident: &Ident,
    arena: &Arena,
    symbols: &SymbolTokens,
    state: &[ExprId],
    rhs: &[ExprId],
    prelude: TokenStream,
    order: usize,
    check_parameters: Option<TokenStream>,
) -> TokenStream {
    let check_parameters =
        check_parameters.unwrap_or_else(|| quote!(::core::result::Result::Ok(())));
    let p = Private;
    let n = state.len();
    let state_exprs = state;
    let state: Option<Vec<SymbolId>> = state.iter().map(|&e| arena.as_symbol(e)).collect();
    let Some(state) = state.filter(|s| s.len() == rhs.len()) else {
        cx.error_spanned_by(
            ident,
            "internal error of the derive: the state of the Taylor recurrences is not a list of symbols; please report this",
        );
        return TokenStream::new();
    };
    let program = Program::lower(arena, rhs);
    // The time is a series only where the program reads it (through an abbreviation too):
    // an autonomous scene whose arena made the symbol anyway (a mechanism's derivation does)
    // keeps no time row.
    let time = arena.time_symbol().filter(|s| program.inputs().contains(s));
    let tape = Tape::from_program(&program, &state, time);
    let code = tape.to_tokens(order, &mut |s| match symbols.get(s) {
        Some(tokens) => tokens,
        None => {
            cx.error_spanned_by(
                ident,
                format!(
                    "internal error of the derive: the Taylor recurrences read the symbol `{}`, which has no value; please report this",
                    arena.symbol(s).name
                ),
            );
            quote!(0.0)
        }
    });
    let (body, workspace) = (code.body, code.workspace);
    // The extended mode's double-double low orders, from tables of the same tape (a symbol
    // without a value was reported above).
    let extended = tape.extended_tokens(order, &mut |s| symbols.get(s).unwrap_or_default());
    // The same tape in batch lanes, reading the symbols as the scalar code does: every
    // scene with `taylor = K` steps in `BatchTaylor` too.
    let lanes = crate::taylor_system::lanes::lane_impl(
        ident,
        arena,
        symbols,
        &prelude,
        state_exprs,
        rhs,
        order,
    );
    quote! {
        #[automatically_derived]
        #[allow(unused_variables, unused_mut, clippy::all, clippy::pedantic, clippy::nursery, unused_parens)]
        impl #p::TaylorSystem<#n> for #ident {
            type Workspace = #workspace;

            #[inline]
            fn max_order(&self) -> usize {
                #order
            }

            fn coefficients_into(
                &self,
                ws: &mut Self::Workspace,
                t: f64,
                y: &[f64; #n],
                order: usize,
                coeffs: &mut [[f64; #n]],
            ) {
                #prelude
                #body
            }

            fn coefficients_extended_into(
                &self,
                ws: &mut Self::Workspace,
                t: #p::Dd,
                y: &[#p::Dd; #n],
                order: usize,
                coeffs: &mut [[f64; #n]],
                low: &mut [[#p::Dd; #n]],
            ) -> bool {
                #prelude
                #extended
            }

            fn check_parameters(&self) -> ::core::result::Result<(), #p::OdeError> {
                #check_parameters
            }
        }

        #lanes
    }
}
