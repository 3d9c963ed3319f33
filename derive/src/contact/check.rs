//! Meaning of the `#[contact(...)]` settings: the surface and the law read from their call
//! forms (`forms.rs`) against the tables in `keys.rs`, values with the value rules of `lang::values` in
//! the same arena, and the rules on the values that are literals (fields meet the same rules
//! at run time, in the generated `ContactDynamics::check_parameters`). One function per rule,
//! its reason in a comment.

use precess_core::contact::{
    ContactError, ContactLaw, ContactScene, ContactTorques, ContactValues, Surface,
};
use precess_core::sym::ExprId;
use syn::{Attribute, Expr, Ident};

use crate::lang::check::Checker;
use crate::lang::keys::{self, CONTACT_KEYS, LAWS, SURFACES};
use crate::lang::syntax::{Item, KeyValue, Parsed};
use crate::lang::units::Dim;
use crate::rigid::check::CheckedBody;

use super::forms::{law_list, read_law, read_surface, surface_list};

/// The checked `#[contact(...)]` settings.
pub struct ContactSettings {
    /// The surface the body touches the table with.
    pub surface: Surface,
    /// The contact law.
    pub law: ContactLaw,
    /// The torques beyond the law's friction the law's keys declare (the resistances of
    /// stick–slip, pivoting friction); the user couple's symbols join at expansion.
    pub torques: ContactTorques,
    /// The path of the user couple function, `torque = f`.
    pub couple: Option<syn::Path>,
    /// g along −z in space.
    pub gravity: ExprId,
}

impl ContactSettings {
    /// The scene of these settings on `body`: its mass, centre of mass and the inertia about
    /// it in description axes, from `#[rigid]`.
    pub fn scene(&self, body: &CheckedBody) -> ContactScene {
        let props = &body.body.props;
        ContactScene {
            mass: props.mass,
            center: props.center,
            inertia: props.inertia_cm,
            surface: self.surface,
            law: self.law,
            gravity: self.gravity,
        }
    }
}

/// Checks the `#[contact]` items, if the struct has any attribute. `None` after an error
/// (recorded), `Some(None)` when the struct declares no contact. `body` is the checked
/// `#[rigid]` body (`None` after its own errors), for the rules that read its centre of mass.
pub fn check(
    ck: &mut Checker,
    attrs: &[&Attribute],
    items: &Parsed<Item>,
    body: Option<&CheckedBody>,
) -> Option<Option<ContactSettings>> {
    let Some(&first) = attrs.first() else {
        return Some(None);
    };
    let errors_before = ck.cx.error_count();
    // One scene per struct: a top is held at its pivot and a free body by nothing, while a
    // body on a table is held by the table; their equations disagree on what the state is.
    for (other, present) in [
        (keys::TOP, !ck.input.top.is_empty()),
        (keys::FREE, !ck.input.attributes(keys::FREE).is_empty()),
    ] {
        if present {
            ck.cx.error_spanned_by(
                first,
                format!(
                    "`#[{}]` cannot be combined with `#[{other}]` on one struct: a body on a table is held by the table, not {}; derive each on its own struct",
                    keys::CONTACT,
                    if other == keys::TOP { "by a pivot" } else { "free" }
                ),
            );
        }
    }
    let in_contact = format!("`#[{}]`", keys::CONTACT);
    let mut seen: Vec<&Ident> = Vec::new();
    let (mut surface, mut law, mut gravity) = (None, None, None);
    let mut couple = None;
    let mut surface_value = None;
    let mut written_as_group: Vec<&str> = Vec::new();
    for item in &items.items {
        let kv = match item {
            Item::Setting(kv) => kv,
            Item::Group { name, .. } => {
                ck.cx.error_spanned_by(name, group_message(name));
                // Told its form already: not missing as well.
                if SURFACES.iter().any(|(s, _, _)| name == s) {
                    written_as_group.push(keys::SURFACE);
                } else if LAWS.iter().any(|(l, _)| name == l) {
                    written_as_group.push(keys::LAW);
                }
                continue;
            }
        };
        let KeyValue { key, value } = &**kv;
        // Each setting once: two surfaces or two laws would be ambiguous.
        if seen.contains(&key) {
            ck.cx
                .error_spanned_by(key, format!("duplicate key `{key}` in {in_contact}"));
            continue;
        }
        seen.push(key);
        match CONTACT_KEYS.iter().find(|&&k| key == k).copied() {
            Some(keys::SURFACE) => {
                surface = read_surface(ck, value);
                surface_value = Some(value);
            }
            Some(keys::LAW) => law = read_law(ck, value),
            Some(keys::TORQUE) => couple = user_fn(ck, value),
            Some(keys::GRAVITY) => {
                gravity = ck.expecting(Dim::ACCELERATION, keys::GRAVITY, |ck| {
                    let why = "it is g along −z; one pulling up would lift the body off the table";
                    ck.non_negative(value, "`gravity`", Some(why))
                });
            }
            _ => ck.cx.error_spanned_by(key, unknown(key)),
        }
    }
    // A missing setting is reported only when every attribute parsed: otherwise it may be
    // in the part that did not.
    if items.complete {
        for (key, what) in [
            (
                keys::SURFACE,
                format!(
                    "the convex surface the body touches the table with: {}",
                    surface_list()
                ),
            ),
            (
                keys::LAW,
                format!("how the body meets the table: {}", law_list()),
            ),
            (
                keys::GRAVITY,
                "g along −z, which presses the body on the table".to_owned(),
            ),
        ] {
            let found = seen.iter().any(|k| *k == key) || written_as_group.contains(&key);
            if !found {
                ck.cx
                    .error_spanned_by(first, format!("{in_contact} needs `{key} = ...`, {what}"));
            }
        }
    }
    if let (Some(s), Some(value), Some(body)) = (&surface, surface_value, body) {
        center_inside(ck, s, value, body);
    }
    let ok = items.complete && ck.cx.error_count() == errors_before;
    if !ok {
        return None;
    }
    let (law, torques) = law?;
    Some(Some(ContactSettings {
        surface: surface?,
        law,
        torques,
        couple,
        gravity: gravity?,
    }))
}

