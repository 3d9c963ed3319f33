//! Meaning of the `#[free(...)]` items: keys against the table in `keys.rs`, values with the
//! value rules of `lang::values` in the same arena, one function per rule with its reason.

use precess_core::free::{AppliedForce, ForcePoint, FreeScene};
use precess_core::sym::ExprId;
use syn::{Attribute, Expr, Ident};

use crate::lang::check::Checker;
use crate::lang::keys::{self, FORCE_KEYS, FREE_FORCES, FREE_KEYS};
use crate::lang::rotor::{Checked, Driven};
use crate::lang::syntax::{Item, KeyValue, Parsed};
use crate::lang::taylor::TaylorKey;
use crate::lang::units::Dim;

/// The checked `#[free(...)]` settings: what acts on the body.
pub struct FreeSettings {
    /// The declared loads and constant-rate rotors as the scene's own fields (gravity,
    /// forces and torques fixed in the body or in space, drag, damping, `rotors`), so that
    /// expansion completes this scene with the body's mass properties rather than copying
    /// a mirror of it field by field. Its mass, centre and frame are placeholders here.
    pub loads: FreeScene,
    /// The path of a user force function (space axes).
    pub force: Option<syn::Path>,
    /// The path of a user torque function (description axes).
    pub torque: Option<syn::Path>,
    /// The paths of user wrench functions (`fn(&Self, f64, &FreeState) -> AppliedWrench`),
    /// their values summed.
    pub wrenches: Vec<syn::Path>,
    /// The maximum order of the generated Taylor recurrences, if asked for.
    pub taylor: Option<usize>,
    /// The declared index of each of `loads.rotors` among all the rotors declared.
    pub rotor_index: Vec<usize>,
    /// Internal rotors turned by motors, with their index among all the rotors declared.
    pub driven: Vec<(usize, Driven)>,
}

impl FreeSettings {
    /// No loads, no rotors, no user functions: a torque-free body.
    fn empty(ck: &mut Checker) -> FreeSettings {
        let zero = ck.arena.zero();
        FreeSettings {
            loads: FreeScene::new(ck.arena, zero, [zero; 3]),
            force: None,
            torque: None,
            wrenches: Vec::new(),
            taylor: None,
            rotor_index: Vec::new(),
            driven: Vec::new(),
        }
    }
}

/// Checks the `#[free]` items, if the struct has any attribute. `None` after an error
/// (recorded), `Some(None)` when the struct declares no free body.
pub fn check(
    ck: &mut Checker,
    attrs: &[&Attribute],
    items: &Parsed<Item>,
) -> Option<Option<FreeSettings>> {
    let Some(&first) = attrs.first() else {
        return Some(None);
    };
    let errors_before = ck.cx.error_count();
    // A top turns about a fixed pivot, a free body about its moving centre of mass: one
    // struct cannot be both, and two sets of equations would disagree on what the state is.
    if !ck.input.top.is_empty() {
        ck.cx.error_spanned_by(
            first,
            format!(
                "`#[{}]` cannot be combined with `#[{}]` on one struct: a top turns about its fixed pivot, a free body about its centre of mass; derive each on its own struct",
                keys::FREE,
                keys::TOP
            ),
        );
    }
    let mut settings = FreeSettings::empty(ck);
    let mut seen: Vec<&Ident> = Vec::new();
    let in_free = format!("`#[{}]`", keys::FREE);
    let free_settings = items.items.iter().filter_map(|item| match item {
        Item::Setting(kv) => Some((&kv.key, &kv.value)),
        Item::Group { .. } => None,
    });
    let taylor = TaylorKey::find(ck.cx, free_settings, &in_free);
    let mut declared_rotors = 0usize;
    for item in &items.items {
        match item {
            // Read by `TaylorKey` above.
            Item::Setting(kv) if kv.key == keys::TAYLOR => {}
            Item::Setting(kv) => setting(ck, &mut settings, &mut seen, kv),
            Item::Group { name, keys } if name == keys::ROTOR => {
                let index = declared_rotors;
                declared_rotors += 1;
                match crate::lang::rotor::check(ck, name, keys, &in_free, true) {
                    Some(Checked::Constant(rotor)) => {
                        settings.loads.rotors.push(rotor);
                        settings.rotor_index.push(index);
                    }
                    Some(Checked::Driven(driven)) => settings.driven.push((index, *driven)),
                    None => {}
                }
            }
            Item::Group { name, keys } => {
                if let Some((space, force)) = force_part(ck, name, keys) {
                    if space {
                        settings.loads.space_forces.push(force);
                    } else {
                        settings.loads.body_forces.push(force);
                    }
                }
            }
        }
    }
    let user = [
        (keys::FORCE, settings.force.is_some()),
        (keys::TORQUE, settings.torque.is_some()),
        (keys::WRENCH, !settings.wrenches.is_empty()),
        (keys::TORQUE, !settings.driven.is_empty()),
    ];
    settings.taylor = taylor.order(ck.cx, &user);
    let ok = items.complete && ck.cx.error_count() == errors_before;
    ok.then_some(Some(settings))
}

