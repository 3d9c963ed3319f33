//! `#[derive(Mechanism)]`: a tree of rigid bodies described by `#[body(...)]` attributes
//! (each a body in the part language of `lang::parts`, joined to its parent by a named
//! joint) and `#[mechanism(...)]` settings, in the phases every attribute has over `lang/`:
//! `attr` (syntax), `check` (meaning, with a body's joint in `joint`, its loads in `loads`
//! and the tree's rules in `tree`), `expand` (the `MechanismDynamics` impl, with
//! `parameters`, `jacobian` and `expand/charts`) and `fallback` (the stubs). Bodies that roll
//! on a floor (`rolls = ..`, with `up` and `speeds`) are read in `rolling` and expanded to
//! `impl RollingDynamics` by `expand/rolling` instead; the `variational(...)` group of
//! `#[mechanism]` is read and emitted in `variational`. This file is the derive's driver.

pub mod attr;
pub mod check;
mod closes;
pub mod expand;
mod fallback;
mod jacobian;
mod joint;
mod loads;
mod parameters;
mod poses;
mod rolling;
mod tree;
mod variational;

use precess_core::sym::Arena;
use proc_macro2::TokenStream;
use syn::DeriveInput;

use crate::lang::ast::Input;
use crate::lang::check::Checker;
use crate::lang::ctxt::Ctxt;
use crate::lang::expansion::Expansion;
use crate::lang::keys;
use crate::lang::symbols::FieldParameters;
use crate::lang::taylor::TaylorKey;

/// The whole derive: the impls, or every error and the stub impls.
pub fn derive(input: &DeriveInput) -> TokenStream {
    let cx = Ctxt::new();
    let expanded = expand(&cx, input);
    cx.finish(&input.ident, expanded, || fallback::stub(input))
}

/// Every phase: syntax and meaning of all attributes, then the expansion.
fn expand(cx: &Ctxt, input: &DeriveInput) -> Option<TokenStream> {
    let ast = Input::for_derive(cx, input, "Mechanism")?;
    let (settings, group) = variational::parse(cx, &ast.attributes(keys::MECHANISM));
    let in_mechanism = format!("`#[{}]`", keys::MECHANISM);
    let pairs = settings.items.iter().map(|kv| (&kv.key, &kv.value));
    let taylor = TaylorKey::find(cx, pairs, &in_mechanism);
    let links = attr::parse_links(cx, &ast.attributes(keys::LINK));
    let mut arena = Arena::new();
    let mut parameters = FieldParameters::default();
    let mut ck = Checker::new(cx, &ast, &mut arena, &mut parameters);
    let checked = check::check(&mut ck, &settings, &links)?;
    let variational = match &group {
        Some(group) => Some(variational::check(&ck, group, &checked)?),
        None => None,
    };
    // An effort computed by a user function has no Taylor coefficients.
    let taylor = taylor.order(cx, &[(keys::EFFORT, !checked.efforts.is_empty())]);
    let mut ex = Expansion {
        cx,
        ident: &input.ident,
        arena: &mut arena,
        parameters: &parameters,
    };
    expand::expand(&mut ex, &checked, taylor, variational.as_ref())
}
