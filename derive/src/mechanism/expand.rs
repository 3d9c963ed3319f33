//! Expansion of `#[derive(Mechanism)]`: the scene derived by precess-core (q̈ by the route
//! it picks, the pivots that say whether M is regular, T, V, the power and the cyclic
//! momenta), each method one straight-line block, quoted into `impl MechanismDynamics<N>`,
//! the ODE `System<2N>` on the struct, and a const per coordinate.

use std::collections::HashSet;

use precess_core::codegen::Emitted;
use precess_core::lagrange::Coordinates;
use precess_core::mechanism::MechanismDerivation;
use precess_core::sym::{Arena, ExprId, SymbolId};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::{Ident, LitStr};

use super::check::{CheckedMechanism, UserEffort};
use crate::lang::ctxt::Ctxt;
use crate::lang::expansion::{Expansion, cannot_derive};
use crate::lang::private::Private;
use crate::lang::symbols::{FieldParameters, Lowering};
use crate::lang::variational::VariationalKey;

mod charts;
mod loops;
mod rolling;

/// Past this many operations q̈ and its pivots are emitted once, in a function the checked
/// and the unchecked method share (a 10-link chain's are about 2 000).
const SHARED_QDD_OPS: usize = 1024;

/// `impl MechanismDynamics<N>` and the rest, or `None` after recording why the equations
/// could not be derived.
pub fn expand(
    ex: &mut Expansion,
    checked: &CheckedMechanism,
    taylor: Option<usize>,
    variational: Option<&VariationalKey>,
) -> Option<TokenStream> {
    if let Some(rolling) = &checked.rolling {
        return rolling::expand(ex, checked, rolling);
    }
    if let Some((_, closes)) = checked.loops.first() {
        // Taylor coefficients and variational equations are of an unconstrained q̈.
        if taylor.is_some() || variational.is_some() {
            ex.cx.error_spanned_by(
                &closes.key,
                "`closes` cannot be used with `taylor` or `variational(...)` on `#[mechanism]`: their equations are the tree's, without the loop",
            );
            return None;
        }
        return loops::expand(ex, checked);
    }
    let (cx, ident, parameters, arena) = ex.split();
    let p = Private;
    let route = checked.route;
    let derivation = match checked.scene.derive(arena, route) {
        Ok(d) => d,
        Err(e) => {
            cannot_derive(cx, ident, "the mechanism's equations of motion", &e);
            return None;
        }
    };
    let taylor = taylor.map(|k| taylor_system(cx, ident, arena, parameters, &derivation, k));
    let inputs = effort_inputs(&checked.efforts);
    let taylor = crate::lang::export::mechanism(ident, arena, (&derivation, &inputs), taylor);
    let variational = variational
        .map(|key| super::variational::expand(cx, ident, arena, parameters, &derivation, key));
    let n = checked.coordinates.len();
    let s = 2 * n;
    let mut symbols = parameters.tokens();
    for effort in &checked.efforts {
        let local = local_of(effort);
        symbols.insert_expr(arena, effort.symbol, quote!(#local));
    }
    let low = Lowering::new(cx, ident, symbols);
    let method = Method {
        low: &low,
        coordinates: &derivation.coordinates,
        time: derivation.time,
        efforts: &checked.efforts,
    };
    let MechanismDerivation {
        accelerations,
        pivots,
        kinetic,
        potential,
        power,
        conserved_momenta,
        ..
    } = &derivation;
    let checked_outputs: Vec<ExprId> = pivots.iter().chain(accelerations).copied().collect();
    let np = pivots.len();
    // A large q̈ is emitted once, in a function both the checked and the unchecked method
    // call, instead of once in each: rustc and LLVM then compile it once (half the build of
    // a long chain), and one call is nothing next to its thousands of operations. A small
    // one stays in both, where inlining it is worth more than the build time it costs.
    let shared = precess_core::codegen::Program::lower(arena, &checked_outputs)
        .op_count()
        .total()
        > SHARED_QDD_OPS;
    let pivot_checks = quote! {
            for (__k, &__v) in __pivots.iter().enumerate() {
                // Not `__v <= 0.0`: a NaN pivot is no regular mass matrix either.
                if !(__v > 0.0) {
                    return ::core::result::Result::Err(#p::MechanismError::SingularMassMatrix { pivot: __k, value: __v });
                }
            }
            if !__a.iter().all(|__v| __v.is_finite()) {
                return ::core::result::Result::Err(#p::MechanismError::NonFinite {
                    quantity: "accelerations",
                    values: __a.to_vec(),
                });
            }
            ::core::result::Result::Ok(__a)
    };
    let both = quote!(<#ident as __PrecessQdd>::__pivots_and_accelerations(self, t, q, qdot));
    let (shared_fn, checked_body, unchecked) = if shared {
        let body = method.body(arena, &checked_outputs, |o| {
            let (pv, acc) = o.split_at(np.min(o.len()));
            quote!(([#(#pv),*], [#(#acc),*]))
        });
        let shared_fn = quote! {
            trait __PrecessQdd {
                fn __pivots_and_accelerations(&self, t: f64, q: &[f64; #n], qdot: &[f64; #n]) -> ([f64; #np], [f64; #n]);
            }
            #[automatically_derived]
            #[allow(unused_variables, clippy::all, clippy::pedantic, clippy::nursery, unused_parens)]
            impl __PrecessQdd for #ident {
                #[inline(never)]
                fn __pivots_and_accelerations(&self, t: f64, q: &[f64; #n], qdot: &[f64; #n]) -> ([f64; #np], [f64; #n]) #body
            }
        };
        let checked = quote!({
            let (__pivots, __a): ([f64; #np], [f64; #n]) = #both;
            #pivot_checks
        });
        (shared_fn, checked, quote!({ #both.1 }))
    } else {
        let checked = method.body(arena, &checked_outputs, |o| {
            let (pv, acc) = o.split_at(np.min(o.len()));
            quote! {
                let __pivots: [f64; #np] = [#(#pv),*];
                let __a: [f64; #n] = [#(#acc),*];
                #pivot_checks
            }
        });
        let unchecked = method.body(arena, accelerations, |o| quote!([#(#o),*]));
        (TokenStream::new(), checked, unchecked)
    };
    let kinetic = method.body(arena, &[*kinetic], |o| quote!(#(#o)*));
    let potential = method.body(arena, &[*potential], |o| quote!(#(#o)*));
    let power = method.body(arena, &[*power], |o| quote!(#(#o)*));
    let cyclic_exprs: Vec<ExprId> = conserved_momenta.iter().map(|&(_, e)| e).collect();
    let cyclic_index: Vec<usize> = conserved_momenta.iter().map(|&(i, _)| i).collect();
    let cyclic = method.body(arena, &cyclic_exprs, |o| {
        let sets = cyclic_index
            .iter()
            .zip(o)
            .map(|(i, v)| quote!(__m[#i] = ::core::option::Option::Some(#v);));
        quote! {
            let mut __m: [::core::option::Option<f64>; #n] = [::core::option::Option::None; #n];
            #(#sets)*
            __m
        }
    });
    let names = checked
        .coordinates
        .iter()
        .map(|c| LitStr::new(&c.to_string(), c.span()));
    let consts = coordinate_consts(checked, "q and q̇ (and of q̈)");
    let check_parameters = super::parameters::method(&low, arena, checked);
    let jacobian = super::jacobian::method(&method, arena, checked, &derivation);
    let poses = super::poses::expand(cx, ident, arena, &method, checked, &derivation.coordinates);
    let route_name = derivation.route.name();
    let (q_of_y, qdot_of_y): (Vec<TokenStream>, Vec<TokenStream>) = (0..n)
        .map(|k| {
            let j = k + n;
            (quote!(y[#k]), quote!(y[#j]))
        })
        .unzip();
    let dydt = (0..n)
        .map(|k| {
            let j = k + n;
            quote!(y[#j])
        })
        .chain((0..n).map(|k| quote!(__a[#k])));
    let charts = charts::expand_charts(cx, ident, arena, &low, checked, route)?;
    Some(quote! {
        #taylor

        #variational

        #[automatically_derived]
        impl #ident {
            #(#consts)*
        }

        // A block, so the shared q̈'s trait is seen by no other code.
        const _: () = {
        #shared_fn

        #[automatically_derived]
        #[allow(unused_variables, clippy::all, clippy::pedantic, clippy::nursery, unused_parens)]
        impl #p::MechanismDynamics<#n> for #ident {
            const COORDINATES: [&'static str; #n] = [#(#names),*];
            const ROUTE: &'static str = #route_name;

            fn accelerations(&self, t: f64, q: &[f64; #n], qdot: &[f64; #n]) -> ::core::result::Result<[f64; #n], #p::MechanismError> {
                if !(t.is_finite() && q.iter().chain(qdot.iter()).all(|__v| __v.is_finite())) {
                    let mut __values = [t].to_vec();
                    __values.extend_from_slice(q);
                    __values.extend_from_slice(qdot);
                    return ::core::result::Result::Err(#p::MechanismError::NonFinite {
                        quantity: "time, coordinates or rates",
                        values: __values,
                    });
                }
                #p::MechanismDynamics::<#n>::check_parameters(self)?;
                #checked_body
            }

            #[inline]
            fn accelerations_unchecked(&self, t: f64, q: &[f64; #n], qdot: &[f64; #n]) -> [f64; #n] #unchecked

            fn kinetic(&self, q: &[f64; #n], qdot: &[f64; #n]) -> f64 #kinetic

            fn potential(&self, q: &[f64; #n]) -> f64 #potential

            fn power(&self, t: f64, q: &[f64; #n], qdot: &[f64; #n]) -> f64 #power

            fn conserved_momenta(&self, q: &[f64; #n], qdot: &[f64; #n]) -> [::core::option::Option<f64>; #n] #cyclic

            #check_parameters

            #jacobian
        }
        };

        #[automatically_derived]
        impl #p::System<#s> for #ident {
            #[inline]
            fn rhs(&self, t: f64, y: &[f64; #s], dydt: &mut [f64; #s]) {
                let __a = #p::MechanismDynamics::<#n>::accelerations_unchecked(
                    self, t, &[#(#q_of_y),*], &[#(#qdot_of_y),*],
                );
                *dydt = [#(#dydt),*];
            }

            fn check_parameters(&self) -> ::core::result::Result<(), #p::OdeError> {
                #p::MechanismDynamics::<#n>::check_parameters(self)
                    .map_err(#p::MechanismError::into_ode_error)
            }
        }

        #poses

        #charts
    })
}

/// The lowering of a mechanism's methods: the fields by `parameters`, each user effort's
/// value by the local its call is bound to.
pub(super) fn effort_lowering<'a>(
    cx: &'a Ctxt,
    ident: &'a Ident,
    parameters: &FieldParameters,
    arena: &mut Arena,
    efforts: &[UserEffort],
) -> Lowering<'a> {
    let mut symbols = parameters.tokens();
    for effort in efforts {
        let local = local_of(effort);
        symbols.insert_expr(arena, effort.symbol, quote!(#local));
    }
    Lowering::new(cx, ident, symbols)
}

/// `(M, f)` of `eqs` as an `(SMatrix<n, n>, SVector<n>)`, one straight-line block.
pub(super) fn mass_forcing(
    method: &Method,
    arena: &mut Arena,
    eqs: &precess_core::lagrange::EquationsOfMotion,
) -> TokenStream {
    let (p, n) = (Private, eqs.coords.len());
    let dynamics = eqs.mass_then_forcing();
    method.body(arena, &dynamics, |o| {
        let (mm, f) = o.split_at((n * n).min(o.len()));
        quote! {(
            #p::SMatrix::<f64, #n, #n>::from_row_slice(&[#(#mm),*]),
            #p::SVector::<f64, #n>::from_column_slice(&[#(#f),*]),
        )}
    })
}

/// The user efforts' values, the inputs of the export (its caller supplies them): `effort_k`,
/// k counting the `effort = f` functions as declared.
pub(super) fn effort_inputs(efforts: &[UserEffort]) -> crate::lang::export::Inputs {
    efforts
        .iter()
        .map(|e| (e.symbol, format!("effort_{}", e.index)))
        .collect()
}

/// The local a user effort's value is held in.
fn local_of(effort: &UserEffort) -> Ident {
    format_ident!("__effort_{}", effort.index)
}

/// The symbols `outputs` read, looking through bound intermediates (the recursive route's
/// abbreviations, leaves to `free_symbols`) to their definitions, as the lowering does.
pub(super) fn symbols_read(arena: &Arena, outputs: &[ExprId]) -> HashSet<SymbolId> {
    let mut read = HashSet::new();
    let mut pending: Vec<ExprId> = outputs.to_vec();
    while let Some(e) = pending.pop() {
        for s in arena.free_symbols(e) {
            if read.insert(s) {
                pending.extend(arena.definition(s));
            }
        }
    }
    read
}

/// A const per coordinate, named after it in capitals, its index in `arrays` (the arrays the
/// trait's methods take, `q and q̇`).
pub(super) fn coordinate_consts(checked: &CheckedMechanism, arrays: &str) -> Vec<TokenStream> {
    let consts = checked.coordinates.iter().enumerate().map(|(k, c)| {
        let upper = format_ident!("{}", c.to_string().to_uppercase(), span = c.span());
        let doc = format!("The index of the coordinate `{c}` in {arrays}.");
        quote! {
            #[doc = #doc]
            pub const #upper: usize = #k;
        }
    });
    consts.collect()
}

/// Lowers one method's outputs over `t`, `q` and `qdot`.
pub(super) struct Method<'a> {
    pub(super) low: &'a Lowering<'a>,
    /// q and q̇, read from `q` and `qdot`.
    pub(super) coordinates: &'a Coordinates,
    /// The time symbol, read from `t`.
    pub(super) time: ExprId,
    pub(super) efforts: &'a [UserEffort],
}

impl<'a> Method<'a> {
    /// The lowering of methods over `coordinates` and `time`, calling `efforts`.
    pub(super) fn new(
        low: &'a Lowering<'a>,
        coordinates: &'a Coordinates,
        time: ExprId,
        efforts: &'a [UserEffort],
    ) -> Method<'a> {
        Method {
            low,
            coordinates,
            time,
            efforts,
        }
    }

    /// `{ user calls; lets; build(outputs) }`.
    pub(super) fn body(
        &self,
        arena: &mut Arena,
        outputs: &[ExprId],
        build: impl FnOnce(&[TokenStream]) -> TokenStream,
    ) -> TokenStream {
        let c = self.coordinates;
        let mut reads: Vec<(ExprId, TokenStream)> = Vec::new();
        for (k, (&q, &v)) in c.q.iter().zip(&c.rates).enumerate() {
            reads.push((q, quote!(q[#k])));
            reads.push((v, quote!(qdot[#k])));
        }
        // q̈ is read only by the rolling `partials` (∂(M a)/∂q at a = q̈).
        for (k, &a) in c.accels.iter().enumerate() {
            reads.push((a, quote!(qddot[#k])));
        }
        reads.push((self.time, quote!(t)));
        let read = symbols_read(arena, outputs);
        // A user function is called only by the methods whose result reads its value.
        let calls = self.efforts.iter().filter_map(|e| {
            let s = arena.as_symbol(e.symbol)?;
            read.contains(&s).then(|| {
                let (local, path) = (local_of(e), &e.path);
                quote!(let #local: f64 = #path(self, t, q, qdot);)
            })
        });
        let calls: TokenStream = calls.collect();
        let Emitted { lets, outputs } = self.low.lower_reading(arena, outputs, &reads);
        let out = build(&outputs);
        quote!({ #calls #lets #out })
    }
}

/// `taylor = K`: `impl TaylorSystem<2n>` for the first-order system `(q, q̇)' = (q̇, q̈)` of
/// the route's q̈, over the state `[q, q̇]`, reading the fields as the other methods do.
fn taylor_system(
    cx: &Ctxt,
    ident: &Ident,
    arena: &Arena,
    parameters: &FieldParameters,
    derivation: &MechanismDerivation,
    order: usize,
) -> TokenStream {
    let (state, rhs) = derivation.first_order_system();
    let symbols = parameters.tokens();
    let (p, n) = (Private, state.len() / 2);
    crate::lang::taylor::expand(
        cx,
        ident,
        arena,
        &symbols,
        &state,
        &rhs,
        TokenStream::new(),
        order,
        Some(quote!(#p::MechanismDynamics::<#n>::check_parameters(self)
            .map_err(#p::MechanismError::into_ode_error))),
    )
}
