//! The `variational(tangents = m, sensitivities = [field, …])` group of `#[top]`: the
//! first-order variational equations of the declared chart, built at expansion by the same
//! `precess_core::variational::VariationalEquations` the interpreted `VariationalSystem`
//! lowers, and emitted as straight-line Rust in `<Name>Variational<'a>`, an
//! `ode::System<N>` with N = 6 + 6·m + 6·k over the same `Layout`, so `benettin` and
//! `FlowMap` take it unchanged. Scenes without the group emit nothing here.

use precess_core::sym::{Arena, ExprId, SymbolId};
use precess_core::variational::VariationalEquations;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::{Expr, ExprLit, Ident, Lit, Visibility};

use crate::lang::check::Checker;
use crate::lang::ctxt::Ctxt;
use crate::lang::keys;
use crate::lang::private::Private;
use crate::lang::symbols::{Lowering, SymbolTokens};
use crate::lang::syntax::KeyValue;
use crate::lang::values::path_ident;

/// The group's name in `#[top(...)]`.
pub const VARIATIONAL: &str = "variational";
/// How many tangent vectors (columns of Φ) to carry: 6, the default, for the whole state
/// transition matrix, 1 for the maximal Lyapunov exponent.
pub const TANGENTS: &str = "tangents";
/// The fields whose sensitivities ∂x/∂p to carry.
pub const SENSITIVITIES: &str = "sensitivities";
/// The keys of the group, both optional.
pub const KEYS: &[&str] = &[TANGENTS, SENSITIVITIES];
/// The entries of the top's state (q, q̇).
const STATE_LEN: usize = 6;

/// How the group is written, for the messages.
pub fn form() -> String {
    format!("`{VARIATIONAL}({TANGENTS} = m, {SENSITIVITIES} = [field, …])`")
}

/// The checked group.
pub struct VariationalKey {
    /// Tangent vectors m, `0 ..= 6`.
    pub tangents: usize,
    /// The fields whose sensitivities are carried, each with its parameter symbol.
    pub sensitivities: Vec<(Ident, SymbolId)>,
    /// The struct's visibility, which the generated type takes.
    pub vis: Visibility,
}

/// Checks one `variational(...)` group named `name` with `keys`, after every other value of
/// the scene was read (a sensitivity must name a field the equations read). `torque` is true
/// when the top declares a user torque function, whose derivatives are unknown. `None` after
/// recording the errors, each spanned on what is wrong.
pub fn check(
    ck: &Checker,
    name: &Ident,
    keys: &[KeyValue],
    torque: bool,
) -> Option<VariationalKey> {
    let cx = ck.cx;
    let errors_before = cx.error_count();
    if torque {
        cx.error_spanned_by(
            name,
            format!(
                "`{VARIATIONAL}(...)` cannot be combined with `{} = …`: the variational equations differentiate the right-hand side, and a user function's derivatives are unknown",
                keys::TORQUE
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
            tangents = tangent_count(cx, value);
        } else if key == SENSITIVITIES {
            sensitivities = sensitivity_fields(ck, value);
        } else {
            cx.error_spanned_by(
                key,
                format!(
                    "unknown key `{key}` in `{VARIATIONAL}(...)`: expected {}{}",
                    KEYS.join(", "),
                    keys::did_you_mean(&key.to_string(), KEYS.iter().copied())
                ),
            );
        }
    }
    let tangents = tangents.unwrap_or(STATE_LEN);
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

/// `tangents = m`: an integer literal from 0 to 6. `None` after recording the error.
fn tangent_count(cx: &Ctxt, value: &Expr) -> Option<usize> {
    let m = match value {
        Expr::Lit(ExprLit {
            lit: Lit::Int(i), ..
        }) => i.base10_parse::<usize>().ok(),
        _ => None,
    };
    let m = m.filter(|&m| m <= STATE_LEN);
    if m.is_none() {
        cx.error_spanned_by(
            value,
            format!(
                "`{TANGENTS}` expects the number of tangent vectors, an integer from 0 to {STATE_LEN} (6 for the whole state transition matrix, 1 for the maximal Lyapunov exponent)"
            ),
        );
    }
    m
}

/// `sensitivities = [a, b]`: distinct f64 fields the top's equations read, each with its
/// parameter symbol; every bad entry is an error on itself.
fn sensitivity_fields(ck: &Checker, value: &Expr) -> Vec<(Ident, SymbolId)> {
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
        "the top's equations read no field".to_owned()
    } else {
        let names: Vec<String> = read.iter().map(|f| format!("`{f}`")).collect();
        format!("the fields they read are {}", names.join(", "))
    };
    let mut fields: Vec<(Ident, SymbolId)> = Vec::new();
    for element in &array.elems {
        let Some(field) = path_ident(element) else {
            cx.error_spanned_by(
                element,
                format!("`{SENSITIVITIES}` expects the names of fields the top's equations read, `[m, l]`: {read_list}"),
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
                    "the top's equations do not read the field `{field}`, so its sensitivity would be zero: {read_list}"
                ),
            ),
            None => cx.error_spanned_by(
                field,
                format!(
                    "no field `{field}` in `{}`: a sensitivity names a field the top's equations read, and {read_list}",
                    ck.input.ident
                ),
            ),
        }
    }
    fields
}

