//! `taylor = K` on `#[mechanism(...)]`: the key's check (after the links, since an effort
//! computed by a user function rules it out) and `impl TaylorSystem<2N>` for the first-order
//! system `(q, q̇)' = (q̇, q̈)` of the route's q̈, emitted by the same function as the tops'
//! and free bodies' (`crate::taylor`). Mechanisms without the key emit nothing here.

use precess_core::mechanism::MechanismDerivation;
use precess_core::sym::Arena;
use proc_macro2::TokenStream;
use syn::{Expr, Ident};

use super::check::CheckedMechanism;
use crate::lang::ctxt::Ctxt;
use crate::lang::keys;
use crate::lang::symbols::FieldParameters;

/// The order of `taylor = K`, or `None` without the key or after recording its error.
pub fn check(cx: &Ctxt, value: Option<&Expr>, checked: &CheckedMechanism) -> Option<usize> {
    let user = [(keys::EFFORT, !checked.efforts.is_empty())];
    crate::lang::taylor::check(cx, value?, &user)
}

/// `impl TaylorSystem<2n>` over the state `[q, q̇]`, reading the fields as the other
/// methods do.
pub fn expand(
    cx: &Ctxt,
    ident: &Ident,
    arena: &Arena,
    parameters: &FieldParameters,
    derivation: &MechanismDerivation,
    order: usize,
) -> TokenStream {
    let (state, rhs) = derivation.first_order_system();
    crate::lang::taylor::expand(
        cx,
        ident,
        arena,
        &parameters.tokens(),
        &state,
        &rhs,
        TokenStream::new(),
        order,
    )
}
