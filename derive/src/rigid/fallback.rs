//! The stub `impl RigidBody` emitted next to the errors, so code using the trait does not
//! add a cascade of "trait not implemented" errors to the real ones.

use proc_macro2::TokenStream;
use quote::quote;
use syn::DeriveInput;

use crate::lang::private::Private;

/// A stub `impl RigidBody` for `input`.
pub fn stub(input: &DeriveInput) -> TokenStream {
    let p = Private;
    let ident = &input.ident;
    let (impl_generics, ty_generics, where_clause) = input.generics.split_for_impl();
    let stub = quote!(::core::unimplemented!(
        "the #[rigid] description has errors"
    ));
    quote! {
        #[automatically_derived]
        impl #impl_generics #p::RigidBody for #ident #ty_generics #where_clause {
            fn description(&self) -> #p::Description<f64> { #stub }
            fn mass(&self) -> f64 { #stub }
            fn center_of_mass(&self) -> #p::Vector3<f64> { #stub }
            fn reference_point(&self) -> #p::Vector3<f64> { #stub }
            fn inertia(&self) -> #p::Matrix3<f64> { #stub }
            fn inertia_cm(&self) -> #p::Matrix3<f64> { #stub }
            fn principal(&self) -> #p::Principal { #stub }
            fn euler_rhs_principal(&self, _: &#p::Vector3<f64>, _: &#p::Vector3<f64>) -> #p::Vector3<f64> { #stub }
        }
    }
}
