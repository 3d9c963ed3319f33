//! What every attribute's expansion reads, passed as one: where errors go, the struct the
//! impls are for, the arena the checker built the values in, and the fields it read. The
//! checks fill the arena and the fields; the expansions only add the equations' expressions
//! to the arena.

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
