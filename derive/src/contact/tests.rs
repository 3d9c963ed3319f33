//! What `#[contact]` emits, checked on its tokens, and the size of the code it derives (run
//! with `--nocapture` to read the operation counts).

use precess_core::codegen::{OpCount, Program};
use precess_core::sym::Arena;
use proc_macro2::TokenStream;
use quote::quote;

use crate::lang::ast::Input;
use crate::lang::check::Checker;
use crate::lang::ctxt::Ctxt;
use crate::lang::keys;
use crate::lang::symbols::FieldParameters;
use crate::lang::tests::{method, rigid_body as expand};
use crate::rigid;

/// The tippe top of the docs.
fn tippe_top() -> TokenStream {
    quote! {
        #[rigid(sphere(mass = 0.015, radius = 0.02), particle(mass = 0.001, at = [0.0, 0.0, 0.015]))]
        #[contact(surface = sphere(radius = 0.02), law = sliding(viscous = 0.3), gravity = 9.81)]
        struct TippeTop;
    }
}

/// Kane & Levinson's rattleback.
fn rattleback() -> TokenStream {
    quote! {
        #[rigid(body(mass = 1.0, inertia = [[2e-4, -2e-5, 0.0], [-2e-5, 1.6e-3, 0.0], [0.0, 0.0, 1.7e-3]]))]
        #[contact(surface = ellipsoid(semi_axes = [0.2, 0.03, 0.02], center = [0.0, 0.0, 0.01]), law = rolling, gravity = 9.81)]
        struct Rattleback;
    }
}

/// The operation counts of the right-hand side and the reaction of each phase the scene
/// derives, `(phase, rhs, reaction)`, through the macro's own check and the engine.
fn counts(input: TokenStream) -> Vec<(&'static str, OpCount, OpCount)> {
    let input: syn::DeriveInput = syn::parse2(input).expect("a struct");
    let cx = Ctxt::new();
    let ast = Input::for_derive(&cx, &input, "RigidBody").expect("a struct");
    let rigid_items = rigid::attr::parse(&cx, &ast.rigid);
    let attrs = ast.attributes(keys::CONTACT);
    let items = super::attr::parse(&cx, &attrs);
    let mut arena = Arena::new();
    let mut parameters = FieldParameters::default();
    let mut ck = Checker::new(&cx, &ast, &mut arena, &mut parameters);
    let body = rigid::check::check(&mut ck, &rigid_items).expect("the body");
    let settings = super::check::check(&mut ck, &attrs, &items, Some(&body));
    let settings = settings.flatten().expect("the contact");
    cx.check().expect("no errors");
    let d = settings.scene(&body).derive(&mut arena).expect("derived");
    [
        ("rolling", d.rolling.as_ref()),
        ("sliding", d.sliding.as_ref()),
    ]
    .into_iter()
    .filter_map(|(name, e)| {
        let e = e?;
        let reaction: Vec<_> = std::iter::once(e.normal).chain(e.friction).collect();
        Some((
            name,
            Program::lower(&arena, &e.rhs).op_count(),
            Program::lower(&arena, &reaction).op_count(),
        ))
    })
    .collect()
}

#[test]
fn the_tippe_top_emits_one_sliding_phase_of_literals() {
    let code = expand(tippe_top());
    assert!(!code.contains("compile_error"), "{code}");
    let rhs = method(&code, "phase_rhs");
    println!("phase_rhs: {rhs}\n");
    // Viscous sliding only: the rolling arm is NaN, and the literal c = 0.3 is folded in.
    assert!(
        rhs.contains("Phase :: Rolling => { * dydt = [f64 :: NAN ; 11usize] ; }"),
        "{rhs}"
    );
    assert!(!rhs.contains("self ."), "{rhs}");
    assert!(code.contains("LawKind :: Sliding"), "{code}");
    assert!(code.contains("SurfaceKind :: Sphere"), "{code}");
    // Viscous friction has no Coulomb coefficient.
    assert!(method(&code, "friction_coefficient").contains("Option :: None"));
    for (phase, rhs, reaction) in counts(tippe_top()) {
        println!("tippe top, {phase}: rhs {rhs}; reaction {reaction}");
        assert_eq!(phase, "sliding");
        // The sliding phase solves for N once: no square root (viscous friction needs no
        // slip speed), and a handful of divisions.
        assert_eq!(rhs.sqrts, 0, "{rhs}");
        assert!(rhs.total() < 600, "{rhs}");
    }
}

#[test]
fn the_rattleback_rolls_with_one_square_root() {
    let code = expand(rattleback());
    assert!(!code.contains("compile_error"), "{code}");
    assert!(code.contains("LawKind :: Rolling"), "{code}");
    let rhs = method(&code, "phase_rhs");
    assert!(
        rhs.contains("Phase :: Sliding => { * dydt = [f64 :: NAN ; 11usize] ; }"),
        "{rhs}"
    );
    for (phase, rhs, reaction) in counts(rattleback()) {
        println!("rattleback, {phase}: rhs {rhs}; reaction {reaction}");
        assert_eq!(phase, "rolling");
        // The ellipsoid's support point has one √(γᵀ D² γ), shared by r and ṙ.
        assert_eq!(rhs.sqrts, 1, "{rhs}");
        assert!(rhs.total() < 700, "{rhs}");
    }
}

#[test]
fn fields_are_read_and_checked_at_run_time() {
    let code = expand(quote! {
        #[rigid(disk(mass = m, radius = r))]
        #[contact(surface = disk_rim(radius = r), law = stick_slip(mu = mu), gravity = g)]
        struct Coin { m: f64, r: f64, mu: f64, g: f64 }
    });
    assert!(!code.contains("compile_error"), "{code}");
    let check = method(&code, "check_parameters");
    for field in ["\"m\"", "\"r\"", "\"mu\"", "\"g\""] {
        assert!(check.contains(field), "{field}: {check}");
    }
    assert!(check.contains("check_contact_values"), "{check}");
    assert!(method(&code, "friction_coefficient").contains("self . mu"));
    // Stick–slip derives both phases.
    let rhs = method(&code, "phase_rhs");
    assert!(!rhs.contains("NAN"), "{rhs}");
}

#[test]
fn a_disk_whose_centre_of_mass_is_off_its_rim_is_refused() {
    // The disk rim of radius 0.05 about the origin, the mass 0.08 from its axis.
    let code = expand(quote! {
        #[rigid(sphere(mass = 1.0, radius = 0.01, at = [0.08, 0.0, 0.0]))]
        #[contact(surface = disk_rim(radius = 0.05), law = rolling, gravity = 9.81)]
        struct Lopsided;
    });
    assert!(code.contains("lies outside the disk_rim"), "{code}");
    assert!(code.contains("ContactDynamics for Lopsided"), "{code}");
}

#[test]
fn a_parametric_surface_is_judged_at_run_time_not_now() {
    let code = expand(quote! {
        #[rigid(sphere(mass = 1.0, radius = 0.01, at = [0.0, 0.0, h]))]
        #[contact(surface = sphere(radius = rho), law = rolling, gravity = 9.81)]
        struct Parametric { h: f64, rho: f64 }
    });
    assert!(!code.contains("compile_error"), "{code}");
}
