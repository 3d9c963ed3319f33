//! Expansion of `#[rigid]`: the checked body's expressions lowered by precess-core's code
//! generator and quoted into a `RigidBody` impl (and, with `taylor = K`, the impls of
//! `expand/euler.rs`). Constants become literals; a field becomes
//! `self.field`; generated code names everything through the hidden path.

use precess_core::body::{Description, Frame};
use precess_core::codegen::{Emitted, f64_literal};
use precess_core::sym::{Arena, ExprId};
use proc_macro2::TokenStream;
use quote::quote;

use super::check::CheckedBody;
use crate::lang::expansion::Expansion;
use crate::lang::private::Private;
use crate::lang::symbols::Lowering;
use crate::lang::tokens::{orientation, shape};

mod euler;

/// A constant whose exact value did not fold to one rational (an overflow kept it as a
/// product) is rounded to one literal, so a body of literals never computes at run time.
fn fold_constants(arena: &mut Arena, outputs: &[ExprId]) -> Vec<ExprId> {
    outputs
        .iter()
        .map(|&e| {
            if arena.as_rational(e).is_some() || !arena.free_symbols(e).is_empty() {
                return e;
            }
            let v = arena.eval(e, &[]);
            arena.float(v).unwrap_or(e)
        })
        .collect()
}

/// Lowers `outputs` with constants folded.
fn emit(low: &Lowering, arena: &mut Arena, outputs: &[ExprId]) -> Emitted {
    let folded = fold_constants(arena, outputs);
    low.lower(arena, &folded)
}

