//! The stub `impl RigidBody` emitted next to the errors, so code using the trait does not
//! add a cascade of "trait not implemented" errors to the real ones.

use proc_macro2::TokenStream;
use quote::quote;
use syn::DeriveInput;

use crate::lang::keys;
use crate::lang::private::Private;
use crate::lang::stub::Stub;

/// A stub `impl RigidBody` for `input`.
pub fn stub(input: &DeriveInput) -> TokenStream {
    let p = Private;
    let stub = Stub::new(input, keys::RIGID);
    let body = &stub.body;
    stub.trait_impl(
        &quote!(#p::RigidBody),
        quote! {
            fn description(&self) -> #p::Description<f64> { #body }
            fn mass(&self) -> f64 { #body }
            fn center_of_mass(&self) -> #p::Vector3<f64> { #body }
            fn reference_point(&self) -> #p::Vector3<f64> { #body }
            fn inertia(&self) -> #p::Matrix3<f64> { #body }
            fn inertia_cm(&self) -> #p::Matrix3<f64> { #body }
            fn principal(&self) -> #p::Principal { #body }
            fn euler_rhs_principal(&self, _: &#p::Vector3<f64>, _: &#p::Vector3<f64>) -> #p::Vector3<f64> { #body }
        },
    )
}
