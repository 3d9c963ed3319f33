//! The `#[derive(RigidBody)]` macro of precess.
//!
//! It reads the body described by `#[rigid(...)]` (see `docs/attributes.md`), computes its
//! mass properties, principal frame and Euler's equations with precess-core's symbolic
//! engine while it expands, and emits a `RigidBody` impl specialised to the body: constants
//! for literal values, straight-line code in the fields for parametric ones. With
//! `#[top(...)]` it also derives the top's equations of motion and emits a `TopDynamics` impl;
//! with `#[free(...)]`, a free body's, and a `FreeDynamics` impl.
//!
//! Each attribute is a folder with the same phases (`rigid/`, `top/`, `free/`: ast → attr → check →
//! expand → fallback). Shared by all: `ctxt` (every error of one expansion, checked once),
//! `keys` (the language's words), `symbols` (the one map from symbols to the Rust that reads
//! them), `private` (the hidden path generated code names), `fallback` (errors plus stubs).
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod free;
mod lang;
mod mechanism;
mod rigid;
mod rigid_body;
mod taylor_system;
mod top;

use precess_core::sym::Arena;
use proc_macro::TokenStream;
use quote::quote;
use syn::{DeriveInput, parse_macro_input};

use lang::ast::Input;
use lang::check::Checker;
use lang::ctxt::Ctxt;
use lang::keys;
use lang::symbols::FieldParameters;

/// Derives `RigidBody` from a `#[rigid(...)]` description of the body's parts, `TopDynamics`
/// when a `#[top(...)]` attribute declares the body a top about its pivot, and `FreeDynamics`
/// when a `#[free(...)]` attribute declares it a free body.
///
/// See the `precess` crate for examples and `docs/attributes.md` for the language.
#[proc_macro_derive(RigidBody, attributes(rigid, top, free))]
pub fn derive_rigid_body(input: TokenStream) -> TokenStream {
    let input = parse_macro_input!(input as DeriveInput);
    derive(&input).into()
}

/// Derives `MechanismDynamics<N>` (and the ODE `System<2N>`) for a tree of rigid bodies
/// described by `#[body(...)]` attributes, one per body with the joint to its parent, and
/// `#[mechanism(...)]` settings (gravity).
///
/// See `docs/mechanisms.md` for the language.
#[proc_macro_derive(Mechanism, attributes(mechanism, body))]
pub fn derive_mechanism(input: TokenStream) -> TokenStream {
    let input = parse_macro_input!(input as DeriveInput);
    mechanism::derive(&input).into()
}

/// An ODE `y' = f(t, y)` written as equations, emitted as a struct with `System<N>` (the
/// right-hand side as straight-line code) and `TaylorSystem<N>` (its Taylor recurrences up
/// to the order given), both derived symbolically while the macro expands.
///
/// ```text
/// precess::taylor_system! {
///     /// Euler's equations of a torque-free body, m in principal axes.
///     pub struct Euler { pub i1: f64, pub i2: f64, pub i3: f64 }
///     state [m1, m2, m3];
///     taylor = 20;
///     d/dt m1 = (1.0 / i3 - 1.0 / i2) * m2 * m3;
///     d/dt m2 = (1.0 / i1 - 1.0 / i3) * m3 * m1;
///     d/dt m3 = (1.0 / i2 - 1.0 / i1) * m1 * m2;
/// }
/// ```
///
/// The struct (unit, or with named `f64` fields read as parameters) comes first, then
/// `state [..];`, `taylor = K;` (2 to 100) and one `d/dt x = …;` per state variable. A
/// right-hand side uses numbers, the state variables, the fields, the time `t`, `+ - * /`,
/// unary `-`, and `sin`, `cos`, `sqrt`, `powi` (integer literal exponent), `powf` (number
/// literal exponent, taken exactly as a rational; the base taken positive) as methods or
/// calls. See `docs/taylor.md` and the doctest on `precess::taylor_system`.
#[proc_macro]
pub fn taylor_system(input: TokenStream) -> TokenStream {
    taylor_system::expand(input.into()).into()
}

/// The whole derive: the impls, or every error and stub impls.
fn derive(input: &DeriveInput) -> proc_macro2::TokenStream {
    let cx = Ctxt::new();
    let expanded = expand(&cx, input);
    match cx.check() {
        Ok(()) => match expanded {
            Some(tokens) => tokens,
            // Every phase that gives up records why; reaching here is a bug of the macro.
            None => rigid_body::expand(
                input,
                &[syn::Error::new_spanned(
                    &input.ident,
                    "internal error of the derive: it stopped without an error; please report this",
                )],
            ),
        },
        Err(errors) => rigid_body::expand(input, &errors),
    }
}

/// Every phase of every attribute. Syntax and meaning are checked for all before any is
/// expanded, so one pass reports the errors of `#[rigid]`, `#[top]` and `#[free]` together.
fn expand(cx: &Ctxt, input: &DeriveInput) -> Option<proc_macro2::TokenStream> {
    let ast = Input::from_syn(cx, input)?;
    let rigid_items = rigid::attr::parse(cx, &ast.rigid);
    let top_items = top::attr::parse(cx, &ast.top);
    let free_attrs: Vec<&syn::Attribute> = (input.attrs.iter())
        .filter(|a| a.path().is_ident(keys::FREE))
        .collect();
    let free_items = free::attr::parse(cx, &free_attrs);
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
    let (body, settings, free_settings) = (body?, settings?, free_settings?);
    let top = match &settings {
        Some(settings) => {
            top::expand::expand(cx, ast.ident, &mut arena, &parameters, &body, settings)?
        }
        None => proc_macro2::TokenStream::new(),
    };
    let free = match &free_settings {
        Some(settings) => {
            free::expand::expand(cx, ast.ident, &mut arena, &parameters, &body, settings)?
        }
        None => proc_macro2::TokenStream::new(),
    };
    let rigid = rigid::expand::expand(cx, ast.ident, &mut arena, &parameters, &body)?;
    Some(quote!(#rigid #top #free))
}

#[cfg(test)]
mod tests;
