//! The `variational(tangents = m, sensitivities = [field, …])` group, in one place for every
//! scene that takes it (`#[top]`, `#[mechanism]`): the group's keys checked against the
//! scene's state length n and the fields its equations read ([`check`]), and the first-order
//! variational equations of the scene's state x and right-hand side f, built at expansion by
//! the same `precess_core::variational::VariationalEquations` the interpreted
//! `VariationalSystem` lowers and emitted as straight-line Rust in `<Name>Variational<'a>`, an
//! `ode::System<N>` with N = n + n·m + n·k over the same `Layout`, so `benettin` and `FlowMap`
//! take it unchanged ([`expand`]). A scene says what is its own in a [`Scene`] and a
//! [`Target`]; scenes without the group emit nothing here.

use precess_core::sym::{Arena, ExprId, SymbolId};
use precess_core::variational::VariationalEquations;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::{Expr, ExprLit, Ident, Lit, Visibility};

use super::check::Checker;
use super::ctxt::Ctxt;
use super::keys;
use super::private::Private;
use super::symbols::{Lowering, SymbolTokens};
use super::syntax::KeyValue;
use super::values::path_ident;

/// The group's name, as in `#[top(variational(...))]`.
pub const VARIATIONAL: &str = "variational";
/// How many tangent vectors (columns of Φ) to carry: n, the default, for the whole state
/// transition matrix, 1 for the maximal Lyapunov exponent.
pub const TANGENTS: &str = "tangents";
/// The fields whose sensitivities ∂x/∂p to carry.
pub const SENSITIVITIES: &str = "sensitivities";
/// The keys of the group, both optional.
pub const KEYS: &[&str] = &[TANGENTS, SENSITIVITIES];

/// How the group is written, for the messages.
pub fn form() -> String {
    format!("`{VARIATIONAL}({TANGENTS} = m, {SENSITIVITIES} = [field, …])`")
}

/// The group as a message for an unknown key of the attribute lists it
/// (`keys::unknown_key`'s `others`): its name, and its form.
pub fn listed() -> (&'static [&'static str], String) {
    (
        &[VARIATIONAL],
        format!("the variational equations {}", form()),
    )
}

/// What the checks need of the scene the group belongs to.
pub struct Scene<'a> {
    /// The scene's possessive in messages, `the top's`.
    pub whose: &'a str,
    /// n, the length of the scene's state (q, q̇).
    pub n: usize,
    /// The key of a user function the scene declares (`torque`, `effort`), if it does: the
    /// variational equations differentiate f, and a user function's derivatives are unknown.
    pub user: Option<&'a str>,
}

/// The checked group.
pub struct VariationalKey {
    /// Tangent vectors m, `0 ..= n`.
    pub tangents: usize,
    /// The fields whose sensitivities are carried, each with its parameter symbol.
    pub sensitivities: Vec<(Ident, SymbolId)>,
    /// The struct's visibility, which the generated type takes.
    pub vis: Visibility,
}

/// Checks one `variational(...)` group named `name` with `keys` for `scene`, after every other
/// value of the scene was read (a sensitivity must name a field the equations read). `None`
/// after recording the errors, each spanned on what is wrong.
pub fn check(
    ck: &Checker,
    name: &Ident,
    keys: &[KeyValue],
    scene: &Scene,
) -> Option<VariationalKey> {
    let cx = ck.cx;
    let errors_before = cx.error_count();
    if let Some(user) = scene.user {
        cx.error_spanned_by(
            name,
            format!(
                "`{VARIATIONAL}(...)` cannot be combined with `{user} = …`: the variational equations differentiate the right-hand side, and a user function's derivatives are unknown",
            ),
        );
    }
    let mut tangents = None;
    let mut sensitivities: Vec<(Ident, SymbolId)> = Vec::new();
    let mut seen: Vec<&Ident> = Vec::new();
    for KeyValue { key, value } in keys {
        if seen.contains(&key) {
            cx.error_spanned_by(
                key,
                format!("duplicate key `{key}` in `{VARIATIONAL}(...)`"),
            );
            continue;
        }
        seen.push(key);
        if key == TANGENTS {
            tangents = tangent_count(cx, value, scene.n);
        } else if key == SENSITIVITIES {
            sensitivities = sensitivity_fields(ck, value, scene.whose);
        } else {
            let place = format!("in `{VARIATIONAL}(...)`");
            cx.error_spanned_by(key, keys::unknown_key(key, &place, KEYS, &[]));
        }
    }
    let tangents = tangents.unwrap_or(scene.n);
    if tangents == 0 && sensitivities.is_empty() && cx.error_count() == errors_before {
        cx.error_spanned_by(
            name,
            format!(
                "`{VARIATIONAL}(...)` with `{TANGENTS} = 0` and no `{SENSITIVITIES}` carries nothing beside the state: give at least one tangent or one field"
            ),
        );
    }
    (cx.error_count() == errors_before).then(|| VariationalKey {
        tangents,
        sensitivities,
        vis: ck.input.vis.clone(),
    })
}

