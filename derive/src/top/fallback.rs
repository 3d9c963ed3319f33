//! The stub `impl TopDynamics` emitted next to the errors when the struct declares a top, so code
//! using the trait does not add errors to the real ones; with it the angle consts (`Top::THETA`)
//! of the sequence `angles = ..` names, read from the tokens as written whatever else is wrong,
//! and for a top with motors `TopDynamics<N>` and the rotor slots (`Top::ROTOR_k`).

use proc_macro2::{TokenStream, TokenTree};
use quote::quote;
use syn::{DeriveInput, Meta};

use crate::lang::keys;
use crate::lang::private::Private;
use crate::lang::stub::{Stub, hidden_const};

/// A stub `impl TopDynamics` for `input`, and its angle consts.
pub fn stub(input: &DeriveInput) -> TokenStream {
    let p = Private;
    let stub = Stub::new(input, keys::TOP);
    let body = &stub.body;
    let span = input.ident.span();
    // Both sets of angle names count from zero when both are emitted.
    let angles = written_angles(input)
        .into_iter()
        .enumerate()
        .map(|(k, name)| hidden_const(name, span, k % 3));
    let driven = crate::lang::rotor::driven_names(input, keys::TOP, super::attr::parse);
    // Unsuffixed, as the stub always wrote its 6.
    let n = proc_macro2::Literal::usize_unsuffixed(6 + driven.len());
    let rotors = driven
        .iter()
        .enumerate()
        .map(|(k, name)| hidden_const(name, span, 6 + k));
    let dynamics = crate::lang::rotor::scene_trait(quote!(#p::TopDynamics), &n, !driven.is_empty());
    let consts = stub.inherent(quote!(#(#angles)* #(#rotors)*));
    let dynamics = stub.trait_impl(
        &dynamics,
        quote! {
            const SEQUENCE: #p::AngleSequence = #p::AngleSequence::Zxz;
            fn top_parameters(&self) -> #p::TopParameters { #body }
            fn accelerations_unchecked_in(&self, _: #p::AngleSequence, _: f64, _: &[f64; #n]) -> [f64; 3] { #body }
            fn rotation_in(&self, _: #p::AngleSequence, _: &[f64; 3]) -> #p::Matrix3<f64> { #body }
            fn rate_matrix_in(&self, _: #p::AngleSequence, _: &[f64; 3]) -> #p::Matrix3<f64> { #body }
            fn energy_in(&self, _: #p::AngleSequence, _: &[f64; #n]) -> f64 { #body }
            fn angle_jacobian(&self, _: f64, _: &[f64; 3], _: &[f64; 3]) -> [[f64; 6]; 3] { #body }
            fn conserved_momenta(&self, _: &[f64; 3], _: &[f64; 3]) -> [::core::option::Option<f64>; 3] { #body }
            fn eulerian_rhs(&self, _: f64, _: &#p::UnitQuaternion<f64>, _: &#p::Vector3<f64>) -> #p::Vector3<f64> { #body }
            fn equations(&self) -> &'static #p::Typeset { #body }
        },
    );
    quote!(#consts #dynamics)
}

/// The angle names of the sequence `angles = ..` writes in `#[top(...)]`: φ, θ, ψ when none
/// is written (the default), yaw, pitch, roll for `zyx`, and both sets for a sequence that
/// is neither (its error is reported; whichever the user meant, their uses resolve).
/// Read from the top-level tokens, so an error elsewhere in the attribute cannot hide it.
fn written_angles(input: &DeriveInput) -> Vec<&'static str> {
    const ZXZ: [&str; 3] = ["phi", "theta", "psi"];
    const ZYX: [&str; 3] = ["yaw", "pitch", "roll"];
    let mut sequence: Option<String> = None;
    for attr in input.attrs.iter().filter(|a| a.path().is_ident(keys::TOP)) {
        let Meta::List(list) = &attr.meta else {
            continue;
        };
        let tokens: Vec<TokenTree> = list.tokens.clone().into_iter().collect();
        for window in tokens.windows(3) {
            if let [TokenTree::Ident(key), TokenTree::Punct(eq), value] = window
                && key == keys::ANGLES
                && eq.as_char() == '='
            {
                sequence = Some(value.to_string());
            }
        }
    }
    match sequence.as_deref() {
        None | Some("zxz") => ZXZ.to_vec(),
        Some("zyx") => ZYX.to_vec(),
        Some(_) => ZXZ.into_iter().chain(ZYX).collect(),
    }
}
