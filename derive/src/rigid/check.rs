//! Meaning of the `#[rigid(...)]` items: each part by the part language (`lang::parts`), the
//! pivot and `taylor = K`, then the body's rules. One function per rule, the reason
//! in a comment; every error is recorded in the context, spanned on the offending tokens.

use precess_core::body::{BodyError, Description, Shape, SymbolicBody, check_part, evaluate};
use precess_core::sym::{Arena, ExprId};
use proc_macro2::TokenStream;
use quote::ToTokens;
use syn::Ident;

use crate::lang::check::Checker;
use crate::lang::ctxt::Ctxt;
use crate::lang::keys::{self, part_list};
use crate::lang::parts::{KeySpans, rotation_message};
use crate::lang::syntax::{Item, KeyValue, Parsed};
use crate::lang::taylor::TaylorKey;
use crate::lang::units;

/// The checked description and the symbolic body computed from it.
pub struct CheckedBody {
    /// The body.
    pub description: Description<ExprId>,
    /// The symbolic body computed from it.
    pub body: SymbolicBody,
    /// The maximum order of `taylor = K`, the Taylor recurrences of the torque-free Euler
    /// equations, if asked for.
    pub taylor: Option<usize>,
}

/// Tokens of each value, to span errors found on the whole body.
struct Spans {
    parts: Vec<KeySpans>,
    pivot: Option<TokenStream>,
    whole: TokenStream,
}

impl Spans {
    fn of(&self, part: usize, key: &str) -> TokenStream {
        let found = self
            .parts
            .get(part)
            .and_then(|p| p.iter().find(|(k, _)| *k == key));
        match found {
            Some((_, t)) => t.clone(),
            None => self.whole.clone(),
        }
    }
}

/// Whether the items declare a pivot: `None` when an attribute did not parse, so the
/// answer is unknown.
pub fn declares_pivot(items: &Parsed<Item>) -> Option<bool> {
    let found = items
        .items
        .iter()
        .any(|item| matches!(item, Item::Setting(kv) if kv.key == keys::PIVOT));
    (found || items.complete).then_some(found)
}

/// Checks the `#[rigid]` items and computes the symbolic body; `None` after recording why
/// it could not.
pub fn check(ck: &mut Checker, items: &Parsed<Item>) -> Option<CheckedBody> {
    let input = ck.input;
    // The body is described only by the attribute: without one there is nothing to derive.
    if input.rigid.is_empty() {
        ck.cx.error_spanned_by(
            input.ident,
            format!(
                "`#[derive(RigidBody)]` needs a `#[{}(...)]` attribute listing the body's parts: {}",
                keys::RIGID,
                part_list()
            ),
        );
        return None;
    }
    let errors_before = ck.cx.error_count();
    let mut description = Description::default();
    let mut spans = Spans {
        parts: Vec::new(),
        pivot: None,
        whole: input.rigid_tokens(),
    };
    let mut pivot_key: Option<&Ident> = None;
    let settings = items.items.iter().filter_map(|item| match item {
        Item::Setting(kv) => Some((&kv.key, &kv.value)),
        Item::Group { .. } => None,
    });
    let in_rigid = format!("`#[{}]`", keys::RIGID);
    // No user function can enter Euler's torque-free equations.
    let taylor = TaylorKey::find(ck.cx, settings, &in_rigid).order(ck.cx, &[]);
    for item in &items.items {
        match item {
            Item::Group { name, keys } => {
                if let Some((part, part_spans)) = ck.part(name, keys) {
                    description.parts.push(part);
                    spans.parts.push(part_spans);
                }
            }
            Item::Setting(setting) if setting.key == keys::PIVOT => {
                let KeyValue { key, value } = &**setting;
                // One pivot: a body turns about a single fixed point.
                if pivot_key.is_some() {
                    ck.cx.error_spanned_by(
                        key,
                        format!("duplicate key `{key}`: a body has one pivot"),
                    );
                    continue;
                }
                pivot_key = Some(key);
                description.pivot =
                    ck.expecting(units::Dim::LENGTH, keys::PIVOT, |ck| ck.vector(value));
                spans.pivot = Some(value.to_token_stream());
            }
            // Read by `TaylorKey` above.
            Item::Setting(setting) if setting.key == keys::TAYLOR => {}
            Item::Setting(setting) => {
                let key = &setting.key;
                let place = format!("in `#[{}]`", keys::RIGID);
                let parts: Vec<&str> = keys::PARTS.iter().map(|p| p.name).collect();
                let groups = [(
                    &parts[..],
                    format!("a part `name(key = value, ...)`: {}", part_list()),
                )];
                let message = keys::unknown_key(key, &place, keys::RIGID_KEYS, &groups);
                ck.cx.error_spanned_by(key, message);
            }
        }
    }
    // The body rules need every value: after a syntax or value error they would only
    // report its consequences.
    if !items.complete || ck.cx.error_count() > errors_before {
        return None;
    }
    let mut checked = validate(ck.cx, ck.arena, description, &spans)?;
    checked.taylor = taylor;
    Some(checked)
}

