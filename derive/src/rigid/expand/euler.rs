//! `taylor = K` on `#[rigid(...)]`: the torque-free Euler equations of the body,
//! `ω̇ᵢ = (I_j − I_k)/I_i · ω_j ω_k` over (i, j, k) cyclic, with ω in the principal axes of
//! the reference point (the pivot, or the centre of mass) in the order of
//! `RigidBody::principal`, emitted on the struct as `impl System<3>` (straight-line code) and
//! `impl TaylorSystem<3>` (the recurrences, by the same function as the other scenes'
//! `taylor = K`, `crate::lang::taylor::expand`). Both come from `SymbolicBody::euler_rhs_principal`
//! with a zero torque, the equations `RigidBody::euler_rhs_principal` is generated from.
//!
//! On the struct rather than a wrapper: ω is the body's own state, N = 3 cannot meet a
//! top's `TaylorSystem<6>` or a free body's `<13>`, and `Taylor::new(&body, t0, ω0, cfg)`
//! then reads as what it is. Bodies without the key emit nothing here.

use std::borrow::Cow;

use precess_core::body::Frame;
use precess_core::sym::ExprId;
use proc_macro2::TokenStream;
use quote::quote;

use crate::lang::expansion::Expansion;
use crate::lang::private::Private;
use crate::lang::symbols::Lowering;
use crate::rigid::check::CheckedBody;

/// `impl System<3>` and `impl TaylorSystem<3>` for the torque-free rotation of the body, or
/// nothing after recording why Euler's equations could not be formed.
pub fn expand(ex: &mut Expansion, checked: &CheckedBody, order: usize) -> TokenStream {
    let (cx, ident, parameters) = (ex.cx, ex.ident, ex.parameters);
    let arena = &mut *ex.arena;
    let p = Private;
    let omega: [ExprId; 3] = std::array::from_fn(|i| arena.input(&format!("omega_{}", i + 1)));
    let zero = [arena.zero(); 3];
    let mut symbols = parameters.tokens();
    // A tensor of fields that is not symbolically diagonal has its principal frame only at
    // run time: the moments are then three symbols read from `RigidBody::principal`, and the
    // same equations are formed over them as over the moments of a diagonal tensor.
    let (body, prelude) = match checked.body.frame {
        Frame::DecomposedAtRunTime => {
            let mut body = checked.body.clone();
            let moments: [ExprId; 3] =
                std::array::from_fn(|k| arena.input(&format!("I_{}", k + 1)));
            for (k, &m) in moments.iter().enumerate() {
                symbols.insert_expr(arena, m, quote!(__pr.moments[#k]));
            }
            body.frame = Frame::Diagonal(moments);
            let prelude = quote!(let __pr = #p::RigidBody::principal(self););
            (Cow::Owned(body), prelude)
        }
        _ => (Cow::Borrowed(&checked.body), TokenStream::new()),
    };
    let rhs = match body.euler_rhs_principal(arena, omega, zero) {
        Ok(Some(rhs)) => rhs,
        Ok(None) => {
            cx.error_spanned_by(
                ident,
                "internal error of the derive: the principal frame of the Taylor recurrences is not known; please report this",
            );
            return TokenStream::new();
        }
        Err(e) => {
            cx.error_spanned_by(ident, format!("cannot form Euler's equations: {e}"));
            return TokenStream::new();
        }
    };
    let reads: Vec<(ExprId, TokenStream)> = (0usize..3)
        .zip(omega)
        .map(|(i, w)| (w, quote!(y[#i])))
        .collect();
    let emitted = Lowering::new(cx, ident, symbols.clone()).lower_reading(arena, &rhs, &reads);
    let (lets, outputs) = (emitted.lets, emitted.outputs);
    let taylor = crate::lang::taylor::expand(
        cx,
        ident,
        arena,
        &symbols,
        &omega,
        &rhs,
        prelude.clone(),
        order,
        None,
    );
    quote! {
        #[automatically_derived]
        #[allow(unused_variables, clippy::all, clippy::pedantic, clippy::nursery, unused_parens)]
        impl #p::System<3> for #ident {
            #[inline]
            fn rhs(&self, t: f64, y: &[f64; 3], dydt: &mut [f64; 3]) {
                #prelude
                #lets
                *dydt = [#(#outputs),*];
            }
        }

        #taylor
    }
}
