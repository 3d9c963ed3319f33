//! `impl Export` for every derived struct: the scene's programs written as text
//! (`precess_core::codegen::Exported::to_text`) while the macro expands, read back at run
//! time to emit C99 or Python (`docs/export.md`).
//!
//! Text rather than the C and the Python themselves: one string literal a third of their
//! size, no formatting of either in the macro, and one emitter for derived structs and
//! scenes built at run time. Each function is lowered from the same outputs as the Rust
//! method it stands for, so its program is that method's.
//!
//! `#[derive(RigidBody)]` runs the expansion of a scene (top, free, contact) before the
//! body's own, and only the latter's tokens are certain to be emitted last: a scene
//! registers its export here ([`top`], [`driven_top`], [`free`], [`contact`]), keyed by the expansion's
//! arena, and [`body`] emits it, or the body's torque-free Euler equations when no scene
//! registered one (in principal axes, or in the description axes when the principal frame
//! is found only at run time), so a struct gets one `impl Export` whatever its attributes. A
//! `#[derive(Mechanism)]` emits its own ([`mechanism`], [`rolling`], [`closed`]), and so does
//! `taylor_system!` ([`system`]).

use std::cell::RefCell;

use precess_core::codegen::{ExportBuilder, ExportError, Exported};
use precess_core::contact::ContactDerivation;
use precess_core::free::FreeDerivation;
use precess_core::lagrange::EquationsOfMotion;
use precess_core::mechanism::MechanismDerivation;
use precess_core::mechanism::loops::LoopDerivation;
use precess_core::mechanism::rolling::RollingDerivation;
use precess_core::sym::{Arena, ExprId};
use proc_macro2::TokenStream;
use quote::{ToTokens, quote};
use syn::Ident;

use super::expansion::Expansion;
use super::private::Private;
use crate::rigid::check::CheckedBody;

/// An export's text, or why there is none.
type Text = Result<String, String>;

/// The values a scene's Rust code takes from user functions (a motor's torque, a user
/// torque's components), each symbol with its name: the export's inputs u, which the caller
/// of the C or the Python supplies.
pub type Inputs = Vec<(ExprId, String)>;

thread_local! {
    /// The export a scene registered, keyed by the arena of its expansion (`Arena::zero`'s id
    /// carries the arena's tag): at most one entry, so an expansion that failed before
    /// [`body`] ran cannot leave its export to another struct.
    static REGISTERED: RefCell<Option<(ExprId, Text)>> = const { RefCell::new(None) };
}

/// Records the export of the scene derived in `arena` (the first one registered wins).
fn register(arena: &Arena, text: Text) {
    REGISTERED.with(|r| {
        let mut r = r.borrow_mut();
        if r.as_ref().is_none_or(|(key, _)| *key != arena.zero()) {
            *r = Some((arena.zero(), text));
        }
    });
}

/// The export registered for `arena`, if any; clears the registry.
fn take(arena: &Arena) -> Option<Text> {
    REGISTERED.with(|r| {
        r.borrow_mut()
            .take()
            .and_then(|(key, text)| (key == arena.zero()).then_some(text))
    })
}

/// `TippeTop` → `tippe_top`, the C and Python prefix.
fn snake_case(ident: &Ident) -> String {
    let mut s = String::new();
    for (i, c) in ident.to_string().chars().enumerate() {
        if c.is_uppercase() && i > 0 {
            s.push('_');
        }
        s.extend(c.to_lowercase());
    }
    s
}

fn text(built: Result<Exported, ExportError>) -> Text {
    built.map(|e| e.to_text()).map_err(|e| e.to_string())
}

/// One function added to a builder: `(name, doc, lowered outputs, kept range, shape)`.
type Function<'a> = (
    &'a str,
    &'a str,
    Vec<ExprId>,
    std::ops::Range<usize>,
    (usize, usize),
);

/// The scene `ident` over `state` with `functions`, the Jacobian of the function
/// `jacobian_of` (an index) added as `jacobian`; the state's entries named as their symbols.
fn build(
    ident: &Ident,
    arena: &mut Arena,
    state: &[ExprId],
    functions: &[Function],
    jacobian_of: Option<usize>,
) -> Result<Exported, ExportError> {
    build_inputs(ident, arena, state, &[], functions, jacobian_of)
}

/// [`build`] with the `inputs` the caller supplies, named as given.
fn build_inputs(
    ident: &Ident,
    arena: &mut Arena,
    state: &[ExprId],
    inputs: &[(ExprId, String)],
    functions: &[Function],
    jacobian_of: Option<usize>,
) -> Result<Exported, ExportError> {
    let names = symbol_names(arena, state);
    build_with(
        ident,
        arena,
        (state, &names, inputs),
        functions,
        jacobian_of,
    )
}

