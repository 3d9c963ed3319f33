//! Expansion of `#[free]`: the scene derived by precess-core (the right-hand side, wrench,
//! energy, power and momenta over the state array), each method one straight-line block,
//! quoted into `impl FreeDynamics for …`.

use precess_core::codegen::{Emitted, f64_literal};
use precess_core::free::{CmFrame, FreeDerivation, FreeScene, STATE_NAMES, WrenchInputs, cm_frame};
use precess_core::rigid::DrivenRotor;
use precess_core::sym::mat3::Mat3;
use precess_core::sym::{Arena, ExprId, SymbolId};
use proc_macro2::TokenStream;
use quote::{ToTokens, format_ident, quote, quote_spanned};
use syn::spanned::Spanned;

use super::check::FreeSettings;
use crate::lang::expansion::{Expansion, cannot_derive};
use crate::lang::keys;
use crate::lang::private::Private;
use crate::lang::symbols::{FieldParameters, Lowering, StateMethod, SymbolTokens};
use crate::rigid::check::CheckedBody;

/// The values generated code computes before a method's straight-line block, each emitted
/// only where the block reads it.
struct Preludes {
    /// The principal frame decomposed at run time: its moments and rotation symbols.
    principal: Vec<ExprId>,
    /// The user force function and the symbols of its value.
    force: Option<(TokenStream, [ExprId; 3])>,
    /// The user torque function and the symbols of its value.
    torque: Option<(TokenStream, [ExprId; 3])>,
    /// The user wrench functions and the symbols of their sum's four parts.
    wrench: Option<(Vec<syn::Path>, [ExprId; 12])>,
    /// The driven rotors' motor functions and the symbols of their torques.
    motors: Vec<(syn::Path, ExprId)>,
}

