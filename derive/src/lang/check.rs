//! The checker every attribute's values go through: one arena, one list of the struct's
//! fields read, one error context, so `#[rigid]`, `#[top]`, `#[free]` and `#[body]` values
//! meet the same rules and errors. The value language is in `values.rs`, the part language
//! in `parts.rs`; each attribute's own rules are in its `check.rs`.

use precess_core::sym::Arena;

use super::ast::Input;
use super::ctxt::Ctxt;
use super::scalar::Expect;
use super::symbols::FieldParameters;

/// Converts attribute values into expressions of the macro's arena, recording every error.
/// It borrows the arena and the list of fields read, so the values of every attribute of one
/// struct share them with the same rules and errors.
pub struct Checker<'a> {
    /// Where errors go.
    pub cx: &'a Ctxt,
    /// The struct whose fields values may name.
    pub input: &'a Input<'a>,
    /// The arena the values are built in.
    pub arena: &'a mut Arena,
    /// The fields read so far, each with its parameter symbol.
    pub(crate) parameters: &'a mut FieldParameters,
    /// The dimension the key being read wants, if it has one (see `scalar.rs`).
    pub(crate) expect: Option<Expect>,
}

impl<'a> Checker<'a> {
    /// A checker building values of `input` in `arena`, recording the fields it reads.
    pub fn new(
        cx: &'a Ctxt,
        input: &'a Input<'a>,
        arena: &'a mut Arena,
        parameters: &'a mut FieldParameters,
    ) -> Self {
        Checker {
            cx,
            input,
            arena,
            parameters,
            expect: None,
        }
    }
}