/// The names of `state`'s symbols. The arena tells apart symbols made under one name (the
/// rate `omega_1` of the body's impl and of its export) by trailing primes; the export has
/// only its own.
pub fn symbol_names(arena: &Arena, state: &[ExprId]) -> Vec<String> {
    state
        .iter()
        .filter_map(|&e| arena.as_symbol(e))
        .map(|s| arena.symbol(s).name.trim_end_matches('\'').to_owned())
        .collect()
}

/// [`build`] over `state` named `names`, its functions reading the `inputs` the caller
/// supplies too.
fn build_with(
    ident: &Ident,
    arena: &mut Arena,
    (state, names, inputs): (&[ExprId], &[String], &[(ExprId, String)]),
    functions: &[Function],
    jacobian_of: Option<usize>,
) -> Result<Exported, ExportError> {
    let symbols: Vec<ExprId> = inputs.iter().map(|(e, _)| *e).collect();
    let mut b = ExportBuilder::with_inputs(&snake_case(ident), arena, state, &symbols)?;
    b.name_state(&names.iter().map(String::as_str).collect::<Vec<_>>())?;
    b.name_inputs(&inputs.iter().map(|(_, n)| n.as_str()).collect::<Vec<_>>())?;
    for (name, doc, lowered, kept, shape) in functions {
        b.function_of(arena, name, doc, lowered, kept.clone(), *shape)?;
    }
    if let Some((_, _, lowered, kept, _)) = jacobian_of.and_then(|i| functions.get(i)) {
        let of = &lowered[kept.clone()];
        let doc = if inputs.is_empty() {
            "the Jacobian of the state derivative, d(dy/dt)/dy"
        } else {
            "the Jacobian of the state derivative, d(dy/dt)/dy, the inputs u held"
        };
        b.jacobian(arena, "jacobian", doc, of)?;
    }
    Ok(b.finish())
}

/// The `mass` and `forcing` functions of a mechanism's tree, documented by `docs`, lowered
/// together from `eqs` as its `(M, f)` method lowers them.
fn mass_and_forcing<'a>(eqs: &EquationsOfMotion, docs: [&'a str; 2]) -> [Function<'a>; 2] {
    let n = eqs.coords.len();
    let both = eqs.mass_then_forcing();
    let [mass, forcing] = docs;
    [
        ("mass", mass, both.clone(), 0..n * n, (n, n)),
        ("forcing", forcing, both, n * n..n * n + n, (n, 1)),
    ]
}

/// A function returning all it lowers.
fn whole<'a>(name: &'a str, doc: &'a str, outputs: Vec<ExprId>) -> Function<'a> {
    let n = outputs.len();
    (name, doc, outputs, 0..n, (n, 1))
}

/// A top without motors: the declared chart's `[q, q̇]`, its derivative `(q̇, q̈)` (q̈ lowered
/// alone, as the chart's `accelerations` arm is: the rates are bare inputs) and its
/// Jacobian (the last three rows are `angle_jacobian`'s, which holds a user torque's
/// value as this one holds the `inputs`).
pub fn top(ident: &Ident, arena: &mut Arena, state: &[ExprId], inputs: &Inputs, rhs: &[ExprId]) {
    let f = [whole("rhs", "the state derivative dy/dt", rhs.to_vec())];
    let built = build_inputs(ident, arena, state, inputs, &f, Some(0));
    register(arena, text(built));
}

/// A top with driven rotors: the declared chart's `[q, q̇, Ω]` (each wheel's rate named
/// `rotor_k` as `TopDynamics::coordinate` names it), the motors' torques (and a user
/// torque's components) the inputs u, its derivative `(q̇, q̈, Ω̇)` lowered as `rhs_in`
/// lowers it (q̈ and Ω̇ together; the rates q̇ are bare inputs) and its Jacobian in y at
/// fixed u.
pub fn driven_top(
    ident: &Ident,
    arena: &mut Arena,
    (state, names, motors): (&[ExprId], &[String], &Inputs),
    rhs: &[ExprId],
) {
    let f = [whole("rhs", "the state derivative dy/dt", rhs.to_vec())];
    let built = build_with(ident, arena, (state, names, motors), &f, Some(0));
    register(arena, text(built));
}

/// A vector's three symbols as inputs named `{name}_x`, `{name}_y`, `{name}_z`.
pub fn vector_inputs(v: Option<&[ExprId; 3]>, name: &str) -> Inputs {
    v.iter()
        .flat_map(|v| v.iter().zip(["x", "y", "z"]))
        .map(|(&e, axis)| (e, format!("{name}_{axis}")))
        .collect()
}