/// One `key = value` setting.
fn setting<'a>(
    ck: &mut Checker,
    settings: &mut FreeSettings,
    seen: &mut Vec<&'a Ident>,
    KeyValue { key, value }: &'a KeyValue,
) {
    // Wrenches may repeat: several contacts, each its own function, add.
    if key == keys::WRENCH {
        settings.wrenches.extend(user_fn(ck, value, keys::WRENCH));
        return;
    }
    // Each setting once: two gravities or two drags would be ambiguous.
    if seen.contains(&key) {
        ck.cx
            .error_spanned_by(key, format!("duplicate key `{key}` in `#[{}]`", keys::FREE));
        return;
    }
    seen.push(key);
    match FREE_KEYS.iter().find(|&&k| key == k).copied() {
        Some(keys::GRAVITY) => {
            settings.loads.gravity =
                ck.expecting(Dim::ACCELERATION, keys::GRAVITY, |ck| gravity(ck, value))
        }
        Some(keys::DRAG) => {
            settings.loads.drag = ck.expecting(Dim::DRAG, keys::DRAG, |ck| {
                ck.non_negative(value, &format!("`{}`", keys::DRAG), FEEDS_ENERGY)
            })
        }
        Some(keys::DAMPING) => {
            settings.loads.damping = ck.expecting(Dim::ROTARY_DAMPING, keys::DAMPING, |ck| {
                ck.non_negative(value, &format!("`{}`", keys::DAMPING), FEEDS_ENERGY)
            })
        }
        Some(keys::BODY_TORQUE) => {
            settings.loads.body_torque =
                ck.expecting(Dim::TORQUE, keys::BODY_TORQUE, |ck| ck.vector(value))
        }
        Some(keys::SPACE_TORQUE) => {
            settings.loads.space_torque =
                ck.expecting(Dim::TORQUE, keys::SPACE_TORQUE, |ck| ck.vector(value))
        }
        Some(keys::FORCE) => settings.force = user_fn(ck, value, keys::FORCE),
        Some(keys::TORQUE) => settings.torque = user_fn(ck, value, keys::TORQUE),
        _ if key == keys::ROTOR => ck
            .cx
            .error_spanned_by(key, crate::lang::rotor::written_as_setting()),
        _ if FREE_FORCES.iter().any(|&f| key == f) => ck.cx.error_spanned_by(
            key,
            format!(
                "`{key}` is a force at a point: write `{key}({} = [x, y, z], {} = [x, y, z])`",
                keys::FORCE,
                keys::FORCE_AT
            ),
        ),
        _ => ck.cx.error_spanned_by(key, unknown(key)),
    }
}

/// The message for a key `#[free]` does not know, listing what it does.
fn unknown(key: &Ident) -> String {
    let forces: Vec<String> = FREE_FORCES
        .iter()
        .map(|f| format!("`{f}({}, {})`", keys::FORCE, keys::FORCE_AT))
        .collect();
    let groups = [
        (FREE_FORCES, format!("a force {}", forces.join(" or "))),
        crate::lang::rotor::listed(true),
    ];
    keys::unknown_key(key, &format!("in `#[{}]`", keys::FREE), FREE_KEYS, &groups)
}

