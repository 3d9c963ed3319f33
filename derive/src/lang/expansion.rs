//! What every attribute's expansion reads, passed as one: where errors go, the struct the
//! impls are for, the arena the checker built the values in, and the fields it read. The
//! checks fill the arena and the fields; the expansions only add the equations' expressions
//! to the arena.

use std::fmt::Display;

use precess_core::sym::Arena;
use syn::Ident;

use super::ctxt::Ctxt;
use super::symbols::FieldParameters;

/// The context of one macro's expansion phase.
pub struct Expansion<'a> {
    /// Where errors go.
    pub cx: &'a Ctxt,
    /// The struct the impls are for (errors of the whole scene are spanned on it).
    pub ident: &'a Ident,
    /// The arena the values were checked into; the equations are derived in it.
    pub arena: &'a mut Arena,
    /// The struct's fields the values read, each with its parameter symbol.
    pub parameters: &'a FieldParameters,
}

impl<'a> Expansion<'a> {
    /// The context in its parts, the arena borrowed mutably beside the others, as every
    /// expansion reads them at once: `(cx, ident, parameters, arena)`.
    pub fn split(&mut self) -> (&'a Ctxt, &'a Ident, &'a FieldParameters, &mut Arena) {
        (self.cx, self.ident, self.parameters, &mut *self.arena)
    }
}

/// Records, on the struct `ident`, that `what` (``the top's equations of motion``) could not
/// be derived, with the engine's reason `e`: every scene's one message for it.
pub fn cannot_derive(cx: &Ctxt, ident: &Ident, what: &str, e: &dyn Display) {
    cx.error_spanned_by(ident, format!("cannot derive {what}: {e}"));
}
