//! `acceleration_jacobian` of the mechanism derive: ∂q̈/∂q and ∂q̈/∂q̇ differentiated exactly
//! by the engine and lowered with shared subexpressions. Emitted for the symbolic and
//! factored routes; the recursive route (large chains, where the differentiated recursion
//! would multiply the expansion) and mechanisms with user-function efforts (opaque to the
//! differentiation: their dependence on q and q̇ is unknown) keep the trait's default,
//! central differences.

use precess_core::mechanism::{MechanismDerivation, Route};
use precess_core::sym::{Arena, ExprId};
use proc_macro2::TokenStream;
use quote::quote;

use super::check::CheckedMechanism;
use super::expand::Method;
use crate::lang::private::Private;

/// The method, or nothing where the default applies.
pub fn method(
    method: &Method,
    arena: &mut Arena,
    checked: &CheckedMechanism,
    derivation: &MechanismDerivation,
) -> TokenStream {
    if derivation.route == Route::Recursive || !checked.efforts.is_empty() {
        return TokenStream::new();
    }
    let p = Private;
    let n = derivation.coordinates.len();
    let rows = checked.scene.jacobian(arena, derivation);
    // Rows n..2n are q̈'s; the first n are the identity block of q̇.
    let entries: Vec<ExprId> = rows.iter().skip(n).flatten().copied().collect();
    if entries.len() != 2 * n * n {
        return TokenStream::new();
    }
    let body = method.body(arena, &entries, |o| {
        let block = |offset: usize| {
            let rows = (0..n).map(|i| {
                let row =
                    (0..n).map(|j| o.get(2 * n * i + offset + j).cloned().unwrap_or_default());
                quote!([#(#row),*])
            });
            quote!([#(#rows),*])
        };
        let (by_q, by_qdot) = (block(0), block(n));
        quote!((#by_q, #by_qdot))
    });
    quote! {
        fn acceleration_jacobian(&self, t: f64, q: &[f64; #n], qdot: &[f64; #n]) -> ::core::result::Result<([[f64; #n]; #n], [[f64; #n]; #n]), #p::MechanismError> {
            // The checks of the accelerations: finite state, parameters, regular M.
            #p::MechanismDynamics::<#n>::accelerations(self, t, q, qdot)?;
            ::core::result::Result::Ok(#body)
        }
    }
}
