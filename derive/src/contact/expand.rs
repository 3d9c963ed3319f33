//! Expansion of `#[contact]`: the scene derived by precess-core (each phase's right-hand
//! side, reaction, energy and momenta; the contact point, Jellett's quantity), each method one
//! straight-line block over the state array, quoted into `impl ContactDynamics for …`.
//!
//! A phase the law does not derive (the sliding phase of a rolling body) is NaN, as the
//! trait asks: the checked methods refuse it before reading it.

use precess_core::codegen::Emitted;
use precess_core::contact::{
    ContactDerivation, ContactEquations, ContactLaw, ContactTorques, Friction, STATE_LEN,
    SurfaceKind, coefficients,
};
use precess_core::sym::{Arena, ExprId};
use proc_macro2::TokenStream;
use quote::{quote, quote_spanned};
use syn::Ident;
use syn::spanned::Spanned;

use super::check::ContactSettings;
use crate::lang::ctxt::Ctxt;
use crate::lang::expansion::{Expansion, cannot_derive};
use crate::lang::private::Private;
use crate::lang::symbols::{FieldParameters, Lowering, StateMethod};
use crate::rigid::check::CheckedBody;

/// `impl ContactDynamics for …`, or `None` after recording why the equations could not be
/// derived.
pub fn expand(
    ex: &mut Expansion,
    checked: &CheckedBody,
    settings: &ContactSettings,
) -> Option<TokenStream> {
    let (cx, ident, parameters, arena) = ex.split();
    let p = Private;
    let scene = settings.scene(checked);
    let what = "the equations of the body on the table";
    let mut torques = settings.torques;
    let mut symbols = parameters.tokens();
    // The user couple enters the derivation as three input symbols, read from the value the
    // user function returns.
    if settings.couple.is_some() {
        let u: [ExprId; 3] =
            std::array::from_fn(|i| arena.input(&format!("contact_couple_{}", i + 1)));
        for (i, &ui) in u.iter().enumerate() {
            symbols.insert_expr(arena, ui, quote!(__u[#i]));
        }
        torques.user = Some(u);
    }
    let derivation = scene
        .derive_with(arena, &torques)
        .map_err(|e| cannot_derive(cx, ident, what, &e))
        .ok()?;
    // The user couple's value is the export's input: its caller supplies it.
    let inputs = crate::lang::export::vector_inputs(torques.user.as_ref(), "couple");
    crate::lang::export::contact(ident, arena, &derivation, &inputs);
    let low = Lowering::new(cx, ident, symbols);
    let couple =
        |arena: &Arena, outputs: &[ExprId]| couple_call(arena, outputs, settings, &torques);
    let method = StateMethod {
        low: &low,
        state: &derivation.state,
        prelude: Some(&couple),
    };
    let vector = |o: &[TokenStream]| quote!(#p::Vector3::new(#(#o),*));
    let ContactDerivation {
        rolling,
        sliding,
        gamma,
        contact_body,
        contact_space,
        height,
        contact_velocity,
        jellett,
        angular_momentum_center,
        ..
    } = &derivation;
    let phases = [rolling.as_ref(), sliding.as_ref()];
    let by_phase = |arena: &mut Arena,
                    outputs: &dyn Fn(&ContactEquations) -> Vec<ExprId>,
                    build: &dyn Fn(&[TokenStream]) -> TokenStream,
                    absent: TokenStream| {
        let [rolling, sliding] = phases.map(|e| match e {
            Some(e) => method.body(arena, &outputs(e), build),
            None => absent.clone(),
        });
        quote!({
            match phase {
                #p::Phase::Rolling => #rolling,
                #p::Phase::Sliding => #sliding,
            }
        })
    };
    let nan = quote!(f64::NAN);
    let rhs = by_phase(
        arena,
        &|e| e.rhs.to_vec(),
        &|o| quote!({ *dydt = [#(#o),*]; }),
        quote!({ *dydt = [#nan; #STATE_LEN]; }),
    );
    let reaction = by_phase(
        arena,
        &|e| std::iter::once(e.normal).chain(e.friction).collect(),
        &|o| match o {
            [n, f @ ..] => quote!(#p::Reaction { normal: #n, friction: #p::Vector3::new(#(#f),*) }),
            [] => quote!(),
        },
        quote!(#p::Reaction { normal: #nan, friction: #p::Vector3::repeat(#nan) }),
    );
    let energy = by_phase(
        arena,
        &|e| vec![e.energy],
        &|o| quote!(#(#o)*),
        quote!(#nan),
    );
    let momenta = by_phase(
        arena,
        &|e| {
            e.linear_momentum
                .iter()
                .chain(angular_momentum_center)
                .chain(&e.angular_momentum_contact)
                .copied()
                .collect()
        },
        &|o| {
            let (linear, rest) = o.split_at(3);
            let (center, contact) = rest.split_at(3);
            quote!(#p::ContactMomenta {
                linear: #p::Vector3::new(#(#linear),*),
                center: #p::Vector3::new(#(#center),*),
                contact: #p::Vector3::new(#(#contact),*),
            })
        },
        quote!(#p::ContactMomenta {
            linear: #p::Vector3::repeat(#nan),
            center: #p::Vector3::repeat(#nan),
            contact: #p::Vector3::repeat(#nan),
        }),
    );
    let point_outputs: Vec<ExprId> = gamma
        .iter()
        .chain(contact_body)
        .chain(contact_space)
        .chain(std::iter::once(height))
        .chain(contact_velocity)
        .copied()
        .collect();
    let contact = method.body(arena, &point_outputs, |o| match o {
        [g @ .., h, u0, u1, u2] if g.len() == 9 => {
            let (g, b, s) = (vector(&g[..3]), vector(&g[3..6]), vector(&g[6..]));
            quote!(#p::ContactPoint { gamma: #g, body: #b, space: #s, height: #h, velocity: #p::Vector3::new(#u0, #u1, #u2) })
        }
        _ => quote!(),
    });
    let jellett = method.body(arena, &[*jellett], |o| quote!(#(#o)*));
    let law = law_kind(&scene.law);
    let surface_kind = surface_kind(scene.surface.kind());
    let mu = match scene.law {
        ContactLaw::Sliding(Friction::Coulomb(mu)) | ContactLaw::StickSlip { mu } => Some(mu),
        _ => None,
    };
    let friction_coefficient = match mu {
        Some(mu) => {
            let Emitted { lets, outputs } = low.lower(arena, &[mu]);
            quote!({ #lets ::core::option::Option::Some(#(#outputs)*) })
        }
        None => quote!({ ::core::option::Option::None }),
    };
    let (check, values) = check_parameters((cx, ident), parameters, &low, arena, &derivation);
    Some(quote! {
        #[automatically_derived]
        #[allow(unused_variables, clippy::all, clippy::pedantic, clippy::nursery, unused_parens)]
        impl #p::ContactDynamics for #ident {
            #[inline]
            fn law(&self) -> #p::LawKind { #law }

            #[inline]
            fn surface_kind(&self) -> #p::SurfaceKind { #surface_kind }

            #[inline]
            fn phase_rhs(&self, phase: #p::Phase, t: f64, y: &[f64; #STATE_LEN], dydt: &mut [f64; #STATE_LEN]) #rhs

            #[inline]
            fn reaction(&self, phase: #p::Phase, y: &[f64; #STATE_LEN]) -> #p::Reaction #reaction

            fn energy(&self, phase: #p::Phase, y: &[f64; #STATE_LEN]) -> f64 #energy

            fn momenta(&self, phase: #p::Phase, y: &[f64; #STATE_LEN]) -> #p::ContactMomenta #momenta

            fn contact(&self, y: &[f64; #STATE_LEN]) -> #p::ContactPoint #contact

            fn jellett(&self, y: &[f64; #STATE_LEN]) -> f64 #jellett

            fn friction_coefficient(&self) -> ::core::option::Option<f64> #friction_coefficient

            fn check_parameters(&self) -> ::core::result::Result<(), #p::ContactError> #check

            fn values(&self) -> #p::ContactValues #values
        }
    })
}

/// The `LawKind` of `law`.
fn law_kind(law: &ContactLaw) -> TokenStream {
    let p = Private;
    match law {
        ContactLaw::Rolling { .. } => quote!(#p::LawKind::Rolling),
        ContactLaw::Sliding(_) => quote!(#p::LawKind::Sliding),
        ContactLaw::StickSlip { .. } => quote!(#p::LawKind::StickSlip),
    }
}

/// The `SurfaceKind` of `kind`.
fn surface_kind(kind: SurfaceKind) -> TokenStream {
    let p = Private;
    match kind {
        SurfaceKind::Sphere => quote!(#p::SurfaceKind::Sphere),
        SurfaceKind::Ellipsoid => quote!(#p::SurfaceKind::Ellipsoid),
        SurfaceKind::DiskRim => quote!(#p::SurfaceKind::DiskRim),
        SurfaceKind::Torus => quote!(#p::SurfaceKind::Torus),
        SurfaceKind::Paraboloid => quote!(#p::SurfaceKind::Paraboloid),
    }
}

/// The call of the user couple, `let __u = f(self, &R, &ω);`, where `outputs` read its
/// value (nothing otherwise). The function is first bound to a fn pointer of the signature
/// the attribute documents, spanned on its path: a function of another signature is then one
/// error on the path in the attribute, naming the expected and the found signature.
fn couple_call(
    arena: &Arena,
    outputs: &[ExprId],
    settings: &ContactSettings,
    torques: &ContactTorques,
) -> TokenStream {
    let (Some(path), Some(u)) = (&settings.couple, torques.user) else {
        return TokenStream::new();
    };
    let read = u
        .iter()
        .filter_map(|&e| arena.as_symbol(e))
        .any(|s| outputs.iter().any(|&o| arena.free_symbols(o).contains(&s)));
    if !read {
        return TokenStream::new();
    }
    let p = Private;
    let bind = quote_spanned! {path.span()=>
        let __torque: fn(&Self, &#p::Matrix3<f64>, &#p::Vector3<f64>) -> #p::Vector3<f64> = #path;
    };
    quote! {
        #bind
        let __r = #p::attitude_of(y).to_rotation_matrix().into_inner();
        let __u = __torque(self, &__r, &#p::Vector3::new(y[8], y[9], y[10]));
    }
}

/// The bodies of `check_parameters` and `values`: the description keeps its rules
/// (`RigidBody::validate`), then the scene's values (`values`), fields and literals alike,
/// meet the one rule of `ContactValues::check` that the interpreted model and the
/// compile-time checks apply.
fn check_parameters(
    (cx, ident): (&Ctxt, &Ident),
    parameters: &FieldParameters,
    low: &Lowering,
    arena: &Arena,
    derivation: &ContactDerivation,
) -> (TokenStream, TokenStream) {
    let p = Private;
    let scene = &derivation.scene;
    let (placement, lengths) = scene.surface.dimensions();
    let coefficients = coefficients(&scene.law, &derivation.torques);
    let mut values: Vec<ExprId> = vec![scene.mass, scene.gravity];
    values.extend(scene.center);
    values.extend(scene.inertia.iter().flatten());
    values.extend(placement);
    values.extend(lengths.iter().map(|&(_, e)| e));
    values.extend(coefficients.iter().map(|&(_, e)| e));
    let Emitted { lets, outputs } = low.lower(arena, &values);
    // One output per value, in the order pushed above.
    let (head, rest) = outputs.split_at(outputs.len().min(17));
    let [mass, gravity, c0, c1, c2, tensor @ .., p0, p1, p2] = head else {
        cx.error_spanned_by(
            ident,
            "internal error of the derive: the contact's parameter values were not lowered one for one; please report this",
        );
        return (TokenStream::new(), TokenStream::new());
    };
    let center = [c0, c1, c2];
    let rows = tensor.chunks(3).map(|r| quote!([#(#r),*]));
    let placement = [p0, p1, p2];
    let (length_values, coefficient_values) = rest.split_at(rest.len().min(lengths.len()));
    let length_names = lengths.iter().map(|&(n, _)| n);
    let coefficient_names = coefficients.iter().map(|&(n, _)| n);
    let surface = surface_kind(scene.surface.kind());
    let fields = parameters.finite_checks(|name, value| {
        quote!(#p::ContactError::BadParameter { name: #name, value: #value, rule: "finite" })
    });
    let check = quote!({
        #fields
        #p::RigidBody::validate(self)?;
        #p::ContactDynamics::values(self).check()
    });
    let values = quote!({
        #lets
        #p::ContactValues {
            mass: #mass,
            center: [#(#center),*],
            inertia: [#(#rows),*],
            gravity: #gravity,
            surface: #surface,
            placement: [#(#placement),*],
            lengths: #p::vec![#((#length_names, #length_values)),*],
            coefficients: #p::vec![#((#coefficient_names, #coefficient_values)),*],
        }
    });
    (check, values)
}