/// The generated type and its methods for the declared chart's state (q, q̇) and right-hand
/// side (q̇, q̈), the fields read through `symbols`; check_parameters is the top's
/// `check_all`. An internal error (recorded on `ident`) emits nothing.
pub fn expand(
    cx: &Ctxt,
    ident: &Ident,
    arena: &mut Arena,
    symbols: &SymbolTokens,
    (state, rhs): (&[ExprId], &[ExprId]),
    key: &VariationalKey,
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
    let names: Vec<String> = key
        .sensitivities
        .iter()
        .map(|(f, _)| f.to_string())
        .collect();
    let doc = format!(
        "The first-order variational equations of [`{ident}`] in its declared chart, generated by `#[top({VARIATIONAL}(...))]`: the state (q, q̇), {m} tangent vector(s) of Φ = ∂x/∂x₀ and the sensitivities to {}, N = {n} + {n}·{m} + {n}·{k} = {len} entries laid out as `precess::variational::Layout` says.",
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
    let method_doc = format!("The variational equations of this top, [`{wrapper}`].");
    quote! {
        #[doc = #doc]
        #[derive(Clone, Copy)]
        #vis struct #wrapper<'a> {
            /// The top whose fields the equations read.
            #vis top: &'a #ident,
        }

        // By hand: a derived `Debug` would ask the top to be `Debug`.
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
                #wrapper { top: self }
            }

            // The equations read the fields as `self.field`: they are a method of the top.
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
                #ident::#helper(self.top, t, y, dydt)
            }

            /// The top's checks of its body and settings, before any step.
            fn check_parameters(&self) -> ::core::result::Result<(), #p::OdeError> {
                #p::TopDynamics::check_all(self.top).map_err(#p::TopError::into_ode_error)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use precess_core::codegen::{Op, Program};
    use precess_core::sym::Arena;
    use precess_core::top::TopScene;
    use precess_core::variational::VariationalEquations;
    use quote::quote;

    use crate::lang::tests::{method, rigid_body as expand};

    /// The emitted right-hand side is the interpreted program written out: one `let` per
    /// instruction of the program `VariationalSystem` runs for the same scene (built here
    /// by hand in precess-core), so the generated type saves the interpreter's dispatch and
    /// nothing else. Run with `--nocapture` for the counts.
    #[test]
    fn the_emitted_equations_are_the_interpreted_program() {
        let code = expand(quote! {
            #[rigid(
                body(mass = m, at = [0.0, 0.0, l], inertia = diag(i1, i2, i3), about = pivot),
                pivot = [0.0, 0.0, 0.0],
            )]
            #[top(gravity = g, variational(sensitivities = [m, l, g]))]
            struct Heavy { m: f64, l: f64, g: f64, i1: f64, i2: f64, i3: f64 }
        });
        assert!(!code.contains("compile_error"), "{code}");
        assert!(code.contains("struct HeavyVariational"), "{code}");
        assert!(
            code.contains("System < 60usize > for HeavyVariational"),
            "{code}"
        );
        let rhs = method(&code, "__precess_variational_rhs");
        // One `let __pN` per instruction, a sine and a cosine sharing one `sin_cos` (the
        // `let (…) = { … }` blocks only group the statements).
        let lets = rhs.matches("let __p").count() + 2 * rhs.matches("sin_cos (").count();
        let writes = rhs.matches("dydt [").count();

        let mut a = Arena::new();
        let z = a.zero();
        let i = ["i1", "i2", "i3"].map(|n| a.parameter(n));
        let mut scene = TopScene::free(&mut a, [[i[0], z, z], [z, i[1], z], [z, z, i[2]]]);
        scene.mass = a.parameter("m");
        scene.center = [z, z, a.parameter("l")];
        scene.gravity = Some(a.parameter("g"));
        let Ok(derivation) = scene.derive(&mut a) else {
            panic!("the heavy top derives");
        };
        let Ok(eq) = VariationalEquations::from_top(&mut a, &derivation, 6, &["m", "l", "g"])
        else {
            panic!("the equations build");
        };
        let program = Program::lower(&a, eq.outputs());
        let instructions = program
            .ops()
            .iter()
            .filter(|op| !matches!(op, Op::Const(_)))
            .count();
        let (f, all) = eq.op_counts(&a);
        println!(
            "emitted: {lets} lets, {writes} outputs; interpreted program: {instructions} instructions, ops f {} / augmented {}",
            f.total(),
            all.total()
        );
        assert_eq!(writes, 60);
        assert_eq!(lets, instructions, "{rhs}");
    }
}
