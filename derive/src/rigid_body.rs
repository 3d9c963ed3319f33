//! `#[derive(RigidBody)]`: its four attributes' phases in order, and what it emits after
//! an error. Syntax and meaning are checked for `#[rigid]`, `#[top]`, `#[free]` and `#[contact]` before
//! any is expanded, so one pass reports all their errors together; after an error it emits
//! every error plus a stub impl of each trait the struct asked for, so code using the traits
//! does not add a cascade of "trait not implemented" errors.

use precess_core::sym::Arena;
use proc_macro2::TokenStream;
use quote::quote;
use syn::DeriveInput;

use crate::lang::ast::Input;
use crate::lang::check::Checker;
use crate::lang::ctxt::Ctxt;
use crate::lang::expansion::Expansion;
use crate::lang::keys;
use crate::lang::symbols::FieldParameters;
use crate::{contact, free, rigid, top};

/// The whole derive: the impls, or every error and the stub impls.
pub fn derive(input: &DeriveInput) -> TokenStream {
    let cx = Ctxt::new();
    let expanded = expand(&cx, input);
    cx.finish(&input.ident, expanded, || stubs(input))
}

/// Every phase of every attribute; `None` after recording why it stopped.
pub fn expand(cx: &Ctxt, input: &DeriveInput) -> Option<TokenStream> {
    let ast = Input::for_derive(cx, input, "RigidBody")?;
    let rigid_items = rigid::attr::parse(cx, &ast.rigid);
    let top_items = top::attr::parse(cx, &ast.top);
    let free_attrs = ast.attributes(keys::FREE);
    let free_items = free::attr::parse(cx, &free_attrs);
    let contact_attrs = ast.attributes(keys::CONTACT);
    let contact_items = contact::attr::parse(cx, &contact_attrs);
    let mut arena = Arena::new();
    let mut parameters = FieldParameters::default();
    let mut ck = Checker::new(cx, &ast, &mut arena, &mut parameters);
    let body = rigid::check::check(&mut ck, &rigid_items);
    // Without any #[rigid] the missing attribute is the error, not the missing pivot.
    let pivot = if ast.rigid.is_empty() {
        None
    } else {
        rigid::check::declares_pivot(&rigid_items)
    };
    let settings = top::check::check(&mut ck, &top_items, pivot);
    let free_settings = free::check::check(&mut ck, &free_attrs, &free_items);
    let contact_settings =
        contact::check::check(&mut ck, &contact_attrs, &contact_items, body.as_ref());
    let (body, settings, free_settings, contact_settings) =
        (body?, settings?, free_settings?, contact_settings?);
    let mut ex = Expansion {
        cx,
        ident: ast.ident,
        arena: &mut arena,
        parameters: &parameters,
    };
    let top = match &settings {
        Some(settings) => top::expand::expand(&mut ex, &body, settings)?,
        None => TokenStream::new(),
    };
    let free = match &free_settings {
        Some(settings) => free::expand::expand(&mut ex, &body, settings)?,
        None => TokenStream::new(),
    };
    let contact = match &contact_settings {
        Some(settings) => contact::expand::expand(&mut ex, &body, settings)?,
        None => TokenStream::new(),
    };
    let rigid = rigid::expand::expand(&mut ex, &body)?;
    Some(quote!(#rigid #top #free #contact))
}

/// A stub impl of each trait the struct asked for.
fn stubs(input: &DeriveInput) -> TokenStream {
    let mut out = rigid::fallback::stub(input);
    if input.attrs.iter().any(|a| a.path().is_ident(keys::TOP)) {
        out.extend(top::fallback::stub(input));
    }
    if input.attrs.iter().any(|a| a.path().is_ident(keys::FREE)) {
        out.extend(free::fallback::stub(input));
    }
    if input.attrs.iter().any(|a| a.path().is_ident(keys::CONTACT)) {
        out.extend(contact::fallback::stub(input));
    }
    out
}
