//! The one path generated code names everything through: the facade's hidden module, so
//! the emitted impls never depend on the user's imports.

use proc_macro2::TokenStream;
use quote::{ToTokens, quote};

/// `::precess::__private`, interpolated as `#Private` in `quote!`.
pub struct Private;

impl ToTokens for Private {
    fn to_tokens(&self, tokens: &mut TokenStream) {
        tokens.extend(quote!(::precess::__private));
    }
}
