//! `#[top(...)]`: a top about the body's pivot, its declared torques and angle sequence.
//! Parsed and checked here with the `#[rigid]` value rules, then handed to precess-core's
//! `emit_top`, which derives both angle charts and the Eulerian form and lowers them.

use precess_core::lagrange::{TopEmit, emit_top};
use precess_core::rigid::AngleSequence;
use precess_core::sym::{ExprId, SymbolId};
use precess_core::top::TopScene;
use proc_macro2::TokenStream;
use quote::{ToTokens, quote};
use syn::punctuated::Punctuated;
use syn::{Expr, Ident, Token};

use crate::ast::Input;
use crate::attr::KeyValue;
use crate::check::{Checked, Checker};
use crate::ctxt::Ctxt;

const KEYS: &str = "gravity, body_torque, space_torque, damping, torque, angles";

/// The checked `#[top(...)]` settings.
pub struct TopSpec {
    gravity: Option<ExprId>,
    body_torque: Option<[ExprId; 3]>,
    space_torque: Option<[ExprId; 3]>,
    damping: Option<ExprId>,
    torque: Option<syn::Path>,
    angles: AngleSequence,
}

/// Reads the `#[top]` attributes, if any, into `checked`'s arena. `None` after an error
/// (recorded in `cx`), `Some(None)` when the struct declares no top.
pub fn check(cx: &mut Ctxt, input: &Input, checked: &mut Checked) -> Option<Option<TopSpec>> {
    let Some(&first) = input.top.first() else {
        return Some(None);
    };
    // A top turns about a fixed point; without a pivot there is none to turn about.
    if checked.description.pivot.is_none() {
        cx.error(
            first,
            "`#[top]` needs a pivot: add `pivot = [x, y, z]` to `#[rigid(...)]`",
        );
        return None;
    }
    let mut items: Vec<KeyValue> = Vec::new();
    for attr in &input.top {
        match attr.parse_args_with(Punctuated::<KeyValue, Token![,]>::parse_terminated) {
            Ok(list) => items.extend(list),
            Err(e) => cx.push(e),
        }
    }
    let mut spec = TopSpec {
        gravity: None,
        body_torque: None,
        space_torque: None,
        damping: None,
        torque: None,
        angles: AngleSequence::Zxz,
    };
    let mut seen: Vec<&Ident> = Vec::new();
    let mut ck = Checker::resume(cx, input, checked);
    for KeyValue { key, value } in &items {
        // Each setting once: two gravities or two dampings would be ambiguous.
        if seen.contains(&key) {
            ck.cx.error(key, format!("duplicate key `{key}`"));
            continue;
        }
        seen.push(key);
        match key.to_string().as_str() {
            "gravity" => spec.gravity = positive(&mut ck, value, "gravity", true),
            "damping" => spec.damping = positive(&mut ck, value, "damping", false),
            "body_torque" => spec.body_torque = ck.vector(value),
            "space_torque" => spec.space_torque = ck.vector(value),
            "torque" => spec.torque = user_fn(&mut ck, value),
            "angles" => spec.angles = angles(&mut ck, value),
            _ => ck.cx.error(
                key,
                format!("unknown key `{key}` in `#[top]`: expected {KEYS}"),
            ),
        }
    }
    let ok = ck.cx.is_ok();
    ck.suspend(checked);
    ok.then_some(Some(spec))
}

/// A scalar that must be positive (gravity: g along −z) or non-negative (damping: a
/// negative coefficient would feed energy in). Only literal values can be judged here.
fn positive(ck: &mut Checker, value: &Expr, what: &str, strict: bool) -> Option<ExprId> {
    let v = ck.scalar(value)?;
    if let Some(r) = ck.arena.as_rational(v) {
        let bad = if strict {
            r.is_negative() || r.is_zero()
        } else {
            r.is_negative()
        };
        if bad {
            let need = if strict {
                "positive (gravity acts along −z; give its magnitude)"
            } else {
                "zero or positive (a negative damping feeds energy in)"
            };
            ck.cx.error(
                value,
                format!("`{what}` is {}: it must be {need}", r.to_f64()),
            );
            return None;
        }
    }
    Some(v)
}

