//! Collects every error of one expansion, so the user sees them all at once.
//!
//! Taken by `&self` (the errors sit in a `RefCell`), so every phase can hold it next to a
//! mutable borrow of the arena. It must be consumed by [`Ctxt::check`]: dropping it with
//! errors still inside would lose them, which only a bug in the macro itself can do.

use std::cell::RefCell;
use std::fmt::Display;
use std::thread;

use proc_macro2::TokenStream;
use quote::ToTokens;
use syn::Ident;

/// The errors found so far.
pub struct Ctxt {
    /// `None` once [`Ctxt::check`] has taken them.
    errors: RefCell<Option<Vec<syn::Error>>>,
}

impl Ctxt {
    /// An empty context.
    pub fn new() -> Ctxt {
        Ctxt {
            errors: RefCell::new(Some(Vec::new())),
        }
    }

    /// Records `msg` spanned on `tokens` (first to last token).
    pub fn error_spanned_by(&self, tokens: impl ToTokens, msg: impl Display) {
        self.syn_error(syn::Error::new_spanned(tokens.into_token_stream(), msg));
    }

    /// Records a ready-made error (a syntax error from syn).
    pub fn syn_error(&self, e: syn::Error) {
        if let Some(errors) = self.errors.borrow_mut().as_mut() {
            errors.push(e);
        }
    }

    /// How many errors were recorded so far: a phase compares it before and after to know
    /// whether its own part went wrong, whatever other phases found.
    pub fn error_count(&self) -> usize {
        self.errors.borrow().as_ref().map_or(0, Vec::len)
    }

    /// Takes the errors: `Ok` if there were none.
    ///
    /// # Errors
    /// Every recorded error, in the order found.
    pub fn check(self) -> Result<(), Vec<syn::Error>> {
        let errors = self.errors.borrow_mut().take().unwrap_or_default();
        if errors.is_empty() {
            Ok(())
        } else {
            Err(errors)
        }
    }
}

impl Ctxt {
    /// The end of every macro's expansion: `expanded` if no error was recorded; else every
    /// error as a `compile_error!`, then `fallback()` (stub impls, or the item as written), so
    /// code using what the macro would have made adds no cascade of errors of its own.
    /// `expanded` missing without an error is the macro's own bug, reported on `ident`.
    pub fn finish(
        self,
        ident: &Ident,
        expanded: Option<TokenStream>,
        fallback: impl FnOnce() -> TokenStream,
    ) -> TokenStream {
        let errors = match (self.check(), expanded) {
            (Ok(()), Some(tokens)) => return tokens,
            // Every phase that gives up records why; reaching here is a bug of the macro.
            (Ok(()), None) => vec![syn::Error::new_spanned(
                ident,
                "internal error of the macro: it stopped without an error; please report this",
            )],
            (Err(errors), _) => errors,
        };
        let mut out: TokenStream = errors.iter().map(syn::Error::to_compile_error).collect();
        out.extend(fallback());
        out
    }
}

impl Drop for Ctxt {
    fn drop(&mut self) {
        // Reachable only if the macro forgot to call `check` (a bug caught by its own
        // tests), never through user input; silent otherwise while already unwinding.
        if !thread::panicking() && self.errors.borrow().is_some() {
            panic!("internal error: the derive's errors were never checked");
        }
    }
}
