//! The motor methods both scenes with driven rotors generate (`#[top]` and `#[free]`):
//! the motors' names and one call per motor, so a run can name the motor whose torque is
//! not finite.

use proc_macro2::TokenStream;
use quote::{quote, quote_spanned};
use syn::spanned::Spanned;

/// `MOTORS` and `motor_torques` of the scene's dynamics trait over a state of `n` slots:
/// each motor function first bound to the documented pointer type
/// `fn(&Self, f64, &[f64]) -> f64`, spanned on its path, so a function of another signature
/// is one error there; its value written to `__out[k]`.
pub fn motor_methods<'a>(
    motors: impl Iterator<Item = &'a syn::Path> + Clone,
    n: usize,
) -> TokenStream {
    let names = motors
        .clone()
        .map(|path| quote!(#path).to_string().replace(' ', ""));
    let calls = motors.enumerate().map(|(k, path)| {
        let bind = quote_spanned! {path.span()=>
            let __motor: fn(&Self, f64, &[f64]) -> f64 = #path;
        };
        quote! {
            #bind
            if let ::core::option::Option::Some(__o) = __out.get_mut(#k) {
                *__o = __motor(self, t, &state[..]);
            }
        }
    });
    quote! {
        const MOTORS: &'static [&'static str] = &[#(#names),*];

        #[inline]
        fn motor_torques(&self, t: f64, state: &[f64; #n], __out: &mut [f64]) {
            #(#calls)*
        }
    }
}
