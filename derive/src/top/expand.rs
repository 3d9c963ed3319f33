//! Expansion of `#[top]`: the scene derived by precess-core in both angle charts (ZXZ and
//! ZYX, so a simulation can switch at gimbal lock) and in Eulerian form, each method one
//! straight-line block per chart, quoted into `impl TopDynamics for …`.

use precess_core::codegen::Emitted;
use precess_core::lagrange::LagrangeError;
use precess_core::rigid::AngleSequence;
use precess_core::sym::mat3::Mat3;
use precess_core::sym::{Arena, ExprId};
use precess_core::top::{TopDerivation, TopScene};
use proc_macro2::TokenStream;
use quote::{format_ident, quote, quote_spanned};
use syn::spanned::Spanned;

use super::charts::{ChartArms, momenta_tokens};
use super::check::TopSettings;
use crate::lang::expansion::{Expansion, cannot_derive};
use crate::lang::private::Private;
use crate::lang::symbols::Lowering;
use crate::rigid::check::CheckedBody;

/// Where a top's driven-rotor rule reads its inertia: about the pivot.
const ABOUT: crate::lang::rotor::InertiaAbout<'static> = crate::lang::rotor::InertiaAbout {
    body: "top",
    point: "the pivot",
};

/// The scene of the checked body and settings: inertia about the pivot, the centre of
/// mass relative to it, and the declared torques (the user torque is added by [`expand`]).
fn scene(arena: &mut Arena, checked: &CheckedBody, settings: &TopSettings) -> TopScene {
    let props = &checked.body.props;
    let center: [ExprId; 3] =
        std::array::from_fn(|k| arena.sub(props.center[k], props.reference[k]));
    TopScene {
        sequence: settings.angles,
        inertia: props.inertia,
        mass: props.mass,
        center,
        gravity: settings.gravity,
        body_torque: settings.body_torque,
        space_torque: settings.space_torque,
        damping: settings.damping,
        user_torque: None,
        rotors: settings.rotors.clone(),
    }
}

