//! Expansion of a mechanism with closed loops (`closes = ..`): the engine's `derive_loops`
//! (M and f of the tree cut open, the closure rows φ, their Jacobian A and Ȧq̇, T + V), each
//! method one straight-line block quoted into `impl LoopDynamics<N, M, K>`, whose provided
//! methods choose the dependent coordinates, project, give the multipliers and close the
//! loop. The closure rule of planar loops is applied here to literal sides (a spanned
//! error) and by the generated `check_parameters` to sides made of fields.

use precess_core::mechanism::MechanismError;
use precess_core::mechanism::loops::{LoopDerivation, check_loop_sides};
use precess_core::sym::{Arena, ExprId};
use proc_macro2::TokenStream;
use quote::quote;
use syn::LitStr;

use super::Method;
use crate::lang::ctxt::Ctxt;
use crate::lang::expansion::{Expansion, cannot_derive};
use crate::lang::private::Private;
use crate::mechanism::check::CheckedMechanism;
use crate::mechanism::closes::CLOSES;

/// `impl LoopDynamics<N, M, K>`, the coordinate consts and the links' poses, or `None` after
/// recording why the loops cannot be derived.
pub(super) fn expand(ex: &mut Expansion, checked: &CheckedMechanism) -> Option<TokenStream> {
    let (cx, ident, parameters, arena) = ex.split();
    let p = Private;
    let closures: Vec<_> = checked.loops.iter().map(|(c, _)| c.clone()).collect();
    let derivation: LoopDerivation = match checked.scene.derive_loops(arena, &closures) {
        Ok(d) => d,
        Err(MechanismError::TooManyClosureRows { rows, coordinates }) => {
            // The last closure is the one past the count.
            let (_, last) = checked.loops.last()?;
            cx.error_spanned_by(
                &last.value,
                format!(
                    "`{CLOSES}` adds too many constraints: the closures hold {rows} components of their points on {coordinates} {}, leaving no free coordinate; give the mechanism more joints or close fewer loops",
                    if coordinates == 1 { "coordinate" } else { "coordinates" }
                ),
            );
            return None;
        }
        Err(e) => {
            cannot_derive(cx, ident, "the closed mechanism's equations of motion", &e);
            return None;
        }
    };
    if !literal_sides(cx, arena, checked, &derivation) {
        return None;
    }
    let coords = derivation.coordinates();
    let (n, m) = (coords.len(), derivation.constraints.len());
    let k = n - m;
    let low = super::effort_lowering(cx, ident, parameters, arena, &checked.efforts);
    let method = Method::new(&low, coords, derivation.time, &checked.efforts);
    let mass_forcing = super::mass_forcing(&method, arena, &derivation.equations);
    let zero = arena.zero();
    let constraints = &derivation.constraints;
    let positions = constraints.positions.iter().map(|h| h.unwrap_or(zero));
    let rows: Vec<ExprId> = positions
        .chain(constraints.coefficients.iter().flatten().copied())
        .collect();
    let closure = method.body(arena, &rows, |o| {
        let (phi, a) = o.split_at(m.min(o.len()));
        quote! {(
            [#(#phi),*],
            #p::SMatrix::<f64, #m, #n>::from_row_slice(&[#(#a),*]),
        )}
    });
    let rate_terms = method.body(
        arena,
        &derivation.rate_terms,
        |o| quote!(#p::SVector::<f64, #m>::from_column_slice(&[#(#o),*])),
    );
    let total = arena.add(derivation.kinetic, derivation.potential);
    let energy = method.body(arena, &[total], |o| quote!(#(#o)*));
    let names = checked
        .coordinates
        .iter()
        .map(|c| LitStr::new(&c.to_string(), c.span()));
    let row_names = derivation
        .rows
        .iter()
        .map(|&(c, axis)| format!("{}.{}", closures[c].name, ["x", "y", "z"][axis]));
    let consts = super::coordinate_consts(checked, "q and q̇");
    let sides: Vec<_> = derivation
        .sides
        .iter()
        .zip(&closures)
        .filter_map(|(s, c)| Some((c.name.clone(), s.clone()?)))
        .collect();
    let check_parameters =
        super::super::parameters::method_with_loops(&low, arena, checked, &sides);
    let poses = super::super::poses::expand(cx, ident, arena, &method, checked, coords);
    let inputs = super::effort_inputs(&checked.efforts);
    let poses = crate::lang::export::closed(ident, arena, (&derivation, &inputs), poses);
    let doc_rows = format!(
        "The closure rows, `body.axis` for the ground-axis component of each closing point's \
         separation: the order of φ, of A's rows and of `multipliers` ({m} rows, {k} free \
         coordinate{})",
        if k == 1 { "" } else { "s" }
    );
    Some(quote! {
        #[automatically_derived]
        impl #ident {
            #(#consts)*
            #[doc = #doc_rows]
            pub const CLOSURE_ROWS: [&'static str; #m] = [#(#row_names),*];
            /// The length of the state [q, q̇]: `LoopDynamics::closed_run` takes it.
            pub const STATE: usize = 2 * #n;
        }

        #[automatically_derived]
        #[allow(unused_variables, clippy::all, clippy::pedantic, clippy::nursery, unused_parens)]
        impl #p::LoopDynamics<#n, #m, #k> for #ident {
            fn closure(&self, q: &[f64; #n]) -> ([f64; #m], #p::SMatrix<f64, #m, #n>) {
                // The closures do not depend on time or rates.
                let (t, qdot) = (0.0_f64, &[0.0_f64; #n]);
                #closure
            }

            fn rate_terms(&self, q: &[f64; #n], qdot: &[f64; #n]) -> #p::SVector<f64, #m> {
                let t = 0.0_f64;
                #rate_terms
            }

            fn mass_forcing(&self, t: f64, q: &[f64; #n], qdot: &[f64; #n]) -> (#p::SMatrix<f64, #n, #n>, #p::SVector<f64, #n>) #mass_forcing

            fn energy(&self, q: &[f64; #n], qdot: &[f64; #n]) -> f64 {
                let t = 0.0_f64;
                #energy
            }

            fn coordinate_names(&self) -> [&'static str; #n] {
                [#(#names),*]
            }

            #check_parameters
        }
        #poses
    })
}

/// The closure rule on every planar loop whose sides are all literals: a loop that cannot
/// close is an error spanned on its `closes = ..` value. False if one failed.
fn literal_sides(
    cx: &Ctxt,
    arena: &Arena,
    checked: &CheckedMechanism,
    derivation: &LoopDerivation,
) -> bool {
    let mut ok = true;
    for ((closure, spec), sides) in checked.loops.iter().zip(&derivation.sides) {
        let Some(sides) = sides else {
            continue;
        };
        let values: Option<Vec<(&str, f64)>> = sides
            .iter()
            .map(|s| {
                let v = arena.as_rational(s.squared)?.to_f64();
                Some((s.body.as_str(), v.max(0.0).sqrt()))
            })
            .collect();
        let Some(values) = values else {
            continue;
        };
        if let Err(e) = check_loop_sides(&closure.name, &values) {
            let listed: Vec<String> = values.iter().map(|(b, l)| format!("{b} {l}")).collect();
            cx.error_spanned_by(
                &spec.value,
                format!("{e} (the loop's sides: {})", listed.join(", ")),
            );
            ok = false;
        }
    }
    ok
}