/// `tangents = m`: an integer literal from 0 to n. `None` after recording the error.
fn tangent_count(cx: &Ctxt, value: &Expr, n: usize) -> Option<usize> {
    let m = match value {
        Expr::Lit(ExprLit {
            lit: Lit::Int(i), ..
        }) => i.base10_parse::<usize>().ok(),
        _ => None,
    };
    let m = m.filter(|&m| m <= n);
    if m.is_none() {
        cx.error_spanned_by(
            value,
            format!(
                "`{TANGENTS}` expects the number of tangent vectors, an integer from 0 to {n} ({n} for the whole state transition matrix, 1 for the maximal Lyapunov exponent)"
            ),
        );
    }
    m
}

/// `sensitivities = [a, b]`: distinct f64 fields the scene's equations read, each with its
/// parameter symbol; every bad entry is an error on itself.
fn sensitivity_fields(ck: &Checker, value: &Expr, whose: &str) -> Vec<(Ident, SymbolId)> {
    let cx = ck.cx;
    let Expr::Array(array) = value else {
        cx.error_spanned_by(
            value,
            format!("`{SENSITIVITIES}` expects a list of the struct's f64 fields, `[m, l]`"),
        );
        return Vec::new();
    };
    let read: Vec<&Ident> = ck.parameters.fields().collect();
    let read_list = if read.is_empty() {
        format!("{whose} equations read no field")
    } else {
        let names: Vec<String> = read.iter().map(|f| format!("`{f}`")).collect();
        format!("the fields they read are {}", names.join(", "))
    };
    let mut fields: Vec<(Ident, SymbolId)> = Vec::new();
    for element in &array.elems {
        let Some(field) = path_ident(element) else {
            cx.error_spanned_by(
                element,
                format!("`{SENSITIVITIES}` expects the names of fields {whose} equations read, `[m, l]`: {read_list}"),
            );
            continue;
        };
        if fields.iter().any(|(f, _)| f == field) {
            cx.error_spanned_by(
                field,
                format!("the sensitivity to `{field}` is given twice: list each field once"),
            );
            continue;
        }
        let symbol = read
            .contains(&field)
            .then(|| ck.arena.find_parameter(&field.to_string()))
            .flatten();
        match symbol {
            Some(symbol) => fields.push((field.clone(), symbol)),
            None if ck.input.field(field).is_some() => cx.error_spanned_by(
                field,
                format!(
                    "{whose} equations do not read the field `{field}`, so its sensitivity would be zero: {read_list}"
                ),
            ),
            None => cx.error_spanned_by(
                field,
                format!(
                    "no field `{field}` in `{}`: a sensitivity names a field {whose} equations read, and {read_list}",
                    ck.input.ident
                ),
            ),
        }
    }
    fields
}

/// What the generated type says and does that is the scene's own.
pub struct Target<'a> {
    /// The attribute the group sits in, `top`, for the docs.
    pub attribute: &'a str,
    /// The wrapper's field holding the scene, `top`; also the scene's name in the docs.
    pub field: Ident,
    /// Where the state's coordinates come from, for the docs: `in its declared chart`.
    pub chart: &'a str,
    /// The doc of `check_parameters`.
    pub check_doc: &'a str,
    /// The body of `check_parameters`, reading the scene as `self.<field>`: the scene's own
    /// checks of its fields as an `OdeError`.
    pub check: TokenStream,
}

