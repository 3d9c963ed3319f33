//! What the derive emits when it found errors: every error, plus a stub impl of each trait
//! the struct asked for, so code using the traits does not add a cascade of "trait not
//! implemented" errors.

use proc_macro2::TokenStream;
use syn::DeriveInput;

use crate::lang::keys;
use crate::{free, rigid, top};

/// The errors as `compile_error!` invocations and the stub impls for `input`.
pub fn expand(input: &DeriveInput, errors: &[syn::Error]) -> TokenStream {
    let mut out: TokenStream = errors.iter().map(syn::Error::to_compile_error).collect();
    out.extend(rigid::fallback::stub(input));
    if input.attrs.iter().any(|a| a.path().is_ident(keys::TOP)) {
        out.extend(top::fallback::stub(input));
    }
    if input.attrs.iter().any(|a| a.path().is_ident(keys::FREE)) {
        out.extend(free::fallback::stub(input));
    }
    out
}
