//! Expansion of a mechanism whose bodies roll: the engine's `derive_rolling` (M, f, the
//! wheels' rows A and Ȧq̇, heights, tilts, contact velocities, T + V), each method one
//! straight-line block quoted into `impl RollingDynamics<N, M, K>`; the provided methods
//! of the trait finish Maggi's projection numerically. `partials` gives the engine's
//! derivatives of M, f, A and Ȧq̇, from which the trait's `acceleration_jacobian` is
//! exact. No `MechanismDynamics` and no `System<2N>`: the state is (q, u), n coordinates
//! and k free speeds, not (q, q̇).

use precess_core::mechanism::MechanismError;
use precess_core::mechanism::rolling::RollingDerivation;
use precess_core::sym::{Arena, ExprId, SymbolId};
use proc_macro2::TokenStream;
use quote::quote;
use syn::LitStr;

use super::Method;
use crate::lang::expansion::{Expansion, cannot_derive};
use crate::lang::private::Private;
use crate::mechanism::check::{CheckedMechanism, UserEffort};
use crate::mechanism::rolling::CheckedRolling;

/// `impl RollingDynamics<N, M, K>`, the coordinate consts and `STATE`, or `None` after
/// recording why the equations could not be derived (the wrong number of free speeds is
/// spanned on `speeds`).
pub(super) fn expand(
    ex: &mut Expansion,
    checked: &CheckedMechanism,
    rolling: &CheckedRolling,
) -> Option<TokenStream> {
    let (cx, ident, parameters, arena) = ex.split();
    let p = Private;
    let derivation: RollingDerivation = match checked.scene.derive_rolling(arena, &rolling.scene) {
        Ok(d) => d,
        Err(MechanismError::SpeedCount {
            got,
            coordinates,
            rows,
        }) => {
            cx.error_spanned_by(
                &rolling.speeds,
                format!(
                    "the wheels give {} on {}, leaving {} free: `speeds` must name that many coordinates, and names {got}",
                    counted(rows, "constraint row"),
                    counted(coordinates, "coordinate"),
                    counted(coordinates.saturating_sub(rows), "speed"),
                ),
            );
            return None;
        }
        Err(e @ MechanismError::UnknownSpeed { .. }) => {
            cx.error_spanned_by(&rolling.speeds, e);
            return None;
        }
        Err(e) => {
            cannot_derive(cx, ident, "the rolling mechanism's equations of motion", &e);
            return None;
        }
    };
    let coords = derivation.coordinates();
    let (n, m, k) = (
        coords.len(),
        derivation.rows(),
        derivation.independent.len(),
    );
    let wheels = derivation.tilts.len();
    let low = super::effort_lowering(cx, ident, parameters, arena, &checked.efforts);
    let method = Method::new(&low, coords, derivation.time, &checked.efforts);
    let mass_forcing = super::mass_forcing(&method, arena, &derivation.equations);
    let rows: Vec<ExprId> = derivation
        .constraints
        .coefficients
        .iter()
        .flatten()
        .chain(&derivation.rate_terms)
        .copied()
        .collect();
    let constraint_rows = method.body(arena, &rows, |o| {
        let (a, r) = o.split_at((m * n).min(o.len()));
        quote! {(
            #p::SMatrix::<f64, #m, #n>::from_row_slice(&[#(#a),*]),
            #p::SVector::<f64, #m>::from_column_slice(&[#(#r),*]),
        )}
    });
    // The exact derivatives the Jacobian of u̇ is assembled from; with user efforts, their
    // values held, plus the chain rule's G ∂τ/∂(q, q̇) where only τ is differenced.
    let partials = partials_method(&method, arena, &derivation, &checked.efforts);
    let zero = arena.zero();
    let heights: Vec<ExprId> = derivation
        .constraints
        .positions
        .iter()
        .map(|h| h.unwrap_or(zero))
        .collect();
    let heights = method.body(arena, &heights, |o| quote!([#(#o),*]));
    let holonomic = derivation.constraints.positions.iter().map(Option::is_some);
    let tilts = method.body(arena, &derivation.tilts, |o| {
        quote! {
            let __tilts: [f64; #wheels] = [#(#o),*];
            // The smallest, or the first NaN: a NaN tilt is no standing wheel either.
            __tilts.iter().copied().enumerate().fold((0, f64::INFINITY), |__best, (__i, __v)| {
                if __v < __best.1 || __v.is_nan() { (__i, __v) } else { __best }
            })
        }
    });
    let total = arena.add(derivation.kinetic, derivation.potential);
    let energy = method.body(arena, &[total], |o| quote!(#(#o)*));
    let velocities: Vec<ExprId> = derivation
        .contact_velocities
        .iter()
        .flatten()
        .copied()
        .collect();
    let contact_speed = method.body(arena, &velocities, |o| {
        let speeds = o.chunks(3).map(|v| quote!((#(#v * #v)+*).sqrt()));
        quote!([#(#speeds),*].iter().copied().fold(0.0_f64, f64::max))
    });
    let names: Vec<LitStr> = checked
        .coordinates
        .iter()
        .map(|c| LitStr::new(&c.to_string(), c.span()))
        .collect();
    let independent = &derivation.independent;
    let dependent = &derivation.dependent;
    let consts = super::coordinate_consts(checked, "q and q̇");
    let state = n + k;
    let state_doc = format!(
        "The length of the rolling state (q, u): {n} coordinates, then the {k} free speeds; \
         `model.rolling_system::<{{{ident}::STATE}}>()` is the ODE system over it."
    );
    let check_parameters = super::super::parameters::method(&low, arena, checked);
    // The links' poses at q, as the tree mechanisms give them (`precess::animate::mechanism`
    // draws a rolling mechanism from them): q is the first n slots of the rolling state.
    let poses = super::super::poses::expand(cx, ident, arena, &method, checked, coords);
    let inputs = super::effort_inputs(&checked.efforts);
    let poses = crate::lang::export::rolling(ident, arena, (&derivation, &inputs), poses);
    Some(quote! {
        #[automatically_derived]
        impl #ident {
            #(#consts)*
            #[doc = #state_doc]
            pub const STATE: usize = #state;
            /// The coordinates whose rates are the free speeds u, in the state's order.
            pub const SPEEDS: [usize; #k] = [#(#independent),*];
        }

        #[automatically_derived]
        #[allow(unused_variables, clippy::all, clippy::pedantic, clippy::nursery, unused_parens)]
        impl #p::RollingDynamics<#n, #m, #k> for #ident {
            fn partition(&self) -> #p::Partition<#m, #k> {
                #p::Partition {
                    independent: [#(#independent),*],
                    dependent: [#(#dependent),*],
                }
            }

            fn coordinate_names(&self) -> [&'static str; #n] {
                [#(#names),*]
            }

            fn mass_forcing(&self, t: f64, q: &[f64; #n], qdot: &[f64; #n]) -> (#p::SMatrix<f64, #n, #n>, #p::SVector<f64, #n>) #mass_forcing

            fn constraint_rows(&self, q: &[f64; #n], qdot: &[f64; #n]) -> (#p::SMatrix<f64, #m, #n>, #p::SVector<f64, #m>) {
                // The wheels' rows do not depend on time.
                let t = 0.0_f64;
                #constraint_rows
            }

            #partials

            fn holonomic_rows(&self) -> [bool; #m] {
                [#(#holonomic),*]
            }

            fn heights(&self, q: &[f64; #n]) -> [f64; #m] {
                let (t, qdot) = (0.0_f64, &[0.0_f64; #n]);
                #heights
            }

            fn lowest_tilt(&self, q: &[f64; #n]) -> (usize, f64) {
                let (t, qdot) = (0.0_f64, &[0.0_f64; #n]);
                #tilts
            }

            fn energy(&self, q: &[f64; #n], qdot: &[f64; #n]) -> f64 {
                let t = 0.0_f64;
                #energy
            }

            fn contact_speed(&self, q: &[f64; #n], qdot: &[f64; #n]) -> f64 {
                let t = 0.0_f64;
                #contact_speed
            }

            #check_parameters
        }
        #poses
    })
}

/// `fn partials`: the engine's derivatives of M q̈, f, A and Ȧq̇ with the user efforts τ held
/// at their values, f's then completed by the chain rule, ∂f/∂q += G ∂τ/∂q and ∂f/∂q̇ +=
/// G ∂τ/∂q̇, G = ∂f/∂τ exact (the generalised force of a unit of each effort) and ∂τ/∂(q, q̇)
/// differences of the user functions alone (`effort_jacobian`; a failure there leaves NaN,
/// which `acceleration_jacobian` reports). Nothing (the trait's `None`, every entry
/// differenced) where M, A or Ȧq̇ would read an effort, which a force cannot make them do.
fn partials_method(
    method: &Method,
    arena: &mut Arena,
    derivation: &RollingDerivation,
    efforts: &[UserEffort],
) -> TokenStream {
    let p = Private;
    let (n, m) = (derivation.coordinates().len(), derivation.rows());
    let inputs: Vec<Option<SymbolId>> = efforts.iter().map(|e| arena.as_symbol(e.symbol)).collect();
    let not_forcing: Vec<ExprId> = derivation
        .equations
        .mass
        .iter()
        .flatten()
        .chain(derivation.constraints.coefficients.iter().flatten())
        .chain(&derivation.rate_terms)
        .copied()
        .collect();
    if !efforts.is_empty() {
        let read = super::symbols_read(arena, &not_forcing);
        if inputs.iter().flatten().any(|s| read.contains(s)) {
            return TokenStream::new();
        }
    }
    let entries = derivation.partials(arena);
    let body = method.body(
        arena,
        &entries,
        |o| quote!(#p::RollingPartials::<#n, #m>::from_slice(&[#(#o),*])),
    );
    let value = if efforts.is_empty() {
        body
    } else {
        let np = efforts.len();
        let zero = arena.zero();
        let g: Vec<ExprId> = derivation
            .equations
            .forcing
            .iter()
            .flat_map(|&f| inputs.iter().map(move |&s| (f, s)))
            .map(|(f, s)| s.map_or(zero, |s| arena.diff(f, s)))
            .collect();
        let g = method.body(
            arena,
            &g,
            |o| quote!(#p::SMatrix::<f64, #n, #np>::from_row_slice(&[#(#o),*])),
        );
        let calls = efforts.iter().map(|e| {
            let path = &e.path;
            quote!(#path(self, t, q, qdot))
        });
        quote! {{
            let mut __partials: #p::RollingPartials<#n, #m> = #body;
            let __g: #p::SMatrix<f64, #n, #np> = #g;
            let (__by_q, __by_qdot) = #p::effort_jacobian::<#n, #np>(
                |q: &[f64; #n], qdot: &[f64; #n]| [#(#calls),*],
                q,
                qdot,
            )
            .unwrap_or((
                #p::SMatrix::<f64, #np, #n>::from_element(f64::NAN),
                #p::SMatrix::<f64, #np, #n>::from_element(f64::NAN),
            ));
            __partials.forcing_by_q += __g * __by_q;
            __partials.forcing_by_qdot += __g * __by_qdot;
            __partials
        }}
    };
    quote! {
        fn partials(&self, t: f64, q: &[f64; #n], qdot: &[f64; #n], qddot: &[f64; #n]) -> ::core::option::Option<#p::RollingPartials<#n, #m>> {
            ::core::option::Option::Some(#value)
        }
    }
}

/// `1 row`, `2 rows`.
fn counted(n: usize, what: &str) -> String {
    if n == 1 {
        format!("{n} {what}")
    } else {
        format!("{n} {what}s")
    }
}
