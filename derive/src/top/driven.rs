//! `#[top(rotor(axis = [..], inertia = J, torque = path))]`: a top whose wheels are turned by
//! motors. Its state is `[q, q̇, Ω₀, …]`, `N = 6 + k`, and its equations come from
//! `TopScene::derive_driven` (precess-core) in both charts; this module lowers them into
//! the state-taking methods of `impl TopDynamics<N>`. Emitted only for a driven scene: a top
//! without motors goes through `expand` alone and emits what it always did.

use precess_core::codegen::Emitted;
use precess_core::rigid::{AngleSequence, DrivenRotor, Rotor, total_momentum};
use precess_core::sym::{Arena, ExprId};
use precess_core::top::{DrivenDerivation, TopScene};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use super::charts::{ChartArms, momenta_tokens};
use super::check::TopSettings;
use super::expand::{UserCall, sequence_tokens};
use crate::lang::private::Private;
use crate::lang::symbols::{Lowering, SymbolTokens};

/// The driven rotors as the derivation takes them: their motor torques input symbols read
/// from the locals `__motor{k}` the motor calls bind, their rates Ω input symbols read from
/// the state.
pub(super) struct DrivenInputs {
    rotors: Vec<DrivenRotor>,
    rates: Vec<ExprId>,
    motors: Vec<syn::Path>,
    /// Each wheel's name, `rotor_k` (k its place among every rotor declared).
    names: Vec<String>,
}

