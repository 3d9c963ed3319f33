//! What the derive emits when it found errors: the errors, plus a stub impl so that code
//! using the trait does not add a cascade of "trait not implemented" errors.

use proc_macro2::TokenStream;
use quote::quote;
use syn::DeriveInput;

use crate::ctxt::Ctxt;

/// The recorded errors and a stub `RigidBody` impl for `input`.
pub fn expand(input: &DeriveInput, cx: &Ctxt) -> TokenStream {
    let errors = cx.to_compile_errors();
    let ident = &input.ident;
    let (impl_generics, ty_generics, where_clause) = input.generics.split_for_impl();
    let p = quote!(::precess::__private);
    let stub = quote!(::core::unimplemented!(
        "the #[rigid] description has errors"
    ));
    quote! {
        #errors
        #[automatically_derived]
        impl #impl_generics #p::RigidBody for #ident #ty_generics #where_clause {
            fn description(&self) -> #p::Description<f64> { #stub }
            fn mass(&self) -> f64 { #stub }
            fn center_of_mass(&self) -> #p::Vector3<f64> { #stub }
            fn reference_point(&self) -> #p::Vector3<f64> { #stub }
            fn inertia(&self) -> #p::Matrix3<f64> { #stub }
            fn inertia_cm(&self) -> #p::Matrix3<f64> { #stub }
            fn principal(&self) -> #p::Principal { #stub }
            fn euler_rhs(&self, _: &#p::Vector3<f64>, _: &#p::Vector3<f64>) -> #p::Vector3<f64> { #stub }
        }
    }
}