/// The generated type and its methods for the scene's state x = (q, q̇) and right-hand side
/// f = (q̇, q̈), the fields read through `symbols`. An internal error (recorded on `ident`)
/// emits nothing.
pub fn expand(
    cx: &Ctxt,
    ident: &Ident,
    arena: &mut Arena,
    symbols: &SymbolTokens,
    (state, rhs): (&[ExprId], &[ExprId]),
    key: &VariationalKey,
    target: &Target,
) -> TokenStream {
    let p = Private;
    let params: Vec<ExprId> = key
        .sensitivities
        .iter()
        .map(|&(_, s)| arena.symbol_expr(s))
        .collect();
    let equations = match VariationalEquations::new(arena, state, rhs, key.tangents, &params) {
        Ok(equations) => equations,
        Err(e) => {
            cx.error_spanned_by(
                ident,
                format!(
                    "internal error of the derive: the variational equations could not be built ({e}); please report this"
                ),
            );
            return TokenStream::new();
        }
    };
    let layout = equations.layout();
    let (n, m, k, len) = (
        layout.n,
        layout.tangents,
        layout.sensitivities,
        layout.len(),
    );
    // Every symbol of the augmented state read from `y` in layout order; time, were the
    // equations to read it, from `t`.
    let mut reads: Vec<(ExprId, TokenStream)> = equations
        .symbols()
        .iter()
        .enumerate()
        .map(|(i, &s)| (arena.symbol_expr(s), quote!(y[#i])))
        .collect();
    reads.extend(
        arena
            .time_symbol()
            .map(|s| (arena.symbol_expr(s), quote!(t))),
    );
    let low = Lowering::new(cx, ident, symbols.clone());
    let code = low.lower_reading(arena, equations.outputs(), &reads);
    let (lets, outputs) = (code.lets, code.outputs);
    let slots = 0..len;
    let vis = &key.vis;
    let wrapper = format_ident!("{}Variational", ident);
    let wrapper_name = wrapper.to_string();
    let helper = format_ident!("__precess_variational_rhs");
    let (field, check, check_doc) = (&target.field, &target.check, target.check_doc);
    let names: Vec<String> = key
        .sensitivities
        .iter()
        .map(|(f, _)| f.to_string())
        .collect();
    let doc = format!(
        "The first-order variational equations of [`{ident}`] {}, generated by `#[{}({VARIATIONAL}(...))]`: the state (q, q̇), {m} tangent vector(s) of Φ = ∂x/∂x₀ and the sensitivities to {}, N = {n} + {n}·{m} + {n}·{k} = {len} entries laid out as `precess::variational::Layout` says.",
        target.chart,
        target.attribute,
        if names.is_empty() {
            "no field".to_owned()
        } else {
            names
                .iter()
                .map(|f| format!("`{f}`"))
                .collect::<Vec<_>>()
                .join(", ")
        }
    );
    let method_doc = format!("The variational equations of this {field}, [`{wrapper}`].");
    let field_doc = format!(" The {field} whose fields the equations read.");
    quote! {
        #[doc = #doc]
        #[derive(Clone, Copy)]
        #vis struct #wrapper<'a> {
            #[doc = #field_doc]
            #vis #field: &'a #ident,
        }

        // By hand: a derived `Debug` would ask the scene's struct to be `Debug`.
        #[automatically_derived]
        impl ::core::fmt::Debug for #wrapper<'_> {
            fn fmt(&self, f: &mut ::core::fmt::Formatter<'_>) -> ::core::fmt::Result {
                f.debug_struct(#wrapper_name).field("layout", &Self::LAYOUT).finish_non_exhaustive()
            }
        }

        #[automatically_derived]
        impl #ident {
            #[doc = #method_doc]
            #[inline]
            #vis fn variational(&self) -> #wrapper<'_> {
                #wrapper { #field: self }
            }

            // The equations read the fields as `self.field`: they are a method of the struct.
            #[doc(hidden)]
            #[inline]
            #[allow(unused_variables, clippy::all, clippy::pedantic, clippy::nursery, unused_parens)]
            fn #helper(&self, t: f64, y: &[f64; #len], dydt: &mut [f64; #len]) {
                #lets
                #( dydt[#slots] = #outputs; )*
            }
        }

        #[automatically_derived]
        impl #wrapper<'_> {
            /// Where x, Φ (column-major) and S sit in the augmented state.
            #vis const LAYOUT: #p::Layout = #p::Layout { n: #n, tangents: #m, sensitivities: #k };

            /// The fields whose sensitivities are carried, in the order of S's columns.
            #vis const SENSITIVITIES: [&'static str; #k] = [#(#names),*];

            /// The augmented state at the start: x₀ = (q, q̇), Φ = I (its first m columns),
            /// S = 0.
            ///
            /// # Errors
            /// As `Layout::initial_state`: `InitialStateLength`, `NonFinite`.
            #vis fn initial_state(&self, x0: &[f64]) -> ::core::result::Result<[f64; #len], #p::VariationalError> {
                Self::LAYOUT.initial_state(x0)
            }
        }

        #[automatically_derived]
        impl #p::System<#len> for #wrapper<'_> {
            #[inline]
            fn rhs(&self, t: f64, y: &[f64; #len], dydt: &mut [f64; #len]) {
                #ident::#helper(self.#field, t, y, dydt)
            }

            #[doc = #check_doc]
            fn check_parameters(&self) -> ::core::result::Result<(), #p::OdeError> {
                #check
            }
        }
    }
}
