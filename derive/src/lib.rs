//! The macros of precess: `#[derive(RigidBody)]`, `#[derive(Mechanism)]` and
//! `taylor_system!`.
//!
//! They read the scene described by their attributes (see `docs/attributes.md`,
//! `docs/mechanisms.md`, `docs/taylor.md`), derive its equations of motion with precess-core's
//! symbolic engine while they expand, and emit impls specialised to it: constants for literal
//! values, straight-line code in the fields for parametric ones. `#[derive(RigidBody)]` emits
//! `RigidBody` from `#[rigid(...)]`, with `#[top(...)]` also `TopDynamics`, with `#[free(...)]`
//! `FreeDynamics`, with `#[contact(...)]` `ContactDynamics`; `#[derive(Mechanism)]` emits `MechanismDynamics<N>` from `#[body(...)]` and
//! `#[mechanism(...)]`; `taylor_system!` emits `System<N>` and `TaylorSystem<N>` from equations.
//!
//! Layout: `lang/` is the front end every macro shares — the error context, the words of the
//! language and its suggestions, the grammar of settings and groups, the value and part
//! languages read into the arena by one checker, the lowering to tokens, `taylor = K` in one
//! place, and the one hidden path generated code names (`::precess::__private`). Each
//! attribute is a folder of the same phases over it, `attr` (syntax) → `check` (meaning) →
//! `expand` (the impls) → `fallback` (stub impls after an error): `rigid/`, `top/`, `free/`, `contact/`,
//! `mechanism/` (whose `mod.rs` is the `Mechanism` derive's driver), and `taylor_system/`
//! (which has `values` for its expression language and no fallback). `rigid_body.rs` drives
//! `#[derive(RigidBody)]` over its four attributes.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod contact;
mod free;
mod lang;
mod mechanism;
mod rigid;
mod rigid_body;
mod taylor_system;
mod top;

use proc_macro::TokenStream;
use syn::{DeriveInput, parse_macro_input};

/// Derives `RigidBody` from a `#[rigid(...)]` description of the body's parts, `TopDynamics`
/// when a `#[top(...)]` attribute declares the body a top about its pivot, `FreeDynamics`
/// when a `#[free(...)]` attribute declares it a free body, and `ContactDynamics` when a
/// `#[contact(...)]` attribute puts it on a table.
///
/// See the `precess` crate for examples and `docs/attributes.md` for the language.
#[proc_macro_derive(RigidBody, attributes(rigid, top, free, contact))]
pub fn derive_rigid_body(input: TokenStream) -> TokenStream {
    let input = parse_macro_input!(input as DeriveInput);
    rigid_body::derive(&input).into()
}

/// Derives `MechanismDynamics<N>` (and the ODE `System<2N>`) for a tree of rigid bodies
/// described by `#[body(...)]` attributes, one per body with the joint to its parent, and
/// `#[mechanism(...)]` settings (gravity). When bodies roll on a floor (`rolls = disk(..)`
/// or `sphere(..)`, with `up` and `speeds`), it derives `RollingDynamics<N, M, K>` instead.
///
/// See `docs/mechanisms.md` and `docs/attributes.md` for the language.
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

#[cfg(test)]
mod tests;
