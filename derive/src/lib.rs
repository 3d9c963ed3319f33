//! The `#[derive(RigidBody)]` macro of precess.
//!
//! It reads the body described by `#[rigid(...)]` (see `docs/attributes.md`), computes its
//! mass properties, principal frame and Euler's equations with precess-core's symbolic
//! engine while it expands, and emits a `RigidBody` impl specialised to the body: constants
//! for literal values, straight-line code in the fields for parametric ones.
//!
//! Phases, one file each: `ast` (borrowed view of the input), `attr` (syntax of the
//! attribute), `check` (meaning and validation, every error collected in `ctxt`), `expand`
//! (calls precess-core and quotes the result), `fallback` (errors plus a stub impl).
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod ast;
mod attr;
mod check;
mod ctxt;
mod expand;
mod fallback;
mod top;

use proc_macro::TokenStream;
use syn::{DeriveInput, parse_macro_input};

/// Derives `RigidBody` from a `#[rigid(...)]` description of the body's parts, and `Top`
/// when a `#[top(...)]` attribute declares the body a top about its pivot.
///
/// See the `precess` crate for examples and `docs/attributes.md` for the language.
#[proc_macro_derive(RigidBody, attributes(rigid, top))]
pub fn derive_rigid_body(input: TokenStream) -> TokenStream {
    let input = parse_macro_input!(input as DeriveInput);
    expand::derive(&input).into()
}

#[cfg(test)]
mod tests;
#[cfg(test)]
mod top_tests;
