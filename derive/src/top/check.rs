//! Meaning of the `#[top(...)]` items: keys against the table in `keys.rs`, values with the
//! value rules of `lang::values` in the same arena, and the rules of
//! `precess_core::top::TopParameters` on the values that are literals (field values meet the
//! same rules at run time, in the generated `TopDynamics::check_parameters`).

use precess_core::nalgebra::Vector3;
use precess_core::rigid::AngleSequence;
use precess_core::rigid::Rotor;
use precess_core::sym::ExprId;
use precess_core::top::TopParameters;
use syn::Expr;

use crate::lang::check::Checker;
use crate::lang::keys::{self, TOP_KEYS};
use crate::lang::syntax::{Item, KeyValue, Parsed, distinct};
use crate::lang::taylor::TaylorKey;
use crate::lang::units::Dim;

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
    /// The maximum order of the generated Taylor recurrences, if asked for.
    pub taylor: Option<usize>,
    /// Internal rotors at constant relative rates (the top is a gyrostat).
    pub rotors: Vec<Rotor>,
    /// Each constant-rate rotor's index among every rotor declared.
    pub rotor_index: Vec<usize>,
    /// The rotors turned by motors, with their index among every rotor declared: their
    /// rates are state variables, after `[q, q̇]`.
    pub driven: Vec<(usize, crate::lang::rotor::Driven)>,
    /// The generated variational equations, if asked for.
    pub variational: Option<super::variational::VariationalKey>,
}

/// Checks the `#[top]` items, if the struct has any. `None` after an error (recorded),
/// `Some(None)` when the struct declares no top. `declares_pivot` is `None` when the
/// `#[rigid]` attribute could not be read, so a missing pivot is not reported twice.
pub fn check(
    ck: &mut Checker,
    items: &Parsed<Item>,
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
        taylor: None,
        rotors: Vec::new(),
        rotor_index: Vec::new(),
        driven: Vec::new(),
        variational: None,
    };
    let in_top = format!("`#[{}]`", keys::TOP);
    let top_settings = items.items.iter().filter_map(|item| match item {
        Item::Setting(kv) => Some(&**kv),
        Item::Group { .. } => None,
    });
    let taylor = TaylorKey::find(
        ck.cx,
        top_settings.clone().map(|kv| (&kv.key, &kv.value)),
        &in_top,
    );
    // The groups: rotors, each checked by the rules `#[free]` holds them to; the
    // variational group once every field the equations read is known, after the settings.
    let mut variational = Vec::new();
    let mut declared_rotors = 0usize;
    for item in &items.items {
        if let Item::Group { name, keys } = item {
            if name == super::variational::VARIATIONAL {
                variational.push((name, keys));
            } else if name == keys::ROTOR {
                let index = declared_rotors;
                declared_rotors += 1;
                match crate::lang::rotor::check(ck, name, keys, &in_top, true) {
                    Some(crate::lang::rotor::Checked::Constant(rotor)) => {
                        settings.rotors.push(rotor);
                        settings.rotor_index.push(index);
                    }
                    Some(crate::lang::rotor::Checked::Driven(driven)) => {
                        settings.driven.push((index, *driven));
                    }
                    None => {}
                }
            } else {
                ck.cx.error_spanned_by(
                    name,
                    format!(
                        "unknown group `{name}(...)` in `#[{}]`: the groups are `{}({} = [x, y, z], {} = J, {} = Ω)`, an internal rotor, and {}, the generated variational equations; settings are written `key = value`",
                        keys::TOP,
                        keys::ROTOR,
                        keys::AXIS,
                        keys::INERTIA,
                        keys::RATE,
                        super::variational::form()
                    ),
                );
            }
        }
    }
    let cx = ck.cx;
    for KeyValue { key, value } in distinct(cx, top_settings, &in_top) {
        match TOP_KEYS.iter().find(|&&k| key == k).copied() {
            Some(k @ keys::GRAVITY) => settings.gravity = scalar(ck, k, Dim::ACCELERATION, value),
            Some(k @ keys::DAMPING) => settings.damping = scalar(ck, k, Dim::ROTARY_DAMPING, value),
            Some(k @ keys::BODY_TORQUE) => settings.body_torque = vector(ck, k, Dim::TORQUE, value),
            Some(k @ keys::SPACE_TORQUE) => {
                settings.space_torque = vector(ck, k, Dim::TORQUE, value)
            }
            Some(keys::TORQUE) => settings.torque = user_fn(ck, value),
            Some(keys::ANGLES) => settings.angles = angles(ck, value),
            _ if key == keys::ROTOR => ck
                .cx
                .error_spanned_by(key, crate::lang::rotor::written_as_setting()),
            _ => {
                let groups = [
                    crate::lang::rotor::listed(true),
                    crate::lang::variational::listed(),
                ];
                let place = format!("in {in_top}");
                let message = keys::unknown_key(key, &place, TOP_KEYS, &groups);
                ck.cx.error_spanned_by(key, message);
            }
        }
    }
    // A motor is a user function too: its torque has no Taylor coefficients.
    let user = [
        (keys::TORQUE, settings.torque.is_some()),
        (keys::TORQUE, !settings.driven.is_empty()),
    ];
    settings.taylor = taylor.order(ck.cx, &user);
    for (k, (name, keys)) in variational.into_iter().enumerate() {
        if k > 0 {
            ck.cx.error_spanned_by(
                name,
                format!("duplicate group `{name}(...)` in {in_top}: one set of variational equations per top"),
            );
        } else if let Some((k, _)) = settings.driven.first() {
            // The variational equations are over [q, q̇]; a driven top's state and its
            // motors' derivatives are beyond them.
            ck.cx.error_spanned_by(
                name,
                format!(
                    "`{name}(...)` cannot be combined with a rotor driven by a motor (rotor {k}'s `{}`): the variational equations are derived over the state [q, q̇] of a top without motors; drop `{name}(...)` or give the rotor a constant `{} = Ω`",
                    keys::TORQUE,
                    keys::RATE
                ),
            );
        } else {
            settings.variational =
                super::variational::check(ck, name, keys, settings.torque.is_some());
        }
    }
    // Every field the body and the top read is known by now.
    // A driven rotor's rate is not among them: its slot is the const `ROTOR_k` and the
    // printed equations name no symbol `rotor_k`, so a field of that name is harmless.
    let names = settings.angles.names().map(str::to_owned);
    let sequence = match settings.angles {
        AngleSequence::Zxz => "zxz",
        AngleSequence::Zyx => "zyx",
    };
    let whose = format!("the top in `{} = {sequence}`", keys::ANGLES);
    ck.refuse_coordinate_names(&names, &whose);
    let ok = items.complete && ck.cx.error_count() == errors_before;
    ok.then_some(Some(settings))
}