impl Preludes {
    /// The statements `outputs` need.
    fn for_outputs(&self, arena: &Arena, outputs: &[ExprId]) -> TokenStream {
        let p = Private;
        let read: Vec<SymbolId> = outputs
            .iter()
            .flat_map(|&o| arena.free_symbols(o))
            .collect();
        let reads = |symbols: &[ExprId]| {
            symbols
                .iter()
                .filter_map(|&e| arena.as_symbol(e))
                .any(|s| read.contains(&s))
        };
        let mut out = TokenStream::new();
        if reads(&self.principal) {
            out.extend(quote!(let __pr = #p::FreeDynamics::principal_cm(self);));
        }
        let calls: Vec<TokenStream> = [(&self.force, quote!(__f)), (&self.torque, quote!(__u))]
            .into_iter()
            .filter_map(|(user, local)| {
                let (path, symbols) = user.as_ref()?;
                reads(symbols)
                    .then(|| quote!(let #local: #p::Vector3<f64> = #path(self, t, &__state);))
            })
            .chain(self.wrench_call(&reads))
            .collect();
        if !calls.is_empty() {
            out.extend(quote!(let __state = #p::FreeState::from_array_unchecked(y);));
            out.extend(calls);
        }
        // The motors through one call of the generated `motor_torques`, once per evaluation
        // that reads a torque.
        let symbols: Vec<ExprId> = self.motors.iter().map(|(_, u)| *u).collect();
        if reads(&symbols) {
            let count = symbols.len();
            let locals = (0..count).map(|k| format_ident!("__motor{k}"));
            let slots = 0..count;
            out.extend(quote! {
                let mut __motors = [0.0f64; #count];
                #p::FreeDynamics::motor_torques(self, t, y, &mut __motors);
                #(let #locals: f64 = __motors[#slots];)*
            });
        }
        out
    }

    /// `MOTORS` and `motor_torques` of `impl FreeDynamics<N>`.
    fn motor_methods(&self, n: usize) -> TokenStream {
        crate::lang::rotor::motor_methods(self.motors.iter().map(|(path, _)| path), n)
    }

    /// The wrench functions called and their sum resolved into its four parts, if `reads`
    /// says an output needs them: one call per function per evaluation. Each function is
    /// first bound as a typed pointer spanned on its path, so a wrong signature is reported
    /// there, naming the expected and the found one.
    fn wrench_call(&self, reads: &dyn Fn(&[ExprId]) -> bool) -> Option<TokenStream> {
        let p = Private;
        let (paths, symbols) = self.wrench.as_ref()?;
        if !reads(symbols) {
            return None;
        }
        let locals: Vec<syn::Ident> = (0..paths.len())
            .map(|k| format_ident!("__wrench_fn{k}"))
            .collect();
        let binds = paths.iter().zip(&locals).map(|(path, local)| {
            quote_spanned! {path.span()=>
                let #local: fn(&Self, f64, &#p::FreeState) -> #p::AppliedWrench = #path;
            }
        });
        Some(quote! {
            #(#binds)*
            let __w: #p::AppliedWrench = #(#locals(self, t, &__state))+*;
            let (__w_fs, __w_ts) = __w.space_part(&__state.position);
            let (__w_fd, __w_td) = __w.description_part();
        })
    }
}

/// The scene of the checked body and settings, with the symbols generated code must supply
/// (the run-time principal frame, the user functions' values) recorded in `symbols`.
fn scene(
    arena: &mut Arena,
    checked: &CheckedBody,
    settings: &FreeSettings,
    frame: &CmFrame,
    symbols: &mut SymbolTokens,
) -> (FreeScene, Preludes) {
    let props = &checked.body.props;
    let mut scene = FreeScene {
        mass: props.mass,
        center: props.center,
        moments: [props.mass; 3],
        ..settings.loads.clone()
    };
    let mut preludes = Preludes {
        principal: Vec::new(),
        force: None,
        torque: None,
        wrench: None,
        motors: Vec::new(),
    };
    match frame {
        CmFrame::Diagonal(m) => scene.moments = *m,
        CmFrame::Constant(pr) => {
            let r = pr.rotation.matrix();
            let constant =
                |arena: &mut Arena, x: f64| arena.float(x).unwrap_or_else(|_| arena.zero());
            scene.moments = std::array::from_fn(|k| constant(arena, pr.moments[k]));
            scene.principal_rotation =
                std::array::from_fn(|i| std::array::from_fn(|j| constant(arena, r[(i, j)])));
        }
        CmFrame::AtRunTime => {
            let moments: [ExprId; 3] =
                std::array::from_fn(|k| arena.input(&format!("I_{}", k + 1)));
            let rotation: Mat3 = std::array::from_fn(|i| {
                std::array::from_fn(|j| arena.input(&format!("R_pd_{i}{j}")))
            });
            for (k, &m) in moments.iter().enumerate() {
                symbols.insert_expr(arena, m, quote!(__pr.moments[#k]));
            }
            for (i, row) in rotation.iter().enumerate() {
                for (j, &r) in row.iter().enumerate() {
                    symbols.insert_expr(arena, r, quote!(__pr.rotation.matrix()[(#i, #j)]));
                }
            }
            preludes.principal = moments
                .into_iter()
                .chain(rotation.into_iter().flatten())
                .collect();
            scene.moments = moments;
            scene.principal_rotation = rotation;
        }
    }
    for (k, (_, d)) in settings.driven.iter().enumerate() {
        // The motor's torque enters the derivation as an input symbol its function supplies.
        let u = arena.input(&format!("u_rotor_{k}"));
        let local = format_ident!("__motor{k}");
        symbols.insert_expr(arena, u, quote!(#local));
        preludes.motors.push((d.torque.clone(), u));
        scene.driven.push(DrivenRotor {
            axis: d.axis,
            inertia: d.inertia,
            torque: u,
        });
    }
    // A user function's value enters the derivation as three input symbols.
    let mut user = |arena: &mut Arena, path: &Option<syn::Path>, local: TokenStream, name: &str| {
        let path = path.as_ref()?;
        let u: [ExprId; 3] = std::array::from_fn(|k| arena.input(&format!("{name}{k}")));
        for (k, &e) in u.iter().enumerate() {
            symbols.insert_expr(arena, e, quote!(#local[#k]));
        }
        Some((path.to_token_stream(), u))
    };
    preludes.force = user(arena, &settings.force, quote!(__f), "f_user_");
    preludes.torque = user(arena, &settings.torque, quote!(__u), "tau_user_");
    scene.user_force = preludes.force.as_ref().map(|(_, u)| *u);
    scene.user_torque = preludes.torque.as_ref().map(|(_, u)| *u);
    if !settings.wrenches.is_empty() {
        let inputs = WrenchInputs::new(arena, "wrench_");
        let locals = [
            quote!(__w_fs),
            quote!(__w_ts),
            quote!(__w_fd),
            quote!(__w_td),
        ];
        let all = inputs.symbols();
        for (k, &e) in all.iter().enumerate() {
            let (local, c) = (&locals[k / 3], k % 3);
            symbols.insert_expr(arena, e, quote!(#local[#c]));
        }
        preludes.wrench = Some((settings.wrenches.clone(), all));
        scene.user_wrench = Some(inputs);
    }
    (scene, preludes)
}

/// The values of a free body's user functions, the inputs of its export (the caller of the
/// C or the Python supplies them): each motor's torque, the user force (space axes), the
/// user torque (description axes), a wrench's four parts (force and torque, space then
/// description axes).
fn export_inputs(scene: &FreeScene) -> crate::lang::export::Inputs {
    use crate::lang::export::vector_inputs;
    let motors = scene
        .driven
        .iter()
        .enumerate()
        .map(|(k, d)| (d.torque, format!("u_rotor_{k}")));
    let wrench = scene.user_wrench.as_ref().map(|w| w.symbols());
    let parts = [
        "force_space",
        "torque_space",
        "force_description",
        "torque_description",
    ];
    let wrench = wrench.iter().flat_map(|w| {
        parts.iter().enumerate().flat_map(move |(i, part)| {
            let v = [w[3 * i], w[3 * i + 1], w[3 * i + 2]];
            vector_inputs(Some(&v), &format!("wrench_{part}"))
        })
    });
    motors
        .chain(vector_inputs(scene.user_force.as_ref(), "force"))
        .chain(vector_inputs(scene.user_torque.as_ref(), "torque"))
        .chain(wrench)
        .collect()
}

/// Where a free body's driven-rotor rule reads its inertia: about its centre of mass.
const ABOUT: crate::lang::rotor::InertiaAbout<'static> = crate::lang::rotor::InertiaAbout {
    body: "body",
    point: "its centre of mass",
};

/// `impl FreeDynamics for …`, or `None` after recording why the equations could not be
/// derived.
pub fn expand(
    ex: &mut Expansion,
    checked: &CheckedBody,
    settings: &FreeSettings,
) -> Option<TokenStream> {
    let (cx, ident, parameters, arena) = ex.split();
    let p = Private;
    let failed = |e: &dyn std::fmt::Display| {
        cannot_derive(cx, ident, "the free body's equations of motion", e)
    };
    let frame = cm_frame(arena, &checked.body.props.inertia_cm)
        .map_err(|e| failed(&e))
        .ok()?;
    let mut symbols = parameters.tokens();
    let (scene, preludes) = scene(arena, checked, settings, &frame, &mut symbols);
    let inertia = &checked.body.props.inertia_cm;
    crate::lang::rotor::literal_driven_inertia(cx, arena, inertia, &settings.driven, ABOUT)?;
    let derivation = scene.derive(arena).map_err(|e| failed(&e)).ok()?;
    crate::lang::export::free(ident, arena, &derivation, &export_inputs(&scene));
    let full_state = derivation.full_state();
    let n = full_state.len();
    let taylor = settings.taylor.map(|order| {
        let prelude = preludes.for_outputs(arena, &derivation.rhs);
        crate::lang::taylor::expand(
            cx,
            ident,
            arena,
            &symbols,
            &derivation.state,
            &derivation.rhs,
            prelude,
            order,
            Some(quote!(#p::FreeDynamics::check_parameters(self).map_err(#p::FreeError::into_ode_error))),
        )
    });
    let low = Lowering::new(cx, ident, symbols);
    let prelude = |arena: &Arena, outputs: &[ExprId]| preludes.for_outputs(arena, outputs);
    let method = StateMethod {
        low: &low,
        state: &full_state,
        prelude: Some(&prelude),
    };
    let rhs = derivation.full_rhs();
    let FreeDerivation {
        force,
        torque,
        energy,
        power,
        linear_momentum,
        angular_momentum,
        ..
    } = &derivation;
    let rhs = method.body(arena, &rhs, |o| quote!(*dydt = [#(#o),*];));
    let wrench_outputs: Vec<ExprId> = force.iter().chain(torque).copied().collect();
    let wrench = method.body(arena, &wrench_outputs, |o| {
        let (f, t) = o.split_at(3);
        quote!(#p::Wrench { force_space: #p::Vector3::new(#(#f),*), torque_principal: #p::Vector3::new(#(#t),*) })
    });
    let energy = method.body(arena, &[*energy], |o| quote!(#(#o)*));
    let power = method.body(arena, &[*power], |o| quote!(#(#o)*));
    let vector = |o: &[TokenStream]| quote!(#p::Vector3::new(#(#o),*));
    let linear = method.body(arena, linear_momentum, vector);
    let angular = method.body(arena, angular_momentum, vector);
    let principal = principal(&low, arena, &frame);
    let gravity = match settings.loads.gravity {
        Some(g) => method.body(arena, &g, vector),
        None => quote!({ #p::Vector3::zeros() }),
    };
    let beyond = match scene.declared_beyond_gravity() {
        Some(name) => quote!(::core::option::Option::Some(#name)),
        None => quote!(::core::option::Option::None),
    };
    let check = check_parameters(parameters, &low, arena, settings);
    let driven_names: Vec<String> = settings
        .driven
        .iter()
        .map(|(k, _)| format!("rotor_{k}"))
        .collect();
    let slots = slot_consts(ident, &driven_names);
    let motor_methods = preludes.motor_methods(n);
    Some(quote! {
        #taylor

        #[automatically_derived]
        impl #ident {
            #(#slots)*
        }

        #[automatically_derived]
        #[allow(unused_variables, clippy::all, clippy::pedantic, clippy::nursery, unused_parens)]
        impl #p::FreeDynamics<#n> for #ident {
            const BEYOND_GRAVITY: ::core::option::Option<&'static str> = #beyond;

            const DRIVEN_ROTORS: &'static [&'static str] = &[#(#driven_names),*];

            #motor_methods

            #[inline]
            fn principal_cm(&self) -> #p::Principal { #principal }

            #[inline]
            fn gravity(&self) -> #p::Vector3<f64> #gravity

            #[inline]
            fn free_rhs(&self, t: f64, y: &[f64; #n], dydt: &mut [f64; #n]) #rhs

            #[inline]
            fn wrench(&self, t: f64, y: &[f64; #n]) -> #p::Wrench #wrench

            fn energy(&self, y: &[f64; #n]) -> f64 #energy

            fn power(&self, t: f64, y: &[f64; #n]) -> f64 #power

            fn linear_momentum(&self, y: &[f64; #n]) -> #p::Vector3<f64> #linear

            fn angular_momentum_origin(&self, y: &[f64; #n]) -> #p::Vector3<f64> #angular

            fn check_parameters(&self) -> ::core::result::Result<(), #p::FreeError> #check
        }
    })
}

/// The body of `principal_cm`: the moments of a diagonal tensor, a constant frame, or the
/// decomposition at run time.
fn principal(low: &Lowering, arena: &mut Arena, frame: &CmFrame) -> TokenStream {
    let p = Private;
    match frame {
        CmFrame::Diagonal(m) => {
            let Emitted { lets, outputs } = low.lower(arena, m);
            quote!(#lets #p::Principal::diagonal(#p::Vector3::new(#(#outputs),*)))
        }
        CmFrame::Constant(pr) => {
            let m = pr.moments.iter().map(|&x| f64_literal(x));
            let r = pr.rotation.matrix();
            let rows = (0..3)
                .flat_map(|i| (0..3).map(move |j| (i, j)))
                .map(|(i, j)| f64_literal(r[(i, j)]));
            quote!(#p::Principal {
                moments: #p::Vector3::new(#(#m),*),
                rotation: #p::Rotation3::from_matrix_unchecked(#p::Matrix3::new(#(#rows),*)),
            })
        }
        CmFrame::AtRunTime => quote!(#p::principal_frame(&#p::RigidBody::inertia_cm(self))),
    }
}

/// The body of `check_parameters`: every field the body and its forces read is finite, drag
/// and damping are not negative (the rule literals meet at compile time), the description
/// keeps its rules, and the mass and principal moments are positive.
fn check_parameters(
    parameters: &FieldParameters,
    low: &Lowering,
    arena: &Arena,
    settings: &FreeSettings,
) -> TokenStream {
    let p = Private;
    let coefficients: Vec<(&str, ExprId)> = [
        (keys::DRAG, settings.loads.drag),
        (keys::DAMPING, settings.loads.damping),
    ]
    .into_iter()
    .filter_map(|(name, c)| c.map(|c| (name, c)))
    .collect();
    let values: Vec<ExprId> = coefficients.iter().map(|&(_, c)| c).collect();
    let Emitted { lets, outputs } = low.lower(arena, &values);
    let signs = coefficients.iter().zip(outputs).map(|(&(name, _), value)| {
        quote! {
            let __c: f64 = #value;
            if __c < 0.0 {
                return ::core::result::Result::Err(#p::FreeError::NegativeCoefficient {
                    name: #name,
                    value: __c,
                });
            }
        }
    });
    let fields = parameters.finite_checks(|name, value| {
        let name = quote!(::std::string::ToString::to_string(#name));
        quote!(#p::FreeError::NonFiniteParameter { name: #name, value: #value })
    });
    // The body must keep a positive definite inertia once the driven wheels turn freely.
    let rotors = crate::lang::rotor::check_tokens(
        low,
        arena,
        (&settings.rotor_index, &settings.loads.rotors),
        &settings.driven,
        &quote!(#p::FreeError),
        &quote!(#p::RigidBody::inertia_cm(self)),
    );
    quote!({
        #fields
        #lets
        #(#signs)*
        #rotors
        #p::RigidBody::validate(self)?;
        let __mass = #p::RigidBody::mass(self);
        let __m = #p::FreeDynamics::principal_cm(self).moments;
        if !(__mass.is_finite() && __mass > 0.0 && __m.iter().all(|v| v.is_finite() && *v > 0.0)) {
            return ::core::result::Result::Err(#p::FreeError::InvalidInertia {
                mass: __mass,
                moments: [__m.x, __m.y, __m.z],
            });
        }
        ::core::result::Result::Ok(())
    })
}

/// A const per slot of the state, named in capitals after [`STATE_NAMES`] (`X`, `VX`, `QW`,
/// `OMEGA_2`, …) and then `driven` (`ROTOR_0`, …: the driven rotors' rates), as a mechanism's
/// derive names its coordinates: `y[Body::VZ]` reads what the CSV column `vz` holds.
pub(super) fn slot_consts(ident: &syn::Ident, driven: &[String]) -> Vec<TokenStream> {
    STATE_NAMES
        .iter()
        .map(|s| (*s).to_owned())
        .chain(driven.iter().cloned())
        .enumerate()
        .map(|(k, name)| {
            let upper = format_ident!("{}", name.to_uppercase(), span = ident.span());
            let doc = format!("The slot of `{name}` in the free body's state array.");
            quote! {
                #[doc = #doc]
                pub const #upper: usize = #k;
            }
        })
        .collect()
}