/// A free body: its `free_rhs` over the full state, its energy; `inputs` the values of its
/// user functions (motors, force, torque, wrench).
pub fn free(ident: &Ident, arena: &mut Arena, d: &FreeDerivation, inputs: &Inputs) {
    let f = [
        whole("rhs", "the state derivative dy/dt", d.full_rhs()),
        whole("energy", "the energy", vec![d.energy]),
    ];
    let built = build_inputs(ident, arena, &d.full_state(), inputs, &f, None);
    register(arena, text(built));
}

/// A body on a table: each derived phase's right-hand side, reaction (N, then the friction
/// force) and energy, and Jellett's quantity, each lowered as its method is; `inputs` a user
/// couple's components.
pub fn contact(ident: &Ident, arena: &mut Arena, d: &ContactDerivation, inputs: &Inputs) {
    let mut f: Vec<Function> = Vec::new();
    let phases = [
        (
            d.rolling.as_ref(),
            ["rhs_rolling", "reaction_rolling", "energy_rolling"],
        ),
        (
            d.sliding.as_ref(),
            ["rhs_sliding", "reaction_sliding", "energy_sliding"],
        ),
    ];
    for (e, [rhs, reaction, energy]) in phases {
        let Some(e) = e else { continue };
        f.push(whole(
            rhs,
            "the state derivative dy/dt in this phase",
            e.rhs.to_vec(),
        ));
        let r = std::iter::once(e.normal).chain(e.friction).collect();
        f.push(whole(
            reaction,
            "the normal force N and the friction force (space axes)",
            r,
        ));
        f.push(whole(energy, "the energy", vec![e.energy]));
    }
    f.push(whole("jellett", "Jellett's quantity", vec![d.jellett]));
    let built = build_inputs(ident, arena, &d.state, inputs, &f, None);
    register(arena, text(built));
}

