//! Rust for a derived top: the body of `impl Top for …`, as the derive macro splices it in.
//!
//! Both angle charts (ZXZ and ZYX) are derived and emitted, so a simulation can switch at
//! gimbal lock; each method is one straight-line block per chart from [`Program::lower`].
//! Everything generated names types through the path the caller gives (the facade's
//! `::precess::__private`).

use proc_macro2::TokenStream;
use quote::quote;

use super::error::LagrangeError;
use crate::codegen::{Emitted, Program};
use crate::rigid::AngleSequence;
use crate::sym::mat3::Mat3;
use crate::sym::{Arena, ExprId, SymbolId};
use crate::top::{TopDerivation, TopScene};

/// What the macro supplies: the scene (its `sequence` is the declared one), how to read a
/// parameter symbol (a struct field) in Rust, and the user torque function, if declared.
pub struct TopEmit<'a> {
    /// The scene. `user_torque` is set by [`emit_top`] itself when `user_fn` is given.
    pub scene: TopScene,
    /// Rust for each parameter symbol, e.g. `self.m`; `None` for symbols it does not know.
    pub parameter: &'a mut dyn FnMut(SymbolId) -> Option<TokenStream>,
    /// A path to `fn(&Self, f64, &Matrix3<f64>, &Vector3<f64>) -> Vector3<f64>`: the user
    /// torque in body axes from time, attitude R (body to space) and body ω.
    pub user_fn: Option<TokenStream>,
    /// The path generated code names types through, e.g. `::precess::__private`.
    pub krate: TokenStream,
}

/// The symbols generated code reads, and the Rust for each.
struct Reads {
    map: Vec<(SymbolId, TokenStream)>,
}

impl Reads {
    fn sym(&mut self, a: &Arena, e: ExprId, tokens: TokenStream) {
        if let Some(s) = a.as_symbol(e) {
            self.map.push((s, tokens));
        }
    }
}

fn lower(
    a: &Arena,
    outputs: &[ExprId],
    reads: &Reads,
    parameter: &mut dyn FnMut(SymbolId) -> Option<TokenStream>,
) -> Emitted {
    Program::lower(a, outputs).to_tokens(&mut |s| {
        reads
            .map
            .iter()
            .find(|(k, _)| *k == s)
            .map(|(_, t)| t.clone())
            .or_else(|| parameter(s))
            // Unreachable for scenes the macro builds; NaN rather than a panic otherwise.
            .unwrap_or_else(|| quote!(f64::NAN))
    })
}

fn flat(m: &Mat3) -> Vec<ExprId> {
    m.iter().flatten().copied().collect()
}

