//! The stub `impl FreeDynamics` emitted next to the errors when the struct declares a free
//! body, so code using the trait does not add errors to the real ones; with it the state's
//! slot names (`Body::VZ`, and `Body::ROTOR_k` for each rotor written with a `torque`), which
//! do not depend on the description.

use proc_macro2::TokenStream;
use quote::quote;
use syn::DeriveInput;

use crate::lang::keys;
use crate::lang::private::Private;
use crate::lang::stub::Stub;

/// A stub `impl FreeDynamics` for `input`, and its slot consts.
pub fn stub(input: &DeriveInput) -> TokenStream {
    let p = Private;
    let stub = Stub::new(input, keys::FREE);
    let body = &stub.body;
    let driven = crate::lang::rotor::driven_names(input, keys::FREE, super::attr::parse);
    let slots = super::expand::slot_consts(&input.ident, &driven);
    let n = precess_core::free::STATE_LEN + driven.len();
    let dynamics = crate::lang::rotor::scene_trait(quote!(#p::FreeDynamics), n, !driven.is_empty());
    let consts = stub.inherent(quote!(#(#slots)*));
    let dynamics = stub.trait_impl(
        &dynamics,
        quote! {
            const BEYOND_GRAVITY: ::core::option::Option<&'static str> = ::core::option::Option::None;
            const DRIVEN_ROTORS: &'static [&'static str] = &[#(#driven),*];
            fn principal_cm(&self) -> #p::Principal { #body }
            fn gravity(&self) -> #p::Vector3<f64> { #body }
            fn free_rhs(&self, _: f64, _: &[f64; #n], _: &mut [f64; #n]) { #body }
            fn wrench(&self, _: f64, _: &[f64; #n]) -> #p::Wrench { #body }
            fn energy(&self, _: &[f64; #n]) -> f64 { #body }
            fn power(&self, _: f64, _: &[f64; #n]) -> f64 { #body }
            fn linear_momentum(&self, _: &[f64; #n]) -> #p::Vector3<f64> { #body }
            fn angular_momentum_origin(&self, _: &[f64; #n]) -> #p::Vector3<f64> { #body }
            fn check_parameters(&self) -> ::core::result::Result<(), #p::FreeError> { #body }
        },
    );
    quote!(#consts #dynamics)
}
