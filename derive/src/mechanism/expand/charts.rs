//! The chart variants of a mechanism with spherical joints: `impl ChartedDynamics<2N>`, with
//! q̈ and the energy of each chart set of `chart_variants` (the scene with the switched
//! joints' sequences swapped, derived again by the same route), selected by a `match` on the
//! chart set. Nothing is emitted for a mechanism without spherical joints.
//!
//! A mechanism with user functions gets only its declared charts: a function receives q and
//! q̇, and would read a switched joint's partner angles as if they were the declared ones.

use precess_core::mechanism::charts::{chart_variants, scene_in_charts, spherical_joints};
use precess_core::mechanism::{MechanismDerivation, Route};
use precess_core::rigid::AngleSequence;
use precess_core::sym::Arena;
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

use super::{CheckedMechanism, Method};
use crate::lang::ctxt::Ctxt;
use crate::lang::private::Private;
use crate::lang::symbols::Lowering;

/// `impl ChartedDynamics<2N>` for a mechanism with spherical joints (empty otherwise), or
/// `None` after recording why a chart's equations could not be derived.
pub(super) fn expand_charts(
    cx: &Ctxt,
    ident: &Ident,
    arena: &mut Arena,
    low: &Lowering,
    checked: &CheckedMechanism,
    route: Route,
) -> Option<TokenStream> {
    let p = Private;
    let joints = spherical_joints(&checked.scene);
    if joints.is_empty() {
        return Some(TokenStream::new());
    }
    let n = checked.coordinates.len();
    let s = 2 * n;
    let user_functions = !checked.efforts.is_empty();
    let switchable: Vec<bool> = joints
        .iter()
        .map(|j| j.switchable && !user_functions)
        .collect();
    let mut accel_arms = Vec::new();
    let mut energy_arms = Vec::new();
    let mut bits = Vec::new();
    for charts in chart_variants(&switchable) {
        let b = charts.0;
        bits.push(b);
        if b == 0 {
            continue;
        }
        let scene = scene_in_charts(&checked.scene, charts);
        let derivation: MechanismDerivation = match scene.derive(arena, route) {
            Ok(d) => d,
            Err(e) => {
                cx.error_spanned_by(
                    ident,
                    format!("cannot derive the mechanism in its chart set {b:#b}: {e}"),
                );
                return None;
            }
        };
        let method = Method {
            low,
            coordinates: &derivation.coordinates,
            time: derivation.time,
            efforts: &[],
        };
        let accel = method.body(arena, &derivation.accelerations, |o| quote!([#(#o),*]));
        let energy = method.body(arena, &[derivation.energy], |o| quote!(#(#o)*));
        accel_arms.push(quote!(#b => #accel,));
        energy_arms.push(quote!(#b => #energy,));
    }
    let joint_values = joints.iter().zip(&switchable).map(|(j, &switchable)| {
        let (name, first) = (&j.name, j.first);
        let declared = match j.declared {
            AngleSequence::Zxz => quote!(#p::AngleSequence::Zxz),
            AngleSequence::Zyx => quote!(#p::AngleSequence::Zyx),
        };
        quote! {
            #p::SphericalJoint {
                name: ::std::string::String::from(#name),
                first: #first,
                declared: #declared,
                switchable: #switchable,
            }
        }
    });
    let q = (0..n).map(|k| quote!(y[#k]));
    let qdot = (0..n).map(|k| {
        let j = k + n;
        quote!(y[#j])
    });
    let split = quote! {
        let q: [f64; #n] = [#(#q),*];
        let qdot: [f64; #n] = [#(#qdot),*];
    };
    let dydt = (0..n)
        .map(|k| {
            let j = k + n;
            quote!(y[#j])
        })
        .chain((0..n).map(|k| quote!(__a[#k])));
    Some(quote! {
        #[automatically_derived]
        #[allow(unused_variables, clippy::all, clippy::pedantic, clippy::nursery, unused_parens)]
        impl #p::ChartedDynamics<#s> for #ident {
            fn dof(&self) -> usize {
                #n
            }

            fn spherical_joints(&self) -> #p::vec::Vec<#p::SphericalJoint> {
                #p::vec![#(#joint_values),*]
            }

            fn has_charts(&self, charts: #p::ChartSet) -> bool {
                matches!(charts.0, #(#bits)|*)
            }

            fn rhs_in(&self, charts: #p::ChartSet, t: f64, y: &[f64; #s], dydt: &mut [f64; #s]) {
                #split
                let __a: [f64; #n] = match charts.0 {
                    0 => #p::MechanismDynamics::<#n>::accelerations_unchecked(self, t, &q, &qdot),
                    #(#accel_arms)*
                    _ => [f64::NAN; #n],
                };
                *dydt = [#(#dydt),*];
            }

            fn energy_in(&self, charts: #p::ChartSet, t: f64, y: &[f64; #s]) -> f64 {
                #split
                match charts.0 {
                    0 => #p::MechanismDynamics::<#n>::energy(self, &q, &qdot),
                    #(#energy_arms)*
                    _ => f64::NAN,
                }
            }

            fn check_parameters(&self) -> ::core::result::Result<(), #p::MechanismError> {
                #p::MechanismDynamics::<#n>::check_parameters(self)
            }
        }
    })
}
