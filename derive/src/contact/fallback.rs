//! The stub `impl ContactDynamics` emitted next to the errors when the struct declares a
//! contact, so code using the trait does not add errors to the real ones.

use proc_macro2::TokenStream;
use quote::quote;
use syn::DeriveInput;

use crate::lang::keys;
use crate::lang::private::Private;
use crate::lang::stub::Stub;

/// A stub `impl ContactDynamics` for `input`.
pub fn stub(input: &DeriveInput) -> TokenStream {
    let p = Private;
    let stub = Stub::new(input, keys::CONTACT);
    let body = &stub.body;
    stub.trait_impl(
        &quote!(#p::ContactDynamics),
        quote! {
            fn law(&self) -> #p::LawKind { #body }
            fn surface_kind(&self) -> #p::SurfaceKind { #body }
            fn phase_rhs(&self, _: #p::Phase, _: f64, _: &[f64; 11], _: &mut [f64; 11]) { #body }
            fn reaction(&self, _: #p::Phase, _: &[f64; 11]) -> #p::Reaction { #body }
            fn energy(&self, _: #p::Phase, _: &[f64; 11]) -> f64 { #body }
            fn momenta(&self, _: #p::Phase, _: &[f64; 11]) -> #p::ContactMomenta { #body }
            fn contact(&self, _: &[f64; 11]) -> #p::ContactPoint { #body }
            fn jellett(&self, _: &[f64; 11]) -> f64 { #body }
            fn friction_coefficient(&self) -> ::core::option::Option<f64> { #body }
            fn check_parameters(&self) -> ::core::result::Result<(), #p::ContactError> { #body }
            fn values(&self) -> #p::ContactValues { #body }
        },
    )
}
