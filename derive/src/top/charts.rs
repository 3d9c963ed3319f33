//! The chart-dispatched methods of `impl TopDynamics`, one arm per angle sequence (ZXZ and
//! ZYX, so a simulation can switch at gimbal lock), for a top with or without motors, and
//! the body of its `conserved_momenta`.

use precess_core::codegen::Emitted;
use precess_core::sym::{Arena, ExprId};
use precess_core::top::TopDerivation;
use proc_macro2::TokenStream;
use quote::quote;

use super::expand::{UserCall, sequence_tokens};
use crate::lang::private::Private;
use crate::lang::symbols::Lowering;

/// The arms of the chart-dispatched methods, one per angle sequence: a top's with or without
/// motors (`driven.rs` adds its `rhs_in` beside them).
#[derive(Default)]
pub(super) struct ChartArms {
    pub(super) accel: Vec<TokenStream>,
    pub(super) rotation: Vec<TokenStream>,
    pub(super) rate_matrix: Vec<TokenStream>,
    pub(super) energy: Vec<TokenStream>,
}

impl ChartArms {
    /// Adds the arms of the chart `top` was derived in.
    pub(super) fn push(
        &mut self,
        low: &Lowering,
        arena: &mut Arena,
        top: &TopDerivation,
        user: &UserCall,
    ) {
        let c = top.coords().clone();
        let seq_t = sequence_tokens(top.sequence);
        let state: Vec<(ExprId, TokenStream)> = (0..3)
            .flat_map(|k| {
                let j = k + 3;
                [(c.q[k], quote!(state[#k])), (c.rates[k], quote!(state[#j]))]
            })
            .collect();
        let call = user.call_in_chart(&seq_t, &quote!(#Private::TopDynamics));
        let Emitted { lets, outputs } = low.lower_reading(arena, &top.accelerations.accel, &state);
        self.accel
            .push(quote!(#seq_t => { #call #lets [#(#outputs),*] }));
        let energy = top.energy(arena);
        let Emitted { lets, outputs } = low.lower_reading(arena, &[energy], &state);
        self.energy.push(quote!(#seq_t => { #lets #(#outputs)* }));
        self.push_frames(low, arena, top);
    }

    /// Adds the arms of R and B of the chart `top` was derived in, which read the angles
    /// from `q` rather than `state`.
    pub(super) fn push_frames(&mut self, low: &Lowering, arena: &mut Arena, top: &TopDerivation) {
        let p = Private;
        let seq_t = sequence_tokens(top.sequence);
        let angles: Vec<(ExprId, TokenStream)> =
            (0..3).map(|k| (top.coords().q[k], quote!(q[#k]))).collect();
        let Emitted { lets, outputs } =
            low.lower_reading(arena, top.rotation.as_flattened(), &angles);
        self.rotation
            .push(quote!(#seq_t => { #lets #p::Matrix3::new(#(#outputs),*) }));
        let Emitted { lets, outputs } =
            low.lower_reading(arena, top.rate_matrix.as_flattened(), &angles);
        self.rate_matrix
            .push(quote!(#seq_t => { #lets #p::Matrix3::new(#(#outputs),*) }));
    }

    /// The chart-dispatched methods over a state of `n` slots.
    pub(super) fn methods(&self, n: usize) -> TokenStream {
        let p = Private;
        let ChartArms {
            accel,
            rotation,
            rate_matrix,
            energy,
        } = self;
        quote! {
            #[inline]
            fn accelerations_unchecked_in(&self, seq: #p::AngleSequence, t: f64, state: &[f64; #n]) -> [f64; 3] {
                match seq { #(#accel)* }
            }

            #[inline]
            fn rotation_in(&self, seq: #p::AngleSequence, q: &[f64; 3]) -> #p::Matrix3<f64> {
                match seq { #(#rotation)* }
            }

            #[inline]
            fn rate_matrix_in(&self, seq: #p::AngleSequence, q: &[f64; 3]) -> #p::Matrix3<f64> {
                match seq { #(#rate_matrix)* }
            }

            #[inline]
            fn energy_in(&self, seq: #p::AngleSequence, state: &[f64; #n]) -> f64 {
                match seq { #(#energy)* }
            }
        }
    }
}

/// The body of a `conserved_momenta` method: the momenta that are conserved, read through
/// `reads`, `None` for the others.
pub(super) fn momenta_tokens(
    low: &Lowering,
    arena: &Arena,
    momenta: &[Option<ExprId>],
    reads: &[(ExprId, TokenStream)],
) -> TokenStream {
    let conserved: Vec<ExprId> = momenta.iter().flatten().copied().collect();
    let Emitted { lets, outputs } = low.lower_reading(arena, &conserved, reads);
    let mut it = outputs.into_iter();
    let slots = momenta.iter().map(|m| match m {
        Some(_) => {
            let v = it.next();
            quote!(::core::option::Option::Some(#v))
        }
        None => quote!(::core::option::Option::None),
    });
    quote!({ #lets [#(#slots),*] })
}