/// `body_force(force = [..], at = [..])` or `space_force(...)`: `(is space-fixed, force)`.
fn force_part(ck: &mut Checker, name: &Ident, kvs: &[KeyValue]) -> Option<(bool, AppliedForce)> {
    let Some(&kind) = FREE_FORCES.iter().find(|&&f| name == f) else {
        ck.cx.error_spanned_by(
            name,
            if FREE_KEYS.iter().any(|&k| name == k) {
                format!("`{name}` is a setting: write `{name} = value`")
            } else {
                unknown(name)
            },
        );
        return None;
    };
    let mut force: Option<&Expr> = None;
    let mut at: Option<&Expr> = None;
    let mut ok = true;
    for KeyValue { key, value } in kvs {
        let Some(k) = keys::known_key(ck.cx, key, &format!("for `{kind}`"), FORCE_KEYS) else {
            ok = false;
            continue;
        };
        let slot = if k == keys::FORCE {
            &mut force
        } else {
            &mut at
        };
        // Each key once: two forces in one part are ambiguous.
        if slot.is_some() {
            ck.cx
                .error_spanned_by(key, format!("duplicate key `{key}` in `{kind}`"));
            ok = false;
            continue;
        }
        *slot = Some(value);
    }
    // The force needs its point: off the centre of mass it also turns the body, and which
    // way depends on where it acts.
    let Some(at) = at else {
        ck.cx.error_spanned_by(
            name,
            format!(
                "`{kind}` needs `{} = [x, y, z]`, the point of the body it acts at (description axes), or `{} = {}` for a force through the centre of mass",
                keys::FORCE_AT,
                keys::FORCE_AT,
                keys::CENTER_POINT
            ),
        );
        return None;
    };
    let Some(force) = force else {
        ck.cx.error_spanned_by(
            name,
            format!("`{kind}` needs `{} = [x, y, z]`", keys::FORCE),
        );
        return None;
    };
    let force = ck.expecting(Dim::FORCE, keys::FORCE, |ck| ck.vector(force));
    let at = ck.expecting(Dim::LENGTH, keys::FORCE_AT, |ck| point(ck, at));
    let (force, at) = (force?, at?);
    ok.then_some((kind == keys::SPACE_FORCE, AppliedForce { force, at }))
}

/// `[x, y, z]` (description axes) or `center`.
fn point(ck: &mut Checker, value: &Expr) -> Option<ForcePoint> {
    if let Expr::Path(p) = value
        && p.path.is_ident(keys::CENTER_POINT)
    {
        return Some(ForcePoint::Center);
    }
    if !matches!(value, Expr::Array(_)) {
        ck.cx.error_spanned_by(
            value,
            format!(
                "expected a point `[x, y, z]` of the body (description axes) or `{}`",
                keys::CENTER_POINT
            ),
        );
        return None;
    }
    ck.vector(value).map(ForcePoint::Body)
}

/// `gravity = g` (magnitude, along −z in space) or `gravity = [gx, gy, gz]` (space axes).
fn gravity(ck: &mut Checker, value: &Expr) -> Option<[ExprId; 3]> {
    if matches!(value, Expr::Array(_)) {
        return ck.vector(value);
    }
    // A magnitude along −z: a negative one would be gravity pointing up, written twice
    // over; give the vector for any direction.
    let why = "a magnitude, acting along −z; give `[gx, gy, gz]` for any other direction";
    let g = ck.positive(value, &format!("`{}`", keys::GRAVITY), Some(why))?;
    let z = ck.arena.zero();
    Some([z, z, ck.arena.neg(g)])
}

/// Why a drag or damping must not be negative.
const FEEDS_ENERGY: Option<&str> = Some("a negative one feeds energy in");

/// The path of a user function.
fn user_fn(ck: &mut Checker, value: &Expr, what: &str) -> Option<syn::Path> {
    let function = match what {
        keys::WRENCH => {
            "`fn(&Self, f64, &FreeState) -> AppliedWrench` (time, state → force and torque, in the frame its constructor names: `AppliedWrench::space`, `AppliedWrench::body` or `AppliedWrench::at_point_space`)"
        }
        keys::FORCE => {
            "`fn(&Self, f64, &FreeState) -> Vector3<f64>` (time, state → the force on the centre of mass, space axes)"
        }
        _ => {
            "`fn(&Self, f64, &FreeState) -> Vector3<f64>` (time, state → the torque about the centre of mass, description axes)"
        }
    };
    ck.function_path(value, &format!("`{what}`"), function)
}
