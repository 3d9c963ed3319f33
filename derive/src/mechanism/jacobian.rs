//! `acceleration_jacobian` of the mechanism derive: ∂q̈/∂q and ∂q̈/∂q̇ differentiated exactly
//! by the engine and lowered with shared subexpressions. Emitted for the symbolic and
//! factored routes; the recursive route (large chains, where the differentiated recursion
//! would multiply the expansion) keeps the trait's default, central differences. With
//! user-function efforts τ (`effort = f`, opaque to the differentiation) the derivatives
//! are taken with τ held at its values and completed by the chain rule, + (∂q̈/∂τ)
//! (∂τ/∂(q, q̇)): ∂q̈/∂τ exact (M⁻¹ times the generalised force of a unit effort), only
//! ∂τ/∂(q, q̇) differenced, of the user functions alone (`effort_jacobian`).

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
    if derivation.route == Route::Recursive {
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
    let efforts = &checked.efforts;
    let value = if efforts.is_empty() {
        quote!(::core::result::Result::Ok(__jacobian))
    } else {
        // ∂q̈ᵢ/∂τ_k, row-major, and the chain rule's term added to each block.
        let np = efforts.len();
        let zero = arena.zero();
        let inputs: Vec<_> = efforts.iter().map(|e| arena.as_symbol(e.symbol)).collect();
        let by_effort: Vec<ExprId> = derivation
            .accelerations
            .iter()
            .flat_map(|&a| inputs.iter().map(move |&s| (a, s)))
            .map(|(a, s)| s.map_or(zero, |s| arena.diff(a, s)))
            .collect();
        let by_effort = method.body(arena, &by_effort, |o| quote!([#(#o),*]));
        let calls = efforts.iter().map(|e| {
            let path = &e.path;
            quote!(#path(self, t, q, qdot))
        });
        quote! {{
            let __by_effort: [f64; #n * #np] = #by_effort;
            let (__tau_q, __tau_qdot) = #p::effort_jacobian::<#n, #np>(
                |q: &[f64; #n], qdot: &[f64; #n]| [#(#calls),*],
                q,
                qdot,
            )?;
            let (mut __by_q, mut __by_qdot) = __jacobian;
            for __i in 0..#n {
                for __k in 0..#np {
                    let __g = __by_effort[__i * #np + __k];
                    for __j in 0..#n {
                        __by_q[__i][__j] += __g * __tau_q[(__k, __j)];
                        __by_qdot[__i][__j] += __g * __tau_qdot[(__k, __j)];
                    }
                }
            }
            ::core::result::Result::Ok((__by_q, __by_qdot))
        }}
    };
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
            let __jacobian: ([[f64; #n]; #n], [[f64; #n]; #n]) = #body;
            #value
        }
    }
}