/// The struct's `impl Export`, after `before`: a scene's registered export, or the body's
/// torque-free Euler equations `ω̇ = f(ω)` with their Jacobian: in principal axes (as
/// `taylor = K` on `#[rigid]` emits them) when the principal frame is known at compile time,
/// else in the description axes, `ω̇ = I⁻¹ (−ω × I ω)` over the full tensor of fields (the
/// principal frame is an eigen-decomposition the straight-line export has no place for).
pub fn body(ex: &mut Expansion, checked: &CheckedBody, before: impl ToTokens) -> TokenStream {
    let (ident, arena) = (ex.ident, &mut *ex.arena);
    let text = take(arena).unwrap_or_else(|| {
        let omega: [ExprId; 3] = std::array::from_fn(|i| arena.input(&format!("omega_{}", i + 1)));
        let zero = [arena.zero(); 3];
        let (rhs, doc) = match checked.body.euler_rhs_principal(arena, omega, zero) {
            Ok(Some(rhs)) => (rhs, "Euler's equations, dω/dt in principal axes"),
            Ok(None) => match checked.body.euler_rhs_description(arena, omega, zero) {
                Ok(rhs) => (
                    rhs,
                    "Euler's equations, dω/dt = I⁻¹(−ω × I ω) in the description axes (the body's principal frame is found only at run time)",
                ),
                Err(e) => return Err(format!("the inertia tensor cannot be inverted: {e}")),
            },
            Err(e) => return Err(e.to_string()),
        };
        let f = [whole("rhs", doc, rhs.to_vec())];
        text(build(ident, arena, &omega, &f, Some(0)))
    });
    let export = tokens(ident, text);
    quote!(#before #export)
}

/// A tree mechanism's `impl Export`, after `before`: `(q̇, q̈)` over `[q, q̇]`, q̈ lowered with
/// the pivots as its methods lower it; `inputs` the values of its `effort = f` functions.
pub fn mechanism(
    ident: &Ident,
    arena: &mut Arena,
    (d, inputs): (&MechanismDerivation, &Inputs),
    before: impl ToTokens,
) -> TokenStream {
    let c = &d.coordinates;
    let state: Vec<ExprId> = c.q.iter().chain(&c.rates).copied().collect();
    let np = d.pivots.len();
    let lowered: Vec<ExprId> = d
        .pivots
        .iter()
        .chain(&c.rates)
        .chain(&d.accelerations)
        .copied()
        .collect();
    let n = lowered.len() - np;
    let f = [(
        "rhs",
        "the state derivative dy/dt",
        lowered,
        np..np + n,
        (n, 1),
    )];
    let built = build_inputs(ident, arena, &state, inputs, &f, None);
    let export = tokens(ident, text(built));
    quote!(#before #export)
}

/// A rolling mechanism's `impl Export`, after `before`: the pieces of Maggi's equations its
/// methods compute from generated code, over `[q, q̇]` (every coordinate and its rate; the
/// projection onto the free speeds is numerical, the caller's): M and f lowered together as
/// `mass_forcing` lowers them, A and Ȧq̇ as `constraint_rows`, the wheels' heights and T + V.
pub fn rolling(
    ident: &Ident,
    arena: &mut Arena,
    (d, inputs): (&RollingDerivation, &Inputs),
    before: impl ToTokens,
) -> TokenStream {
    let c = d.coordinates();
    let (n, m) = (c.len(), d.rows());
    let state: Vec<ExprId> = c.q.iter().chain(&c.rates).copied().collect();
    let rows: Vec<ExprId> = d
        .constraints
        .coefficients
        .iter()
        .flatten()
        .chain(&d.rate_terms)
        .copied()
        .collect();
    let zero = arena.zero();
    let heights: Vec<ExprId> = d
        .constraints
        .positions
        .iter()
        .map(|h| h.unwrap_or(zero))
        .collect();
    let energy = arena.add(d.kinetic, d.potential);
    let [mass, forcing] = mass_and_forcing(
        &d.equations,
        [
            "the mass matrix M(q) of the unconstrained tree, M q'' = f + A^T lambda",
            "the forcing f(t, q, q') of the unconstrained tree",
        ],
    );
    let f = [
        mass,
        forcing,
        (
            "constraints",
            "the wheels' constraint rows A(q), A q' = 0",
            rows.clone(),
            0..m * n,
            (m, n),
        ),
        (
            "rate_terms",
            "the rate terms (dA/dt) q', A q'' + (dA/dt) q' = 0",
            rows,
            m * n..m * n + m,
            (m, 1),
        ),
        whole(
            "heights",
            "each row's position function: a wheel's height, 0 for a no-slip row",
            heights,
        ),
        whole("energy", "the energy T + V", vec![energy]),
    ];
    let export = tokens(
        ident,
        text(build_inputs(ident, arena, &state, inputs, &f, None)),
    );
    quote!(#before #export)
}

/// A closed mechanism's `impl Export`, after `before`: the pieces of its equations its
/// `LoopDynamics` methods compute from generated code, over `[q, q̇]` (the choice of the
/// dependent coordinates and the projection are numerical, the caller's): M and f lowered
/// together as `mass_forcing` lowers them, φ and A as `closure`, Ȧq̇ and T + V.
pub fn closed(
    ident: &Ident,
    arena: &mut Arena,
    (d, inputs): (&LoopDerivation, &Inputs),
    before: impl ToTokens,
) -> TokenStream {
    let c = d.coordinates();
    let (n, m) = (c.len(), d.constraints.len());
    let state: Vec<ExprId> = c.q.iter().chain(&c.rates).copied().collect();
    let zero = arena.zero();
    let closure: Vec<ExprId> = d
        .constraints
        .positions
        .iter()
        .map(|h| h.unwrap_or(zero))
        .chain(d.constraints.coefficients.iter().flatten().copied())
        .collect();
    let energy = arena.add(d.kinetic, d.potential);
    let [mass, forcing] = mass_and_forcing(
        &d.equations,
        [
            "the mass matrix M(q) of the tree cut open, M q'' = f + A^T lambda",
            "the forcing f(t, q, q') of the tree cut open",
        ],
    );
    let f = [
        mass,
        forcing,
        (
            "closure",
            "the closure rows phi(q), zero when every loop is closed",
            closure.clone(),
            0..m,
            (m, 1),
        ),
        (
            "constraints",
            "their Jacobian A(q) = d(phi)/dq, A q' = 0",
            closure,
            m..m + m * n,
            (m, n),
        ),
        whole(
            "rate_terms",
            "the rate terms (dA/dt) q', A q'' + (dA/dt) q' = 0",
            d.rate_terms.clone(),
        ),
        whole("energy", "the energy T + V", vec![energy]),
    ];
    let built = build_inputs(ident, arena, &state, inputs, &f, None);
    let export = tokens(ident, text(built));
    quote!(#before #export)
}

/// A `taylor_system!`'s `impl Export`, after `before`: its state, its right-hand side (lowered
/// whole, as `System::rhs` lowers it) and the Jacobian of it.
pub fn system(
    ident: &Ident,
    arena: &mut Arena,
    state: &[ExprId],
    rhs: &[ExprId],
    before: impl ToTokens,
) -> TokenStream {
    let f = [whole("rhs", "the state derivative dy/dt", rhs.to_vec())];
    let export = tokens(ident, text(build(ident, arena, state, &f, Some(0))));
    quote!(#before #export)
}

/// `impl Export for ident` with `text`.
fn tokens(ident: &Ident, text: Text) -> TokenStream {
    let p = Private;
    let value = match text {
        Ok(t) => quote!(::core::result::Result::Ok(#t)),
        Err(reason) => quote!(::core::result::Result::Err(#reason)),
    };
    quote! {
        #[automatically_derived]
        impl #p::Export for #ident {
            const EXPORTED: ::core::result::Result<&'static str, &'static str> = #value;
        }
    }
}
