//! What the stubs every attribute emits beside its errors are made of, so code using the
//! traits and consts the macro would have made adds no cascade of errors to the real ones:
//! one body for every stub method, naming the attribute whose description has errors, the
//! impls over the struct's generics, and the hidden consts the uses of a slot resolve to.

use proc_macro2::{Span, TokenStream};
use quote::{format_ident, quote};
use syn::DeriveInput;

/// The stubs of one attribute for one struct.
pub struct Stub<'a> {
    input: &'a DeriveInput,
    /// The body of every stub method: `unimplemented!`, naming the attribute.
    pub body: TokenStream,
}

impl<'a> Stub<'a> {
    /// The stubs of `#[attribute]` for `input`.
    pub fn new(input: &'a DeriveInput, attribute: &str) -> Self {
        let message = format!("the #[{attribute}] description has errors");
        Stub {
            input,
            body: quote!(::core::unimplemented!(#message)),
        }
    }

    /// `impl trait_path for` the struct, over its generics, holding `items`.
    pub fn trait_impl(&self, trait_path: &TokenStream, items: TokenStream) -> TokenStream {
        let ident = &self.input.ident;
        let (impl_generics, ty_generics, where_clause) = self.input.generics.split_for_impl();
        quote! {
            #[automatically_derived]
            impl #impl_generics #trait_path for #ident #ty_generics #where_clause {
                #items
            }
        }
    }

    /// The struct's own impl, over its generics, holding `items` (its consts).
    pub fn inherent(&self, items: TokenStream) -> TokenStream {
        let ident = &self.input.ident;
        let (impl_generics, ty_generics, where_clause) = self.input.generics.split_for_impl();
        quote! {
            #[automatically_derived]
            impl #impl_generics #ident #ty_generics #where_clause {
                #items
            }
        }
    }
}

/// `#[doc(hidden)] pub const NAME: usize = value;` for `name` in capitals, spanned at `span`:
/// a slot or index a stub keeps so its uses resolve.
pub fn hidden_const(name: &str, span: Span, value: usize) -> TokenStream {
    let upper = format_ident!("{}", name.to_uppercase(), span = span);
    quote! {
        #[doc(hidden)]
        pub const #upper: usize = #value;
    }
}
