//! The attribute language every macro of the crate shares, whichever attribute or macro
//! reads it. Each attribute's folder (`rigid/`, `top/`, `free/`, `mechanism/`,
//! `taylor_system/`) holds only what is its own, in the phases attr → check → expand →
//! fallback over these:
//!
//! - `ctxt`: every error of one expansion, checked once, and how every macro ends.
//! - `keys`: the language's words, each written once, and the "did you mean" suggestions.
//! - `ast`: the struct a derive applies to, its fields and attributes.
//! - `syntax`: the grammar of lists, `key = value` settings and `name(key = value, ...)`
//!   groups, one parser for every attribute.
//! - `check`: the checker all values go through (one arena, one list of fields read);
//!   `values` and `scalar`, the value language it reads (numbers, fields, arithmetic, vectors, tensors,
//!   axes, rotations); `parts`, the part language of `#[rigid]` and a mechanism body.
//! - `sign`: the sign rules on constant values (`Checker::positive`, `non_negative`), one
//!   message for every attribute.
//! - `units`: units on values (`2 cm`, `7.8 g/cm^3`), attached to what they follow before
//!   syn reads a value; `dim`, the dimensions each key's values are checked against.
//! - `expansion`: what every expansion reads; `symbols`, the lowering of the arena's
//!   expressions to Rust reading the fields; `tokens`, the body language's values as Rust.
//! - `export`: every derive's `impl Export` (the scene's programs as text for C and Python),
//!   one call in each scene's expansion.
//! - `taylor`: the `taylor = K` key of every attribute, found, checked and expanded in one
//!   place.
//! - `variational`: the `variational(...)` group of `#[top]` and `#[mechanism]`, checked
//!   against the scene's state and fields and emitted as `<Name>Variational` in one place.
//! - `surface`: the one reader of a rolling surface, `#[contact(surface = ..)]`'s and a
//!   wheel's `rolls = ..`.
//! - `stub`: what the stubs emitted beside the errors are made of, for every attribute.
//! - `private`: the one hidden path, `::precess::__private`, generated code names precess
//!   through.

pub mod ast;
pub mod check;
pub mod ctxt;
pub mod dim;
pub mod expansion;
pub mod export;
pub mod keys;
pub mod parts;
pub mod private;
pub mod rotor;
pub mod scalar;
pub mod sign;
pub mod stub;
pub mod surface;
pub mod symbols;
pub mod syntax;
pub mod taylor;
pub mod tokens;
pub mod units;
pub mod values;
pub mod variational;

#[cfg(test)]
pub(crate) mod tests;