fn user_fn(ck: &mut Checker, value: &Expr) -> Option<syn::Path> {
    match value {
        Expr::Path(p) if p.qself.is_none() => Some(p.path.clone()),
        _ => {
            ck.cx.error(value, "`torque` expects a path to a function `fn(&Self, f64, &Matrix3<f64>, &Vector3<f64>) -> Vector3<f64>` (time, attitude, body ω → body torque)");
            None
        }
    }
}

fn angles(ck: &mut Checker, value: &Expr) -> AngleSequence {
    let name = match value {
        Expr::Path(p) => p.path.get_ident().map(|i| i.to_string()),
        _ => None,
    };
    match name.as_deref() {
        Some("zxz") => AngleSequence::Zxz,
        Some("zyx") => AngleSequence::Zyx,
        _ => {
            ck.cx.error(
                value,
                "`angles` expects `zxz` (φ, θ, ψ) or `zyx` (yaw, pitch, roll)",
            );
            AngleSequence::Zxz
        }
    }
}

/// `impl Top for …`, or `None` after recording why the equations could not be derived.
pub fn expand(
    cx: &mut Ctxt,
    ident: &Ident,
    checked: &mut Checked,
    spec: TopSpec,
) -> Option<TokenStream> {
    let a = &mut checked.arena;
    let props = checked.body.props.clone();
    let center: [ExprId; 3] = std::array::from_fn(|k| a.sub(props.center[k], props.reference[k]));
    let scene = TopScene {
        sequence: spec.angles,
        inertia: props.inertia,
        mass: props.mass,
        center,
        gravity: spec.gravity,
        body_torque: spec.body_torque,
        space_torque: spec.space_torque,
        damping: spec.damping,
        user_torque: None,
    };
    let fields = checked.fields.clone();
    // Fields are found by id among the parameters, never by a symbol's shown name.
    let by_id: Vec<(SymbolId, Ident)> = fields
        .iter()
        .filter_map(|f| a.find_parameter(&f.to_string()).map(|s| (s, f.clone())))
        .collect();
    let mut parameter = |s: SymbolId| -> Option<TokenStream> {
        let (_, field) = by_id.iter().find(|(id, _)| *id == s)?;
        Some(quote!(self.#field))
    };
    let p = quote!(::precess::__private);
    let emitted = emit_top(
        a,
        TopEmit {
            scene,
            parameter: &mut parameter,
            user_fn: spec.torque.map(|path| path.to_token_stream()),
            krate: p.clone(),
        },
    );
    match emitted {
        Ok(items) => Some(quote! {
            #[automatically_derived]
            #[allow(unused_variables, clippy::all, clippy::pedantic, clippy::nursery, unused_parens)]
            impl #p::Top for #ident {
                #items
            }
        }),
        Err(e) => {
            cx.error(
                ident,
                format!("cannot derive the top's equations of motion: {e}"),
            );
            None
        }
    }
}

/// A stub `impl Top` so code using the trait does not add errors to the real ones.
pub fn fallback(ident: &Ident) -> TokenStream {
    let p = quote!(::precess::__private);
    let stub = quote!(::core::unimplemented!("the #[top] description has errors"));
    quote! {
        #[automatically_derived]
        impl #p::Top for #ident {
            const SEQUENCE: #p::AngleSequence = #p::AngleSequence::Zxz;
            fn accel_in(&self, _: #p::AngleSequence, _: f64, _: &[f64; 6]) -> [f64; 3] { #stub }
            fn rotation_in(&self, _: #p::AngleSequence, _: &[f64; 3]) -> #p::Matrix3<f64> { #stub }
            fn rate_matrix_in(&self, _: #p::AngleSequence, _: &[f64; 3]) -> #p::Matrix3<f64> { #stub }
            fn energy_in(&self, _: #p::AngleSequence, _: &[f64; 6]) -> f64 { #stub }
            fn angle_jacobian(&self, _: f64, _: &[f64; 3], _: &[f64; 3]) -> [[f64; 6]; 3] { #stub }
            fn conserved_momenta(&self, _: &[f64; 3], _: &[f64; 3]) -> [::core::option::Option<f64>; 3] { #stub }
            fn eulerian_rhs(&self, _: f64, _: &#p::UnitQuaternion<f64>, _: &#p::Vector3<f64>) -> #p::Vector3<f64> { #stub }
        }
    }
}