/// The scalar setting `key` (`gravity`, `damping`), held to the rule of the generated
/// `TopDynamics::check_parameters` when it is a constant ([`literal_rule`]).
fn scalar(ck: &mut Checker, key: &'static str, dim: Dim, value: &Expr) -> Option<ExprId> {
    let v = ck.expecting(dim, key, |ck| ck.scalar(value))?;
    literal_rule(ck, key, value, &[v]).then_some(v)
}

/// The vector setting `key` (`body_torque`, `space_torque`), as [`scalar`].
fn vector(ck: &mut Checker, key: &'static str, dim: Dim, value: &Expr) -> Option<[ExprId; 3]> {
    let v = ck.expecting(dim, key, |ck| ck.vector(value))?;
    literal_rule(ck, key, value, &v).then_some(v)
}

/// Judges the setting `key`, of value `v`, by the rule the generated
/// `TopDynamics::check_parameters` applies to field values at run time, so both are held to
/// one rule, when all of `v` is constant (a vector mixing fields and literals is judged
/// whole at run time; its literal components are finite: literals always are); records its
/// error on `value`. False after an error.
fn literal_rule(ck: &Checker, key: &str, value: &Expr, v: &[ExprId]) -> bool {
    let constant: Option<Vec<f64>> = v
        .iter()
        .map(|&e| ck.arena.as_rational(e).map(|r| r.to_f64()))
        .collect();
    let Some(c) = constant else {
        return true;
    };
    let mut literal = TopParameters::default();
    match (key, c.as_slice()) {
        (keys::GRAVITY, &[g]) => literal.gravity = Some(g),
        (keys::DAMPING, &[k]) => literal.damping = Some(k),
        (keys::BODY_TORQUE, &[x, y, z]) => literal.body_torque = Some(Vector3::new(x, y, z)),
        (keys::SPACE_TORQUE, &[x, y, z]) => literal.space_torque = Some(Vector3::new(x, y, z)),
        _ => {}
    }
    match literal.check() {
        Ok(()) => true,
        Err(e) => {
            ck.cx.error_spanned_by(value, e);
            false
        }
    }
}

/// The path of the user torque function.
fn user_fn(ck: &mut Checker, value: &Expr) -> Option<syn::Path> {
    let function = "`fn(&Self, f64, &Matrix3<f64>, &Vector3<f64>) -> Vector3<f64>` (time, attitude, body ω → body torque)";
    ck.function_path(value, &format!("`{}`", keys::TORQUE), function)
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