/// A method body: the `let`s, then `build` applied to the output expressions.
fn method_body(
    low: &Lowering,
    arena: &mut Arena,
    outputs: &[ExprId],
    build: impl FnOnce(&[TokenStream]) -> TokenStream,
) -> TokenStream {
    let Emitted { lets, outputs } = emit(low, arena, outputs);
    let out = build(&outputs);
    quote! { #lets #out }
}

fn vector(o: &[TokenStream]) -> TokenStream {
    quote!(#Private::Vector3::new(#(#o),*))
}

fn matrix(o: &[TokenStream]) -> TokenStream {
    quote!(#Private::Matrix3::new(#(#o),*))
}

/// `impl RigidBody for …`, or `None` after recording why Euler's equations could not be
/// formed.
pub fn expand(ex: &mut Expansion, checked: &CheckedBody) -> Option<TokenStream> {
    let (cx, ident, parameters) = (ex.cx, ex.ident, ex.parameters);
    let arena = &mut *ex.arena;
    let p = Private;
    let omega_in = [
        arena.input("omega_1"),
        arena.input("omega_2"),
        arena.input("omega_3"),
    ];
    let torque_in = [arena.input("G_1"), arena.input("G_2"), arena.input("G_3")];
    let mut symbols = parameters.tokens();
    for (i, (&w, &g)) in omega_in.iter().zip(&torque_in).enumerate() {
        symbols.insert_expr(arena, w, quote!(omega[#i]));
        symbols.insert_expr(arena, g, quote!(torque[#i]));
    }
    let low = Lowering::new(cx, ident, symbols);
    let props = &checked.body.props;
    let mass = method_body(&low, arena, &[props.mass], |o| quote!(#(#o)*));
    let center = method_body(&low, arena, &props.center, vector);
    let reference = method_body(&low, arena, &props.reference, vector);
    let inertia = method_body(&low, arena, props.inertia.as_flattened(), matrix);
    let inertia_cm = method_body(&low, arena, props.inertia_cm.as_flattened(), matrix);
    let principal = match &checked.body.frame {
        Frame::Diagonal(m) => method_body(&low, arena, m, |o| {
            let v = vector(o);
            quote!(#p::Principal::diagonal(#v))
        }),
        Frame::Constant(pr) => {
            let m: Vec<TokenStream> = pr.moments.iter().map(|&x| f64_literal(x)).collect();
            let r = pr.rotation.matrix();
            let rows: Vec<TokenStream> = (0..3)
                .flat_map(|i| (0..3).map(move |j| (i, j)))
                .map(|(i, j)| f64_literal(r[(i, j)]))
                .collect();
            let (m, r) = (vector(&m), matrix(&rows));
            quote!(#p::Principal { moments: #m, rotation: #p::Rotation3::from_matrix_unchecked(#r) })
        }
        Frame::DecomposedAtRunTime => quote!(#p::principal_frame(&#p::RigidBody::inertia(self))),
    };
    let rhs = match checked.body.euler_rhs_principal(arena, omega_in, torque_in) {
        Ok(Some(rhs)) => method_body(&low, arena, &rhs, vector),
        Ok(None) => quote! {
            let principal = #p::RigidBody::principal(self);
            #p::euler_rhs_diagonal(&principal.moments, omega, torque)
        },
        Err(e) => {
            cx.error_spanned_by(ident, format!("cannot form Euler's equations: {e}"));
            return None;
        }
    };
    let d = description(&low, arena, &checked.description);
    let validate = if parameters.is_empty() {
        // Literal bodies were checked while expanding.
        quote! {
            fn validate(&self) -> ::core::result::Result<(), #p::BodyError> {
                ::core::result::Result::Ok(())
            }
        }
    } else {
        // The trait's default checks the description built from the fields.
        TokenStream::new()
    };
    // `taylor = K`: the torque-free Euler equations as a system of their own.
    let taylor = checked
        .taylor
        .map(|order| euler::expand(ex, checked, order));
    let taylor = crate::lang::export::body(ex, checked, taylor);
    Some(quote! {
        #taylor

        #[automatically_derived]
        #[allow(clippy::all, clippy::pedantic, clippy::nursery, unused_parens)]
        impl #p::RigidBody for #ident {
            #[inline]
            fn mass(&self) -> f64 { #mass }
            #[inline]
            fn center_of_mass(&self) -> #p::Vector3<f64> { #center }
            #[inline]
            fn reference_point(&self) -> #p::Vector3<f64> { #reference }
            #[inline]
            fn inertia(&self) -> #p::Matrix3<f64> { #inertia }
            #[inline]
            fn inertia_cm(&self) -> #p::Matrix3<f64> { #inertia_cm }
            #[inline]
            fn principal(&self) -> #p::Principal { #principal }
            #[inline]
            fn euler_rhs_principal(&self, omega: &#p::Vector3<f64>, torque: &#p::Vector3<f64>) -> #p::Vector3<f64> { #rhs }
            fn description(&self) -> #p::Description<f64> { #d }
            #validate
        }
    })
}

/// The description as a run-time value, each value an expression of the fields.
pub(crate) fn description(
    low: &Lowering,
    arena: &mut Arena,
    description: &Description<ExprId>,
) -> TokenStream {
    let p = Private;
    let mut all = Vec::new();
    let indexed: Description<usize> = description.map(&mut |&e| {
        all.push(e);
        all.len() - 1
    });
    let Emitted { lets, outputs } = emit(low, arena, &all);
    let d = indexed.map(&mut |&i| outputs.get(i).cloned().unwrap_or_default());
    let parts = d.parts.iter().map(|part| {
        let shape = shape(&part.shape);
        let at = &part.at;
        let orientation = match &part.orientation {
            Some(o) => {
                let o = orientation(o);
                quote!(::core::option::Option::Some(#o))
            }
            None => quote!(::core::option::Option::None),
        };
        quote!(#p::Part { shape: #shape, at: [#(#at),*], orientation: #orientation })
    });
    let pivot = match &d.pivot {
        Some(v) => quote!(::core::option::Option::Some([#(#v),*])),
        None => quote!(::core::option::Option::None),
    };
    quote! {{
        #lets
        #p::Description { parts: #p::vec![#(#parts),*], pivot: #pivot }
    }}
}