pub(super) fn sequence_tokens(s: AngleSequence) -> TokenStream {
    match s {
        AngleSequence::Zxz => quote!(#Private::AngleSequence::Zxz),
        AngleSequence::Zyx => quote!(#Private::AngleSequence::Zyx),
    }
}

/// A user torque's components (body axes), the inputs of the scene's export: the caller of
/// the C or the Python supplies the value the Rust function returns.
pub(super) fn user_inputs(scene: &TopScene) -> crate::lang::export::Inputs {
    crate::lang::export::vector_inputs(scene.user_torque.as_ref(), "torque")
}

/// The declared user torque function, if any: how each method calls it into `__u`.
pub(super) struct UserCall(Option<syn::Path>);

impl UserCall {
    /// The statements calling the function, or nothing: `setup` (which binds the attitude
    /// matrix `__r`), then `__u = f(self, t, &__r, omega)`.
    ///
    /// The function is first bound to a fn pointer of the signature the attribute
    /// documents, spanned on its path: a function of another signature is then one error on
    /// the path in the attribute, naming the expected and the found signature, rather than
    /// errors of the call spread over the derive. (The optimiser sees through the pointer: it
    /// is a constant.)
    pub(super) fn call(&self, setup: TokenStream, omega: TokenStream) -> TokenStream {
        let Some(path) = &self.0 else {
            return TokenStream::new();
        };
        let p = Private;
        let bind = quote_spanned! {path.span()=>
            let __torque: fn(&Self, f64, &#p::Matrix3<f64>, &#p::Vector3<f64>) -> #p::Vector3<f64> = #path;
        };
        quote!(#setup #bind let __u = __torque(self, t, &__r, #omega);)
    }

    /// [`UserCall::call`] in the arm of the chart `seq_t`: R and ω computed by the chart's
    /// own methods of `dynamics` (the trait as the impl names it: `TopDynamics<N>` for a top
    /// with motors).
    pub(super) fn call_in_chart(&self, seq_t: &TokenStream, dynamics: &TokenStream) -> TokenStream {
        let p = Private;
        self.call(
            quote! {
                let __q = [state[0], state[1], state[2]];
                let __r = #dynamics::rotation_in(self, #seq_t, &__q);
                let __w = #dynamics::rate_matrix_in(self, #seq_t, &__q) * #p::Vector3::new(state[3], state[4], state[5]);
            },
            quote!(&__w),
        )
    }
}

/// `impl TopDynamics for …`, or `None` after recording why the equations could not be derived.
pub fn expand(
    ex: &mut Expansion,
    checked: &CheckedBody,
    settings: &TopSettings,
) -> Option<TokenStream> {
    let (cx, ident, parameters, arena) = ex.split();
    let p = Private;
    let mut scene = scene(arena, checked, settings);
    let user = UserCall(settings.torque.clone());
    let mut symbols = parameters.tokens();
    // The user torque enters the derivation as three input symbols, read from the value
    // the user function returns.
    if user.0.is_some() {
        let u = [arena.input("u0"), arena.input("u1"), arena.input("u2")];
        for (i, &ui) in u.iter().enumerate() {
            symbols.insert_expr(arena, ui, quote!(__u[#i]));
        }
        scene.user_torque = Some(u);
    }
    // A driven top's motor torques are read from the locals its motor calls bind.
    let driven = (!settings.driven.is_empty())
        .then(|| super::driven::DrivenInputs::new(arena, settings, &mut symbols));
    if driven.is_some() {
        let inertia = &checked.body.props.inertia;
        crate::lang::rotor::literal_driven_inertia(cx, arena, inertia, &settings.driven, ABOUT)?;
    }
    let taylor_symbols = symbols.clone();
    let low = Lowering::new(cx, ident, symbols);
    let failed =
        |e: &dyn std::fmt::Display| cannot_derive(cx, ident, "the top's equations of motion", e);
    // In the order a top without motors always derived them, so it emits what it did.
    let (body, equations, lagrangian) = match &driven {
        None => {
            let (body, lagrangian) = undriven(&low, arena, &scene, &user)
                .map_err(|e| failed(&e))
                .ok()?;
            let equations = super::equations::method(cx, ident, arena, &scene);
            (body, equations, Some(lagrangian))
        }
        Some(inputs) => {
            let methods = super::driven::methods(&low, arena, &scene, inputs, &user)
                .map_err(|e| failed(&e))
                .ok()?;
            // The typeset equations are the effective scene's (see `TopScene::derive_driven`),
            // rebuilt over Eulerian inputs made for them.
            eulerian_inputs(arena);
            let equations = super::equations::method(cx, ident, arena, &methods.scene);
            (methods.tokens, equations, None)
        }
    };
    let declared_t = sequence_tokens(scene.sequence);
    let parameters = top_parameters(&low, arena, settings);
    let beyond_gravity = beyond_gravity(settings);
    let rotors = match rotor_methods(&low, arena, &scene, settings) {
        Ok(rotors) => rotors,
        Err(e) => {
            cannot_derive(cx, ident, "the top's rotors", &e);
            return None;
        }
    };
    // `taylor` and `variational(...)` are refused with a driven rotor (check.rs).
    let extra = lagrangian.map(|(state, rhs)| {
        crate::lang::export::top(ident, arena, &state, &user_inputs(&scene), &rhs);
        let variational = settings.variational.as_ref().map(|key| {
            super::variational::expand(cx, ident, arena, &taylor_symbols, (&state, &rhs), key)
        });
        // The Lagrangian state [q, q̇] of the declared chart: y' = (q̇, q̈).
        let taylor = settings.taylor.map(|order| {
            crate::lang::taylor::expand(
                cx,
                ident,
                arena,
                &taylor_symbols,
                &state,
                &rhs,
                TokenStream::new(),
                order,
                Some(
                    quote!(#p::TopDynamics::check_all(self).map_err(#p::TopError::into_ode_error)),
                ),
            )
        });
        quote! {
            #taylor

            #variational
        }
    });
    let n = 6 + settings.driven.len();
    let dynamics = crate::lang::rotor::scene_trait(quote!(#p::TopDynamics), n, driven.is_some());
    let slots = scene
        .sequence
        .names()
        .into_iter()
        .map(str::to_owned)
        .chain(settings.driven.iter().map(|(k, _)| format!("rotor_{k}")));
    let slots = slots.enumerate().map(|(k, name)| {
        let upper = format_ident!("{}", name.to_uppercase(), span = ident.span());
        let (doc, at) = if k < 3 {
            (
                format!(
                    "The index of the angle `{name}` in q and q̇ of the declared chart (its rate is slot {} of the state [q, q̇]).",
                    k + 3
                ),
                k,
            )
        } else {
            (
                format!("The slot of the driven rotor `{name}`'s rate Ω in the state [q, q̇, Ω]."),
                k + 3,
            )
        };
        quote! {
            #[doc = #doc]
            pub const #upper: usize = #at;
        }
    });
    Some(quote! {
        #extra

        #[automatically_derived]
        impl #ident {
            #(#slots)*
        }

        #[automatically_derived]
        #[allow(unused_variables, clippy::all, clippy::pedantic, clippy::nursery, unused_parens)]
        impl #dynamics for #ident {
            const SEQUENCE: #p::AngleSequence = #declared_t;

            const BEYOND_GRAVITY: ::core::option::Option<&'static str> = #beyond_gravity;

            fn top_parameters(&self) -> #p::TopParameters #parameters

            #rotors

            #body

            #equations
        }
    })
}

/// The methods of a top without motors over `[q, q̇]` (both charts, the declared chart's
/// Jacobian and momenta, the Eulerian form), and the declared chart's state and right-hand
/// side for `taylor` and `variational(...)`.
#[allow(clippy::type_complexity)]
fn undriven(
    low: &Lowering,
    arena: &mut Arena,
    scene: &TopScene,
    user: &UserCall,
) -> Result<(TokenStream, (Vec<ExprId>, Vec<ExprId>)), LagrangeError> {
    let p = Private;
    let Methods {
        arms,
        jacobian,
        momenta,
        eulerian,
        lagrangian,
    } = methods(low, arena, scene, user)?;
    let chart = arms.methods(6);
    let body = quote! {
        #chart

        fn angle_jacobian(&self, t: f64, q: &[f64; 3], q_dot: &[f64; 3]) -> [[f64; 6]; 3] #jacobian

        fn conserved_momenta(&self, q: &[f64; 3], q_dot: &[f64; 3]) -> [::core::option::Option<f64>; 3] #momenta

        #[inline]
        fn eulerian_rhs(
            &self,
            t: f64,
            attitude: &#p::UnitQuaternion<f64>,
            omega: &#p::Vector3<f64>,
        ) -> #p::Vector3<f64> #eulerian
    };
    Ok((body, lagrangian))
}

/// `ROTORS`, `DRIVEN_ROTORS`, `rotor_momentum` and a `check_parameters` that judges the
/// rotors' field values (a constant rate finite, every inertia positive and axis non-zero,
/// the inertia left positive definite by the driven wheels) before the settings; nothing
/// without rotors, so the trait's defaults stand.
fn rotor_methods(
    low: &Lowering,
    arena: &mut Arena,
    scene: &TopScene,
    settings: &TopSettings,
) -> Result<TokenStream, precess_core::sym::SymError> {
    let p = Private;
    let h = scene.rotor_momentum(arena)?;
    if h.is_none() && settings.driven.is_empty() {
        return Ok(TokenStream::new());
    }
    let count = scene.rotors.len() + settings.driven.len();
    let momentum = h.map(|h| {
        let Emitted { lets, outputs } = low.lower(arena, &h);
        quote! {
            fn rotor_momentum(&self) -> #p::Vector3<f64> {
                #lets
                #p::Vector3::new(#(#outputs),*)
            }
        }
    });
    let shapes = crate::lang::rotor::check_tokens(
        low,
        arena,
        (&settings.rotor_index, &scene.rotors),
        &settings.driven,
        &quote!(#p::TopError),
        &quote!(#p::RigidBody::inertia(self)),
    );
    let rates: Vec<ExprId> = scene.rotors.iter().map(|r| r.rate).collect();
    let Emitted {
        lets: rate_lets,
        outputs: rate_values,
    } = low.lower(arena, &rates);
    let driven_names = settings.driven.iter().map(|(k, _)| format!("rotor_{k}"));
    // Only for a driven top: without one the trait's default (none) stands.
    let driven_names = (!settings.driven.is_empty())
        .then(|| quote!(const DRIVEN_ROTORS: &'static [&'static str] = &[#(#driven_names),*];));
    Ok(quote! {
        const ROTORS: usize = #count;

        #driven_names

        #momentum

        fn check_parameters(&self) -> ::core::result::Result<(), #p::TopError> {
            #rate_lets
            #(
                let __rate: f64 = #rate_values;
                if !__rate.is_finite() {
                    return ::core::result::Result::Err(#p::TopError::NonFiniteParameter {
                        parameter: "rotor rate",
                        value: __rate,
                    });
                }
            )*
            #shapes
            self.top_parameters().check()
        }
    })
}

/// `TopDynamics::BEYOND_GRAVITY`: the first declared torque other than gravity, by its
/// attribute name (a declared zero counts: the declaration decides, not the value).
fn beyond_gravity(settings: &TopSettings) -> TokenStream {
    let declared = [
        ("damping", settings.damping.is_some()),
        ("body_torque", settings.body_torque.is_some()),
        ("space_torque", settings.space_torque.is_some()),
        ("torque", settings.torque.is_some()),
    ]
    .into_iter()
    .find(|(_, declared)| *declared);
    match declared {
        Some((name, _)) => quote!(::core::option::Option::Some(#name)),
        None => quote!(::core::option::Option::None),
    }
}

/// The body of `top_parameters`: the declared settings' values, read from the fields where
/// they name fields, for `check_parameters` to judge at run time by the rule literals met at
/// compile time.
fn top_parameters(low: &Lowering, arena: &Arena, settings: &TopSettings) -> TokenStream {
    let p = Private;
    let scalars = [settings.gravity, settings.damping];
    let vectors = [settings.body_torque, settings.space_torque];
    let values: Vec<ExprId> = scalars
        .iter()
        .flatten()
        .copied()
        .chain(vectors.iter().flatten().flatten().copied())
        .collect();
    let Emitted { lets, outputs } = low.lower(arena, &values);
    let mut it = outputs.into_iter();
    let some = quote!(::core::option::Option::Some);
    let none = quote!(::core::option::Option::None);
    let [gravity, damping] = scalars.map(|s| match s {
        Some(_) => {
            let v = it.next();
            quote!(#some(#v))
        }
        None => none.clone(),
    });
    let [body_torque, space_torque] = vectors.map(|v| match v {
        Some(_) => {
            let (x, y, z) = (it.next(), it.next(), it.next());
            quote!(#some(#p::Vector3::new(#x, #y, #z)))
        }
        None => none.clone(),
    });
    quote!({
        #lets
        #p::TopParameters { gravity: #gravity, damping: #damping, body_torque: #body_torque, space_torque: #space_torque }
    })
}

/// The bodies of every method of `impl TopDynamics`.
struct Methods {
    arms: ChartArms,
    jacobian: TokenStream,
    momenta: TokenStream,
    eulerian: TokenStream,
    /// The declared chart's state [q, q̇] and right-hand side (q̇, q̈), for `taylor = K`.
    lagrangian: (Vec<ExprId>, Vec<ExprId>),
}

/// Derives the scene in both charts and in Eulerian form and lowers every method.
fn methods(
    low: &Lowering,
    arena: &mut Arena,
    scene: &TopScene,
    user: &UserCall,
) -> Result<Methods, LagrangeError> {
    let mut arms = ChartArms::default();
    let mut chart = |seq: AngleSequence, arms: &mut ChartArms| {
        let top = TopScene {
            sequence: seq,
            ..scene.clone()
        }
        .derive(arena)?;
        arms.push(low, arena, &top, user);
        Ok::<_, LagrangeError>(top)
    };
    let zxz = chart(AngleSequence::Zxz, &mut arms)?;
    let zyx = chart(AngleSequence::Zyx, &mut arms)?;
    let declared = match scene.sequence {
        AngleSequence::Zxz => &zxz,
        AngleSequence::Zyx => &zyx,
    };
    let (jacobian, momenta) = declared_chart(low, arena, declared, user);
    let eulerian = eulerian(low, arena, scene, user)?;
    let c = declared.coords();
    let state = c.q.iter().chain(&c.rates).copied().collect();
    let rhs = c
        .rates
        .iter()
        .chain(&declared.accelerations.accel)
        .copied()
        .collect();
    Ok(Methods {
        arms,
        jacobian,
        momenta,
        eulerian,
        lagrangian: (state, rhs),
    })
}

/// The declared chart only: the Jacobian of q̈ and the conserved momenta, over q and q̇.
fn declared_chart(
    low: &Lowering,
    arena: &mut Arena,
    top: &TopDerivation,
    user: &UserCall,
) -> (TokenStream, TokenStream) {
    let p = Private;
    let c = top.coords().clone();
    let reads: Vec<(ExprId, TokenStream)> = (0..3)
        .flat_map(|k| [(c.q[k], quote!(q[#k])), (c.rates[k], quote!(q_dot[#k]))])
        .collect();
    let declared_t = sequence_tokens(top.sequence);
    let call = user.call(
        quote! {
            let __r = #p::TopDynamics::rotation_in(self, #declared_t, q);
            let __w = #p::TopDynamics::rate_matrix_in(self, #declared_t, q) * #p::Vector3::from(*q_dot);
        },
        quote!(&__w),
    );
    let jac = top.jacobian(arena);
    let Emitted { lets, outputs } = low.lower_reading(arena, jac.as_flattened(), &reads);
    let rows = outputs.chunks(6).map(|row| quote!([#(#row),*]));
    let jacobian = quote!({ #call #lets [#(#rows),*] });
    let momenta = momenta_tokens(low, arena, &top.conserved_momenta, &reads);
    (jacobian, momenta)
}

/// The input symbols `R{i}{j}` and `w{k}` of the Eulerian form, which `equations` typesets
/// the scene over.
fn eulerian_inputs(arena: &mut Arena) -> (Mat3, [ExprId; 3]) {
    let rot: Mat3 =
        std::array::from_fn(|i| std::array::from_fn(|j| arena.input(&format!("R{i}{j}"))));
    let omega = [arena.input("w0"), arena.input("w1"), arena.input("w2")];
    (rot, omega)
}

/// The Eulerian form ω̇(R, ω) over the attitude matrix and ω.
fn eulerian(
    low: &Lowering,
    arena: &mut Arena,
    scene: &TopScene,
    user: &UserCall,
) -> Result<TokenStream, LagrangeError> {
    let p = Private;
    let (rot, omega) = eulerian_inputs(arena);
    let rhs = scene.eulerian_rhs(arena, &rot, &omega)?;
    let mut reads = Vec::new();
    for (i, (&w, row)) in omega.iter().zip(&rot).enumerate() {
        reads.push((w, quote!(omega[#i])));
        for (j, &r) in row.iter().enumerate() {
            reads.push((r, quote!(__r[(#i, #j)])));
        }
    }
    let call = user.call(TokenStream::new(), quote!(omega));
    let Emitted { lets, outputs } = low.lower_reading(arena, &rhs, &reads);
    Ok(quote!({
        let __r: #p::Matrix3<f64> = attitude.to_rotation_matrix().into_inner();
        #call
        #lets
        #p::Vector3::new(#(#outputs),*)
    }))
}