impl DrivenInputs {
    /// Makes the symbols of `settings`' driven rotors, registering the motor torques in
    /// `symbols` (every method reads them from the same locals).
    pub fn new(arena: &mut Arena, settings: &TopSettings, symbols: &mut SymbolTokens) -> Self {
        let mut out = DrivenInputs {
            rotors: Vec::new(),
            rates: Vec::new(),
            motors: Vec::new(),
            names: Vec::new(),
        };
        for (k, (declared, d)) in settings.driven.iter().enumerate() {
            let u = arena.input(&format!("u_rotor_{declared}"));
            let local = format_ident!("__motor{k}");
            symbols.insert_expr(arena, u, quote!(#local));
            out.rotors.push(DrivenRotor {
                axis: d.axis,
                inertia: d.inertia,
                torque: u,
            });
            out.rates
                .push(arena.input(&format!("Omega_rotor_{declared}")));
            out.motors.push(d.torque.clone());
            out.names.push(format!("rotor_{declared}"));
        }
        out
    }

    /// The state's length, 6 + the driven rotors.
    pub fn state_len(&self) -> usize {
        6 + self.rotors.len()
    }

    /// The statements binding each motor's torque `__motor{k}` from the state, all through
    /// one call of the generated `motor_torques`.
    fn calls(&self) -> TokenStream {
        let p = Private;
        let (n, count) = (self.state_len(), self.motors.len());
        let locals = (0..count).map(|k| format_ident!("__motor{k}"));
        let slots = 0..count;
        quote! {
            let mut __motors = [0.0f64; #count];
            <Self as #p::TopDynamics<#n>>::motor_torques(self, t, state, &mut __motors);
            #(let #locals: f64 = __motors[#slots];)*
        }
    }

    /// `MOTORS` and `motor_torques` of `impl TopDynamics<N>`.
    fn motor_methods(&self) -> TokenStream {
        crate::lang::rotor::motor_methods(self.motors.iter(), self.state_len())
    }
}

/// The state-taking methods of a driven top, by chart: a top's, and `rhs_in`.
#[derive(Default)]
struct Arms {
    chart: ChartArms,
    rhs: Vec<TokenStream>,
}

/// The methods of `impl TopDynamics<N>` that a driven top generates in place of the
/// angle-only ones, and the effective scene of the declared chart (whose equations
/// `equations()` typesets).
pub(super) struct DrivenMethods {
    /// The methods.
    pub tokens: TokenStream,
    /// The declared chart's effective scene.
    pub scene: TopScene,
}

impl DrivenInputs {
    /// Registers the export of the declared chart `d`: the state `[q, q̇, Ω]`, the motors'
    /// torques (then `user`, a user torque's components) as the inputs the caller supplies,
    /// `rhs_in`'s outputs (q̇ then q̈ and Ω̇).
    fn export(
        &self,
        ident: &syn::Ident,
        arena: &mut Arena,
        d: &DrivenDerivation,
        user: &crate::lang::export::Inputs,
    ) {
        let c = d.effective.coords();
        let mut state: Vec<ExprId> = c.q.iter().chain(&c.rates).copied().collect();
        // The angles and their rates named as their symbols, as a top without motors names
        // them.
        let mut names = crate::lang::export::symbol_names(arena, &state);
        state.extend(&self.rates);
        names.extend(self.names.iter().cloned());
        let inputs: crate::lang::export::Inputs = self
            .rotors
            .iter()
            .zip(&self.names)
            .map(|(r, name)| (r.torque, format!("u_{name}")))
            .chain(user.iter().cloned())
            .collect();
        let rhs: Vec<ExprId> = c
            .rates
            .iter()
            .chain(&d.accel)
            .chain(&d.rotor_accel)
            .copied()
            .collect();
        crate::lang::export::driven_top(ident, arena, (&state, &names, &inputs), &rhs);
    }
}

/// Derives the driven scene in both charts and lowers every method over the whole state.
pub(super) fn methods(
    low: &Lowering,
    arena: &mut Arena,
    scene: &TopScene,
    inputs: &DrivenInputs,
    user: &UserCall,
) -> Result<DrivenMethods, precess_core::lagrange::LagrangeError> {
    let p = Private;
    let n = inputs.state_len();
    let mut arms = Arms::default();
    let chart = |arena: &mut Arena, sequence: AngleSequence, arms: &mut Arms| {
        let d = TopScene {
            sequence,
            ..scene.clone()
        }
        .derive_driven(arena, &inputs.rotors, &inputs.rates)?;
        arms.push(low, arena, &d, inputs, user, n);
        Ok::<_, precess_core::lagrange::LagrangeError>(d)
    };
    let zxz = chart(arena, AngleSequence::Zxz, &mut arms)?;
    let zyx = chart(arena, AngleSequence::Zyx, &mut arms)?;
    let declared = match scene.sequence {
        AngleSequence::Zxz => zxz,
        AngleSequence::Zyx => zyx,
    };
    inputs.export(
        low.ident(),
        arena,
        &declared,
        &super::expand::user_inputs(scene),
    );
    let reads = state_reads(&declared, inputs);
    let momenta_in = momenta_tokens(low, arena, &declared.conserved_momenta, &reads);
    // Every rotor's momentum at the state: the constant ones' and J Ω â of each driven one.
    let all: Vec<Rotor> = scene
        .rotors
        .iter()
        .copied()
        .chain(
            inputs
                .rotors
                .iter()
                .zip(&inputs.rates)
                .map(|(d, &rate)| d.at_rate(rate)),
        )
        .collect();
    let h = total_momentum(arena, &all)
        .map_err(|(_, e)| e)?
        .unwrap_or([arena.zero(); 3]);
    let Emitted { lets, outputs } = low.lower_reading(arena, &h, &reads);
    let momentum_in = quote!({ #lets #p::Vector3::new(#(#outputs),*) });
    let chart = arms.chart.methods(n);
    let rhs = &arms.rhs;
    let motor_methods = inputs.motor_methods();
    let tokens = quote! {
        #motor_methods

        #chart

        #[inline]
        fn rhs_in(&self, seq: #p::AngleSequence, t: f64, state: &[f64; #n], __rate: &mut [f64; #n]) {
            match seq { #(#rhs)* }
        }

        fn rotor_momentum_in(&self, state: &[f64; #n]) -> #p::Vector3<f64> #momentum_in

        fn conserved_momenta_in(&self, state: &[f64; #n]) -> [::core::option::Option<f64>; 3] #momenta_in

        /// A driven top's q̈ reads its wheels' rates, which (q, q̇) do not give: NaN.
        fn angle_jacobian(&self, t: f64, q: &[f64; 3], q_dot: &[f64; 3]) -> [[f64; 6]; 3] {
            [[f64::NAN; 6]; 3]
        }

        /// A driven top's momenta read its wheels' rates: see `conserved_momenta_in`.
        fn conserved_momenta(&self, q: &[f64; 3], q_dot: &[f64; 3]) -> [::core::option::Option<f64>; 3] {
            [::core::option::Option::None; 3]
        }

        /// A driven top's ω̇ reads its wheels' rates and motors, which (R, ω) do not give: NaN.
        fn eulerian_rhs(
            &self,
            t: f64,
            attitude: &#p::UnitQuaternion<f64>,
            omega: &#p::Vector3<f64>,
        ) -> #p::Vector3<f64> {
            #p::Vector3::from_element(f64::NAN)
        }
    };
    Ok(DrivenMethods {
        tokens,
        scene: declared.scene,
    })
}

/// The state symbols of `d` and how the methods read them: `state[k]`.
fn state_reads(d: &DrivenDerivation, inputs: &DrivenInputs) -> Vec<(ExprId, TokenStream)> {
    let c = d.effective.coords();
    c.q.iter()
        .chain(&c.rates)
        .chain(&inputs.rates)
        .enumerate()
        .map(|(k, &e)| (e, quote!(state[#k])))
        .collect()
}

impl Arms {
    /// Adds the arms of the chart `d` was derived in.
    fn push(
        &mut self,
        low: &Lowering,
        arena: &mut Arena,
        d: &DrivenDerivation,
        inputs: &DrivenInputs,
        user: &UserCall,
        n: usize,
    ) {
        let p = Private;
        let top = &d.effective;
        let seq_t = sequence_tokens(top.sequence);
        let reads = state_reads(d, inputs);
        let user_call = user.call_in_chart(&seq_t, &quote!(<Self as #p::TopDynamics<#n>>));
        let motors = inputs.calls();
        let Emitted { lets, outputs } = low.lower_reading(arena, &d.accel, &reads);
        self.chart
            .accel
            .push(quote!(#seq_t => { #user_call #motors #lets [#(#outputs),*] }));
        let rhs: Vec<ExprId> = d.accel.iter().chain(&d.rotor_accel).copied().collect();
        let Emitted { lets, outputs } = low.lower_reading(arena, &rhs, &reads);
        self.rhs.push(quote!(#seq_t => {
            #user_call
            #motors
            #lets
            *__rate = [state[3], state[4], state[5], #(#outputs),*];
        }));
        let Emitted { lets, outputs } = low.lower_reading(arena, &[d.energy], &reads);
        self.chart
            .energy
            .push(quote!(#seq_t => { #lets #(#outputs)* }));
        self.chart.push_frames(low, arena, top);
    }
}
