//! The stub `impl TopDynamics` emitted next to the errors when the struct declares a top, so code
//! using the trait does not add errors to the real ones.

use proc_macro2::TokenStream;
use quote::quote;
use syn::DeriveInput;

use crate::lang::private::Private;

/// A stub `impl TopDynamics` for `input`.
pub fn stub(input: &DeriveInput) -> TokenStream {
    let p = Private;
    let ident = &input.ident;
    let (impl_generics, ty_generics, where_clause) = input.generics.split_for_impl();
    let stub = quote!(::core::unimplemented!("the #[top] description has errors"));
    quote! {
        #[automatically_derived]
        impl #impl_generics #p::TopDynamics for #ident #ty_generics #where_clause {
            const SEQUENCE: #p::AngleSequence = #p::AngleSequence::Zxz;
            fn top_parameters(&self) -> #p::TopParameters { #stub }
            fn accelerations_unchecked_in(&self, _: #p::AngleSequence, _: f64, _: &[f64; 6]) -> [f64; 3] { #stub }
            fn rotation_in(&self, _: #p::AngleSequence, _: &[f64; 3]) -> #p::Matrix3<f64> { #stub }
            fn rate_matrix_in(&self, _: #p::AngleSequence, _: &[f64; 3]) -> #p::Matrix3<f64> { #stub }
            fn energy_in(&self, _: #p::AngleSequence, _: &[f64; 6]) -> f64 { #stub }
            fn angle_jacobian(&self, _: f64, _: &[f64; 3], _: &[f64; 3]) -> [[f64; 6]; 3] { #stub }
            fn conserved_momenta(&self, _: &[f64; 3], _: &[f64; 3]) -> [::core::option::Option<f64>; 3] { #stub }
            fn eulerian_rhs(&self, _: f64, _: &#p::UnitQuaternion<f64>, _: &#p::Vector3<f64>) -> #p::Vector3<f64> { #stub }
            fn equations(&self) -> &'static #p::Typeset { #stub }
        }
    }
}
