//! The attribute language every macro of the crate shares, whichever attribute or macro
//! reads it: `ctxt` (every error of one expansion, checked once), `keys` (the language's
//! words and the "did you mean" suggestions), `ast` (the struct the derive applies to),
//! `values` (attribute values into the symbolic engine's arena), `symbols` (lowering the
//! arena's expressions to Rust reading the fields), `taylor` (the `taylor = K` key of every
//! attribute, parsed, checked and expanded in one place) and `private` (the one hidden path
//! generated code names precess through).

pub mod ast;
pub mod check;
pub mod ctxt;
pub mod keys;
pub mod parts;
pub mod private;
pub mod symbols;
pub mod syntax;
pub mod taylor;
pub mod tokens;
pub mod values;

#[cfg(test)]
pub(crate) mod tests;