/// Runs the body rules: each part whose values are all literals now, then the whole body.
fn validate(
    cx: &Ctxt,
    arena: &mut Arena,
    description: Description<ExprId>,
    spans: &Spans,
) -> Option<CheckedBody> {
    if description.parts.is_empty() {
        cx.error_spanned_by(
            &spans.whole,
            format!("a body needs at least one part: {}", part_list()),
        );
        return None;
    }
    let errors_before = cx.error_count();
    // Literal parts are checked at compile time; parametric ones by the generated validate().
    for (index, part) in description.parts.iter().enumerate() {
        let single = Description {
            parts: vec![part.clone()],
            pivot: None,
        };
        if let Some(numeric) = evaluate(arena, &single)
            && let Some(numeric_part) = numeric.parts.first()
            && let Err(e) = check_part(index, numeric_part)
        {
            report(cx, spans, &e);
        } else if let Shape::Explicit { inertia, .. } = &part.shape {
            symmetric_tensor(cx, arena, inertia, &spans.of(index, keys::INERTIA));
        }
    }
    if cx.error_count() > errors_before {
        return None;
    }
    if let Some(numeric) = evaluate(arena, &description)
        && let Err(e) = numeric.validate()
    {
        report(cx, spans, &e);
        return None;
    }
    match SymbolicBody::new(arena, &description) {
        Ok(body) => Some(CheckedBody {
            description,
            body,
            taylor: None,
        }),
        Err(e) => {
            report(cx, spans, &e);
            None
        }
    }
}

/// An explicit tensor with field entries must still be symmetric for every value of the
/// fields: I[i][j] and I[j][i] are the same quantity, so they must be the same expression.
fn symmetric_tensor(cx: &Ctxt, arena: &mut Arena, t: &[[ExprId; 3]; 3], tokens: &TokenStream) {
    for (i, j) in [(0, 1), (0, 2), (1, 2)] {
        let d = arena.sub(t[i][j], t[j][i]);
        if arena.expand(d) != arena.zero() {
            let (a, b) = (arena.display(t[i][j]), arena.display(t[j][i]));
            cx.error_spanned_by(tokens, format!("the inertia tensor must be symmetric, but I[{i}][{j}] = {a} and I[{j}][{i}] = {b}: write the same value in both"));
            return;
        }
    }
}

/// Records a body error on the tokens it is about, with what is allowed.
fn report(cx: &Ctxt, spans: &Spans, e: &BodyError) {
    let (tokens, msg) = match *e {
        BodyError::NoParts => (spans.whole.clone(), format!("a body needs at least one part: {}", part_list())),
        BodyError::NonFinite { part, key, value, .. } => (spans.of(part, key), format!("`{key}` evaluates to {value}: values must be finite")),
        BodyError::NonFinitePivot { value } => (spans.pivot.clone().unwrap_or(spans.whole.clone()), format!("the pivot has the coordinate {value}: values must be finite")),
        BodyError::NonPositiveMass { part, value, .. } => (spans.of(part, keys::MASS), format!("mass must be positive, got {value}")),
        BodyError::NonPositiveDimension { part, key, value, .. } => (spans.of(part, key), format!("`{key}` must be positive, got {value}")),
        BodyError::TubeRadii { part, inner, outer } => (spans.of(part, keys::INNER), format!("the inner radius must satisfy 0 ≤ inner < outer, got inner = {inner} and outer = {outer}")),
        BodyError::NotSymmetric { part, row, col, upper, lower } => (
            spans.of(part, keys::INERTIA),
            format!("the inertia tensor must be symmetric, but I[{row}][{col}] = {upper} and I[{col}][{row}] = {lower}"),
        ),
        BodyError::NotPositiveDefinite { part, moments } => (
            spans.of(part, keys::INERTIA),
            format!("the inertia tensor must be positive definite, but its principal moments are {moments:?}"),
        ),
        BodyError::TriangleInequality { part, moments } => (
            spans.of(part, keys::INERTIA),
            format!("the principal moments {moments:?} break the triangle inequality I1 + I2 ≥ I3, which every mass distribution satisfies"),
        ),
        BodyError::ZeroRotationAxis { part, .. }
        | BodyError::NotOrthonormal { part, .. }
        | BodyError::ImproperRotation { part, .. } => (spans.of(part, keys::ROTATE), rotation_message(e)),
        BodyError::PivotRequired { part } => (spans.of(part, keys::ABOUT), "`about = pivot` needs a pivot: declare `pivot = [x, y, z]`, or give the tensor `about = center`".to_owned()),
        BodyError::ZeroTotalMass => (spans.whole.clone(), "the total mass is zero: masses must be positive".to_owned()),
        BodyError::IdenticallyZeroMoment { .. } => (
            spans.whole.clone(),
            "the body has a principal moment that is zero whatever its fields: all its mass lies on a line through the reference point; Euler's equations need three positive moments".to_owned(),
        ),
        BodyError::Overflow { quantity, value } => (spans.whole.clone(), format!("the body's {quantity} overflows f64 (it evaluates to {value}): its values are too large for f64, whose largest finite value is about 1.8e308; use larger units")),
        BodyError::Underflow { moments } => (spans.whole.clone(), format!("the body's principal moments {moments:?} underflow f64: its values are too small for f64, whose smallest normal value is about 2.2e-308; use smaller units")),
        BodyError::ZeroPrincipalMoment { moments } => (
            spans.whole.clone(),
            format!("the body has a zero principal moment (moments {moments:?}): all its mass lies on a line through the reference point; Euler's equations need three positive moments"),
        ),
    };
    cx.error_spanned_by(tokens, msg);
}
