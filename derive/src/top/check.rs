//! Meaning of the `#[top(...)]` items: keys against the table in `keys.rs`, values with the
//! `#[rigid]` value rules in the same arena, and the signs that literals can be judged on.

use precess_core::rigid::AngleSequence;
use precess_core::sym::ExprId;
use syn::{Expr, Ident};

use crate::keys::{self, TOP_KEYS};
use crate::rigid::attr::{KeyValue, Parsed};
use crate::rigid::check::Checker;

/// The checked `#[top(...)]` settings: the torques the scene declares and its angles.
pub struct TopSettings {
    /// g along −z in space.
    pub gravity: Option<ExprId>,
    /// A constant torque fixed in the body.
    pub body_torque: Option<[ExprId; 3]>,
    /// A constant torque fixed in space.
    pub space_torque: Option<[ExprId; 3]>,
    /// Linear damping −c ω.
    pub damping: Option<ExprId>,
    /// The path of a user torque function.
    pub torque: Option<syn::Path>,
    /// The declared angle sequence.
    pub angles: AngleSequence,
}

/// Checks the `#[top]` items, if the struct has any. `None` after an error (recorded),
/// `Some(None)` when the struct declares no top. `declares_pivot` is `None` when the
/// `#[rigid]` attribute could not be read, so a missing pivot is not reported twice.
pub fn check(
    ck: &mut Checker,
    items: &Parsed<KeyValue>,
    declares_pivot: Option<bool>,
) -> Option<Option<TopSettings>> {
    let Some(&first) = ck.input.top.first() else {
        return Some(None);
    };
    let errors_before = ck.cx.error_count();
    // A top turns about a fixed point; without a pivot there is none to turn about.
    if declares_pivot == Some(false) {
        ck.cx.error_spanned_by(
            first,
            format!(
                "`#[{}]` needs a pivot: add `{} = [x, y, z]` to `#[{}(...)]`",
                keys::TOP,
                keys::PIVOT,
                keys::RIGID
            ),
        );
    }
    let mut settings = TopSettings {
        gravity: None,
        body_torque: None,
        space_torque: None,
        damping: None,
        torque: None,
        angles: AngleSequence::Zxz,
    };
    let mut seen: Vec<&Ident> = Vec::new();
    for KeyValue { key, value } in &items.items {
        // Each setting once: two gravities or two dampings would be ambiguous.
        if seen.contains(&key) {
            ck.cx
                .error_spanned_by(key, format!("duplicate key `{key}`"));
            continue;
        }
        seen.push(key);
        match TOP_KEYS.iter().find(|&&k| key == k).copied() {
            Some(keys::GRAVITY) => settings.gravity = sign_checked(ck, value, keys::GRAVITY, true),
            Some(keys::DAMPING) => settings.damping = sign_checked(ck, value, keys::DAMPING, false),
            Some(keys::BODY_TORQUE) => settings.body_torque = ck.vector(value),
            Some(keys::SPACE_TORQUE) => settings.space_torque = ck.vector(value),
            Some(keys::TORQUE) => settings.torque = user_fn(ck, value),
            Some(keys::ANGLES) => settings.angles = angles(ck, value),
            _ => ck.cx.error_spanned_by(
                key,
                format!(
                    "unknown key `{key}` in `#[{}]`: expected {}",
                    keys::TOP,
                    TOP_KEYS.join(", ")
                ),
            ),
        }
    }
    let ok = items.complete && ck.cx.error_count() == errors_before;
    ok.then_some(Some(settings))
}

/// A scalar that must be positive (gravity: g along −z) or non-negative (damping: a
/// negative coefficient would feed energy in). Only literal values can be judged here.
fn sign_checked(ck: &mut Checker, value: &Expr, what: &str, strict: bool) -> Option<ExprId> {
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
            ck.cx.error_spanned_by(
                value,
                format!("`{what}` is {}: it must be {need}", r.to_f64()),
            );
            return None;
        }
    }
    Some(v)
}

/// The path of the user torque function.
fn user_fn(ck: &mut Checker, value: &Expr) -> Option<syn::Path> {
    match value {
        Expr::Path(p) if p.qself.is_none() => Some(p.path.clone()),
        _ => {
            ck.cx.error_spanned_by(value, format!("`{}` expects a path to a function `fn(&Self, f64, &Matrix3<f64>, &Vector3<f64>) -> Vector3<f64>` (time, attitude, body ω → body torque)", keys::TORQUE));
            None
        }
    }
}

/// `zxz` or `zyx`.
fn angles(ck: &mut Checker, value: &Expr) -> AngleSequence {
    let name = match value {
        Expr::Path(p) => p.path.get_ident().map(|i| i.to_string()),
        _ => None,
    };
    match name.as_deref() {
        Some("zxz") => AngleSequence::Zxz,
        Some("zyx") => AngleSequence::Zyx,
        _ => {
            ck.cx.error_spanned_by(
                value,
                format!(
                    "`{}` expects `zxz` (φ, θ, ψ) or `zyx` (yaw, pitch, roll)",
                    keys::ANGLES
                ),
            );
            AngleSequence::Zxz
        }
    }
}