/// The path of the user couple, `torque = f`: a function of the state, as `#[top]`'s
/// `torque` is, without the time (the normal force, which the witnesses read, is then a
/// function of the state alone).
fn user_fn(ck: &mut Checker, value: &Expr) -> Option<syn::Path> {
    let function = "`fn(&Self, &Matrix3<f64>, &Vector3<f64>) -> Vector3<f64>` (attitude, body ω → the couple on the body, description axes)";
    ck.function_path(value, &format!("`{}`", keys::TORQUE), function)
}

/// The message for `name(...)` written as an item of `#[contact]` itself.
fn group_message(name: &Ident) -> String {
    if SURFACES.iter().any(|(s, _, _)| name == s) {
        format!(
            "`{name}(...)` is a surface: write `{} = {name}(...)`",
            keys::SURFACE
        )
    } else if LAWS.iter().any(|(l, _)| name == l) {
        format!(
            "`{name}(...)` is a contact law: write `{} = {name}(...)`",
            keys::LAW
        )
    } else {
        unknown(name)
    }
}

/// The message for a key `#[contact]` does not take.
fn unknown(key: &Ident) -> String {
    keys::unknown_key(
        key,
        &format!("in `#[{}]`", keys::CONTACT),
        CONTACT_KEYS,
        &[],
    )
}

/// The centre of mass inside the surface, by the run-time rule of
/// [`ContactValues::check`] (one rule for literals and fields), when the centre and the
/// surface's placement and lengths are literals. The contact model needs it: a closed
/// surface is the body's hull, which holds its centre of mass; a disk or a torus rolls on a
/// rim around its centre of mass, a bowl rocks with its centre of mass above the bowl.
fn center_inside(ck: &mut Checker, surface: &Surface, value: &Expr, body: &CheckedBody) {
    let arena = &*ck.arena;
    let literal = |e: &ExprId| arena.as_rational(*e).map(|r| r.to_f64());
    let literal3 = |v: &[ExprId; 3]| -> Option<[f64; 3]> {
        let [x, y, z] = v.each_ref().map(literal);
        Some([x?, y?, z?])
    };
    let (placement, lengths) = surface.dimensions();
    let lengths: Option<Vec<(&'static str, f64)>> = lengths
        .iter()
        .map(|(name, e)| literal(e).map(|v| (*name, v)))
        .collect();
    let (Some(center), Some(placement), Some(lengths)) = (
        literal3(&body.body.props.center),
        literal3(&placement),
        lengths,
    ) else {
        return;
    };
    // Only the placement of the centre of mass is judged here: the other values are stand-ins
    // that meet their rules (each of the real ones is checked where it is written).
    let values = ContactValues {
        mass: 1.0,
        center,
        inertia: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        gravity: 0.0,
        surface: surface.kind(),
        placement,
        lengths,
        coefficients: Vec::new(),
    };
    if let Err(e @ ContactError::CenterOutsideSurface { .. }) = values.check() {
        ck.cx.error_spanned_by(value, e);
    }
}
