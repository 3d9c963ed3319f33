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
    // The values the rules are checked on are the trait's `values`, fields and literals
    // alike.
    assert!(check.contains("values (self) . check ()"), "{check}");
    assert!(method(&code, "values").contains("ContactValues"));
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

/// Values for the property test: literals of every sign and size, fields named like the
/// derivation's own state symbols and the generated code's locals, arithmetic on them.
const VALUES: &[&str] = &[
    "0.02",
    "0.3",
    "-0.01",
    "0.0",
    "1e300",
    "r",
    "x",
    "v_x",
    "q_w",
    "omega_1",
    "y",
    "contact_gamma_1",
    "2.0 * r",
    "r - r",
    "0.01 + x",
];
/// The fields the values may name.
const FIELDS: &str =
    "r: f64, x: f64, v_x: f64, q_w: f64, omega_1: f64, y: f64, contact_gamma_1: f64";

/// A random `#[contact]` scene as source text: any surface and law, any values, now and then
/// a key left out or misspelled.
fn contact_input() -> impl proptest::strategy::Strategy<Value = String> {
    use proptest::prelude::*;
    let v = || proptest::sample::select(VALUES);
    let surface = (
        0..6usize,
        v(),
        v(),
        v(),
        proptest::option::of((v(), v(), v())),
    )
        .prop_map(|(kind, a, b, c, at)| {
            let at = at.map_or(String::new(), |(x, y, z)| {
                format!(", center = [{x}, {y}, {z}]")
            });
            match kind {
                0 => format!("sphere(radius = {a}{at})"),
                1 => format!("ellipsoid(semi_axes = [{a}, {b}, {c}]{at})"),
                2 => format!("disk_rim(radius = {a}{at})"),
                3 => format!("torus(radius = {a}, tube = {b}{at})"),
                4 => format!("paraboloid(curvature_radius = {a})"),
                _ => format!("spehre(radius = {a})"),
            }
        });
    let law = (0..11usize, v()).prop_map(|(kind, c)| match kind {
        0 => "rolling".to_owned(),
        1 => format!("rolling(rolling_resistance = {c})"),
        2 => format!("rolling(spin_resistance = {c}, rolling_resistance = {c})"),
        3 => format!("sliding(viscous = {c})"),
        4 => format!("sliding(coulomb = {c})"),
        5 => "sliding(frictionless)".to_owned(),
        6 => format!("stick_slip(mu = {c})"),
        7 => format!("stick_slip(mu = {c}, rolling_resistance = {c}, pivoting = {c})"),
        8 => format!("sliding(normal_viscous = {c})"),
        9 => format!("rolling(pivoting = {c}, spin_resistance = {c})"),
        _ => format!("sliding(viscous = {c}, coulomb = {c})"),
    });
    (surface, law, proptest::option::of(v()), v(), v()).prop_map(|(surface, law, g, h, m)| {
        let g = g.map_or(String::new(), |g| format!(", gravity = {g}"));
        format!(
            "#[rigid(sphere(mass = 1.0, radius = 0.01, at = [0.0, 0.0, {h}]), particle(mass = {m}, at = [0.001, 0.0, 0.0]))]\n#[contact(surface = {surface}, law = {law}{g})]\nstruct Scene {{ {FIELDS} }}"
        )
    })
}

/// Runs the derive on `source`: it never panics, and gives either code that names precess
/// only through the hidden module and has no error, or errors each spanned on the input and
/// none internal.
fn contact_is_total(source: &str) -> Result<(), proptest::test_runner::TestCaseError> {
    use proptest::prelude::*;
    let input: syn::DeriveInput = syn::parse_str(source)
        .map_err(|e| TestCaseError::fail(format!("bad syntax: {e}\n{source}")))?;
    let cx = Ctxt::new();
    let expanded = crate::rigid_body::expand(&cx, &input);
    match cx.check() {
        Ok(()) => {
            let code = expanded.map(|t| t.to_string()).unwrap_or_default();
            prop_assert!(
                code.contains("ContactDynamics for Scene"),
                "no impl\n{source}"
            );
            for bad in ["INFINITY", "from_bits", "compile_error"] {
                prop_assert!(!code.contains(bad), "`{bad}` emitted for\n{source}");
            }
            prop_assert_eq!(
                code.matches(":: precess ::").count(),
                code.matches(":: precess :: __private ::").count()
            );
        }
        Err(errors) => {
            for e in errors {
                let message = e.to_string();
                prop_assert!(!message.contains("internal error"), "{message}\n{source}");
                let at = e.span().byte_range();
                prop_assert!(at.end > at.start, "`{message}` not spanned\n{source}");
            }
        }
    }
    Ok(())
}

proptest::proptest! {
    #![proptest_config(proptest::test_runner::Config {
        cases: std::env::var("PROPTEST_CASES").ok().and_then(|c| c.parse().ok()).unwrap_or(8),
        failure_persistence: None,
        ..proptest::test_runner::Config::default()
    })]

    /// The class of bug: a value, a name or a surface the macro did not expect making it
    /// panic, emit an unspanned error, or lose a field's symbol.
    #[test]
    fn contact_scenes_give_code_or_spanned_errors(source in contact_input()) {
        contact_is_total(&source)?;
    }
}
