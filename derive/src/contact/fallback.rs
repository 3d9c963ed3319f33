//! The stub `impl ContactDynamics` emitted next to the errors when the struct declares a
//! contact, so code using the trait does not add errors to the real ones.

use proc_macro2::TokenStream;
use quote::quote;
use syn::DeriveInput;

use crate::lang::private::Private;

/// A stub `impl ContactDynamics` for `input`.
pub fn stub(input: &DeriveInput) -> TokenStream {
    let p = Private;
    let ident = &input.ident;
    let (impl_generics, ty_generics, where_clause) = input.generics.split_for_impl();
    let stub = quote!(::core::unimplemented!(
        "the #[contact] description has errors"
    ));
    quote! {
        #[automatically_derived]
        impl #impl_generics #p::ContactDynamics for #ident #ty_generics #where_clause {
            fn law(&self) -> #p::LawKind { #stub }
            fn surface_kind(&self) -> #p::SurfaceKind { #stub }
            fn phase_rhs(&self, _: #p::Phase, _: f64, _: &[f64; 11], _: &mut [f64; 11]) { #stub }
            fn reaction(&self, _: #p::Phase, _: &[f64; 11]) -> #p::Reaction { #stub }
            fn energy(&self, _: #p::Phase, _: &[f64; 11]) -> f64 { #stub }
            fn momenta(&self, _: #p::Phase, _: &[f64; 11]) -> #p::ContactMomenta { #stub }
            fn contact(&self, _: &[f64; 11]) -> #p::ContactPoint { #stub }
            fn jellett(&self, _: &[f64; 11]) -> f64 { #stub }
            fn friction_coefficient(&self) -> ::core::option::Option<f64> { #stub }
            fn check_parameters(&self) -> ::core::result::Result<(), #p::ContactError> { #stub }
            fn values(&self) -> #p::ContactValues { #stub }
        }
    }
}