/// The items of `impl Top for …` (without the `impl` line).
///
/// # Errors
/// Any [`LagrangeError`] of the derivation (a singular inertia tensor).
pub fn emit_top(arena: &mut Arena, e: TopEmit<'_>) -> Result<TokenStream, LagrangeError> {
    let TopEmit {
        mut scene,
        parameter,
        user_fn,
        krate: p,
    } = e;
    let user = user_fn
        .as_ref()
        .map(|_| [arena.input("u0"), arena.input("u1"), arena.input("u2")]);
    scene.user_torque = user;
    let declared = scene.sequence;
    let seq_tokens = |s: AngleSequence| match s {
        AngleSequence::Zxz => quote!(#p::AngleSequence::Zxz),
        AngleSequence::Zyx => quote!(#p::AngleSequence::Zyx),
    };
    let mut reads = Reads { map: Vec::new() };
    if let Some(u) = user {
        for (i, &ui) in u.iter().enumerate() {
            reads.sym(arena, ui, quote!(__u[#i]));
        }
    }
    // The user torque is called with R and ω computed by the chart's own methods.
    let user_call_state = |seq_t: &TokenStream| match &user_fn {
        Some(f) => quote! {
            let __q = [state[0], state[1], state[2]];
            let __r = #p::Top::rotation_in(self, #seq_t, &__q);
            let __w = #p::Top::rate_matrix_in(self, #seq_t, &__q) * #p::Vector3::new(state[3], state[4], state[5]);
            let __u: #p::Vector3<f64> = #f(self, t, &__r, &__w);
        },
        None => TokenStream::new(),
    };

    let mut accel_arms = Vec::new();
    let mut rotation_arms = Vec::new();
    let mut rate_arms = Vec::new();
    let mut energy_arms = Vec::new();
    let mut declared_top: Option<TopDerivation> = None;
    for seq in [AngleSequence::Zxz, AngleSequence::Zyx] {
        let mut s = scene.clone();
        s.sequence = seq;
        let top = s.derive(arena)?;
        let c = top.coords().clone();
        let mut r = Reads {
            map: reads.map.clone(),
        };
        for k in 0..3 {
            let j = k + 3;
            r.sym(arena, c.q[k], quote!(state[#k]));
            r.sym(arena, c.rates[k], quote!(state[#j]));
        }
        let seq_t = seq_tokens(seq);
        let call = user_call_state(&seq_t);
        let Emitted { lets, outputs } = lower(arena, &top.accelerations.accel, &r, parameter);
        accel_arms.push(quote!(#seq_t => { #call #lets [#(#outputs),*] }));
        let energy = top.energy(arena);
        let Emitted { lets, outputs } = lower(arena, &[energy], &r, parameter);
        energy_arms.push(quote!(#seq_t => { #lets #(#outputs)* }));
        // R and B read the angles from `q` rather than `state`.
        let mut rq = Reads {
            map: reads.map.clone(),
        };
        for k in 0..3 {
            rq.sym(arena, c.q[k], quote!(q[#k]));
        }
        let Emitted { lets, outputs } = lower(arena, &flat(&top.rotation), &rq, parameter);
        rotation_arms.push(quote!(#seq_t => { #lets #p::Matrix3::new(#(#outputs),*) }));
        let Emitted { lets, outputs } = lower(arena, &flat(&top.rate_matrix), &rq, parameter);
        rate_arms.push(quote!(#seq_t => { #lets #p::Matrix3::new(#(#outputs),*) }));
        if seq == declared {
            declared_top = Some(top);
        }
    }
    let Some(top) = declared_top else {
        unreachable!("the declared sequence is one of the two derived")
    };

    // Declared chart only: Jacobian and conserved momenta, over q and q_dot.
    let c = top.coords().clone();
    let mut r = Reads {
        map: reads.map.clone(),
    };
    for k in 0..3 {
        r.sym(arena, c.q[k], quote!(q[#k]));
        r.sym(arena, c.rates[k], quote!(q_dot[#k]));
    }
    let declared_t = seq_tokens(declared);
    let call = match &user_fn {
        Some(f) => quote! {
            let __r = #p::Top::rotation_in(self, #declared_t, q);
            let __w = #p::Top::rate_matrix_in(self, #declared_t, q) * #p::Vector3::from(*q_dot);
            let __u: #p::Vector3<f64> = #f(self, t, &__r, &__w);
        },
        None => TokenStream::new(),
    };
    let jac = top.jacobian(arena);
    let Emitted { lets, outputs } = lower(arena, jac.as_flattened(), &r, parameter);
    let rows = outputs.chunks(6).map(|row| quote!([#(#row),*]));
    let jacobian = quote!({ #call #lets [#(#rows),*] });
    let conserved: Vec<ExprId> = top.conserved_momenta.iter().flatten().copied().collect();
    let Emitted { lets, outputs } = lower(arena, &conserved, &r, parameter);
    let mut it = outputs.into_iter();
    let slots = top.conserved_momenta.iter().map(|m| match m {
        Some(_) => {
            let v = it.next();
            quote!(::core::option::Option::Some(#v))
        }
        None => quote!(::core::option::Option::None),
    });
    let momenta = quote!({ #lets [#(#slots),*] });

    // The Eulerian form over the attitude matrix and ω.
    let rot: Mat3 =
        std::array::from_fn(|i| std::array::from_fn(|j| arena.input(&format!("R{i}{j}"))));
    let omega = [arena.input("w0"), arena.input("w1"), arena.input("w2")];
    let rhs = scene.eulerian_rhs(arena, &rot, &omega)?;
    let mut re = Reads {
        map: reads.map.clone(),
    };
    for (i, (&w, row)) in omega.iter().zip(&rot).enumerate() {
        re.sym(arena, w, quote!(omega[#i]));
        for (j, &r) in row.iter().enumerate() {
            re.sym(arena, r, quote!(__r[(#i, #j)]));
        }
    }
    let call = match &user_fn {
        Some(f) => quote!(let __u: #p::Vector3<f64> = #f(self, t, &__r, omega);),
        None => TokenStream::new(),
    };
    let Emitted { lets, outputs } = lower(arena, &rhs, &re, parameter);
    let eulerian = quote!({
        let __r: #p::Matrix3<f64> = attitude.to_rotation_matrix().into_inner();
        #call
        #lets
        #p::Vector3::new(#(#outputs),*)
    });

    Ok(quote! {
        const SEQUENCE: #p::AngleSequence = #declared_t;

        #[inline]
        fn accel_in(&self, seq: #p::AngleSequence, t: f64, state: &[f64; 6]) -> [f64; 3] {
            match seq { #(#accel_arms)* }
        }

        #[inline]
        fn rotation_in(&self, seq: #p::AngleSequence, q: &[f64; 3]) -> #p::Matrix3<f64> {
            match seq { #(#rotation_arms)* }
        }

        #[inline]
        fn rate_matrix_in(&self, seq: #p::AngleSequence, q: &[f64; 3]) -> #p::Matrix3<f64> {
            match seq { #(#rate_arms)* }
        }

        #[inline]
        fn energy_in(&self, seq: #p::AngleSequence, state: &[f64; 6]) -> f64 {
            match seq { #(#energy_arms)* }
        }

        fn angle_jacobian(&self, t: f64, q: &[f64; 3], q_dot: &[f64; 3]) -> [[f64; 6]; 3] #jacobian

        fn conserved_momenta(&self, q: &[f64; 3], q_dot: &[f64; 3]) -> [::core::option::Option<f64>; 3] #momenta

        #[inline]
        fn eulerian_rhs(
            &self,
            t: f64,
            attitude: &#p::UnitQuaternion<f64>,
            omega: &#p::Vector3<f64>,
        ) -> #p::Vector3<f64> #eulerian
    })
}
