//! `rotor(axis = [x, y, z], inertia = J, rate = Ω)`: an internal wheel spinning at a constant
//! rate relative to the body, shared by `#[free]` and `#[top]`; `rotor(axis = [x, y, z],
//! inertia = J, torque = path)`: a wheel turned by a motor, its rate a state variable. Its values go through the
//! same checker as every other value (units, fields, arithmetic), with the rules a rotor
//! adds: a positive inertia and a non-zero axis, checked now for literals and by
//! `check_parameters` at run time for fields.

use precess_core::rigid::Rotor;
use precess_core::sym::ExprId;
use proc_macro2::TokenStream;
use quote::{ToTokens, quote};
use syn::{Attribute, DeriveInput, Expr, Ident};

use crate::lang::check::Checker;
use crate::lang::ctxt::Ctxt;
use crate::lang::keys::{self, ROTOR_KEYS};
use crate::lang::syntax::{Item, KeyValue, Parsed};
use crate::lang::units::Dim;

mod checks;
mod motors;

pub use motors::motor_methods;

pub use checks::{InertiaAbout, check_tokens, literal_driven_inertia};

/// An angular rate, rad/s (`rpm`, `rev/s`, `rad/s`).
const RATE: Dim = Dim::ANGULAR_RATE;

/// The rotor's form as the messages write it: `` `rotor(axis = [x, y, z], inertia = J, rate = Ω)` ``.
pub fn form() -> String {
    format!(
        "`{}({} = [x, y, z], {} = J, {} = Ω)`",
        keys::ROTOR,
        keys::AXIS,
        keys::INERTIA,
        keys::RATE
    )
}

/// A rotor group as a message for an unknown key of the attribute lists it
/// (`keys::unknown_key`'s `others`): its name, and its form with every key it takes.
pub fn listed(driven: bool) -> (&'static [&'static str], String) {
    let form = format!(
        "a rotor `{}({})`",
        keys::ROTOR,
        allowed_keys(driven).join(", ")
    );
    (&[keys::ROTOR], form)
}

/// The keys a rotor takes where `driven` rotors are allowed (`#[free]`) or not (`#[top]`:
/// no `torque`).
pub fn allowed_keys(driven: bool) -> &'static [&'static str] {
    if driven { ROTOR_KEYS } else { &ROTOR_KEYS[..3] }
}

/// The message for `rotor = ..` written as a setting: a rotor is a group of its own keys.
pub fn written_as_setting() -> String {
    format!("`{}` is a part: write {}", keys::ROTOR, form())
}

/// A wheel turned by a motor, as `#[free]` and `#[top]` declare it.
pub struct Driven {
    /// Its axis, description axes.
    pub axis: [ExprId; 3],
    /// Its axial moment J.
    pub inertia: ExprId,
    /// The motor function `fn(&Self, f64, &[f64]) -> f64` (time, whole state → u).
    pub torque: syn::Path,
    /// The `inertia` value as written, where a literal J too large for the body is reported.
    pub inertia_expr: Expr,
}

/// A checked `rotor(...)` group: spun at a constant rate, or driven by a motor.
pub enum Checked {
    /// `rate = Ω`.
    Constant(Rotor),
    /// `torque = path`.
    Driven(Box<Driven>),
}

/// Checks one `rotor(...)` group of the attribute `within` (`#[free]`, `#[top]`); a driven
/// rotor (`torque = path`) only where `driven` allows it.
pub fn check(
    ck: &mut Checker,
    name: &Ident,
    kvs: &[KeyValue],
    within: &str,
    driven: bool,
) -> Option<Checked> {
    let mut slots: [Option<&Expr>; 4] = [None; 4];
    let mut ok = true;
    for KeyValue { key, value } in kvs {
        let Some(at) = ROTOR_KEYS.iter().position(|&k| key == k) else {
            let place = format!("for `{}` in {within}", keys::ROTOR);
            let message = keys::unknown_key(key, &place, allowed_keys(driven), &[]);
            ck.cx.error_spanned_by(key, message);
            ok = false;
            continue;
        };
        // Each key once: two rates for one wheel are ambiguous.
        if slots[at].is_some() {
            ck.cx
                .error_spanned_by(key, format!("duplicate key `{key}` in `{}`", keys::ROTOR));
            ok = false;
            continue;
        }
        if key == keys::TORQUE && !driven {
            ck.cx.error_spanned_by(
                key,
                format!(
                    "a rotor driven by a motor `{}` is for `#[{}]` only: a rotor in {within} spins at a constant `{} = Ω`",
                    keys::TORQUE,
                    keys::FREE,
                    keys::RATE
                ),
            );
            ok = false;
            continue;
        }
        slots[at] = Some(value);
    }
    // An unknown or repeated key is the error to fix first; a key it stood for would be
    // reported missing too.
    if !ok {
        return None;
    }
    let [axis, inertia, rate, torque] = slots;
    if let (Some(_), Some(torque)) = (rate, torque) {
        // Held at Ω by its motor, or accelerated by a given torque: one wheel cannot be both.
        ck.cx.error_spanned_by(
            torque,
            format!(
                "a rotor has either `{} = Ω` (held at a constant rate) or `{} = path` (turned by a motor, its rate a state variable), not both",
                keys::RATE,
                keys::TORQUE
            ),
        );
        return None;
    }
    let (Some(axis), Some(inertia), true) = (axis, inertia, rate.is_some() || torque.is_some())
    else {
        // The wheel needs all three: which way it spins, how heavy it is, how fast.
        let mut missing: Vec<String> = ROTOR_KEYS
            .iter()
            .zip(slots)
            .take(2)
            .filter(|(_, s)| s.is_none())
            .map(|(k, _)| format!("`{k}`"))
            .collect();
        if rate.is_none() && torque.is_none() {
            missing.push(if driven {
                format!("`{}` or `{}`", keys::RATE, keys::TORQUE)
            } else {
                format!("`{}`", keys::RATE)
            });
        }
        let driven_form = if driven {
            format!(
                ", or `{}({} = [x, y, z], {} = J, {} = path)` for a wheel turned by a motor (`fn(&Self, f64, &[f64]) -> f64`: time and the whole state → its torque)",
                keys::ROTOR,
                keys::AXIS,
                keys::INERTIA,
                keys::TORQUE
            )
        } else {
            String::new()
        };
        ck.cx.error_spanned_by(
            name,
            format!(
                "`{}` needs {}: write `{}({} = [x, y, z], {} = J, {} = Ω)` (the axis fixed in the body, description axes; J the wheel's moment of inertia about it; Ω its spin relative to the body, e.g. `3000 rpm`){driven_form}",
                keys::ROTOR,
                missing.join(" and "),
                keys::ROTOR,
                keys::AXIS,
                keys::INERTIA,
                keys::RATE
            ),
        );
        return None;
    };
    let axis = ck.expecting(Dim::NONE, keys::AXIS, |ck| rotor_axis(ck, axis));
    // A wheel without inertia carries no momentum; a negative one is unphysical.
    let what = format!("the rotor's `{}`", keys::INERTIA);
    let why = Some("the wheel's moment of inertia about its axis, kg m^2");
    let inertia_value = ck.expecting(Dim::INERTIA, keys::INERTIA, |ck| {
        ck.positive(inertia, &what, why)
    });
    if let Some(torque) = torque {
        let path = motor(ck, torque);
        return Some(Checked::Driven(Box::new(Driven {
            axis: axis?,
            inertia: inertia_value?,
            torque: path?,
            inertia_expr: inertia.clone(),
        })));
    }
    let rate = rate.and_then(|rate| ck.expecting(RATE, keys::RATE, |ck| ck.scalar(rate)));
    Some(Checked::Constant(Rotor {
        axis: axis?,
        inertia: inertia_value?,
        rate: rate?,
    }))
}

/// The motor function's path.
fn motor(ck: &mut Checker, value: &Expr) -> Option<syn::Path> {
    let function = "`fn(&Self, f64, &[f64]) -> f64` (time and the whole state → the motor torque on the wheel about its axis, N m; the state's rotor slots are `Self::ROTOR_k`)";
    ck.function_path(value, &format!("the rotor's `{}`", keys::TORQUE), function)
}

/// `[x, y, z]`, not zero when written in literals.
fn rotor_axis(ck: &mut Checker, value: &Expr) -> Option<[ExprId; 3]> {
    if !matches!(value, Expr::Array(_)) {
        ck.cx.error_spanned_by(
            value,
            format!(
                "expected the rotor's `{}` as a direction `[x, y, z]` fixed in the body (description axes)",
                keys::AXIS
            ),
        );
        return None;
    }
    let axis = ck.vector(value)?;
    let zero = axis
        .iter()
        .all(|&c| ck.arena.as_rational(c).is_some_and(|r| r.is_zero()));
    if zero {
        ck.cx.error_spanned_by(
            value,
            format!(
                "the rotor's `{}` is zero: give a non-zero direction `[x, y, z]` (its length does not matter)",
                keys::AXIS
            ),
        );
        return None;
    }
    Some(axis)
}

/// A scene's trait as a user writes it (`path`, a `TopDynamics` or `FreeDynamics` whose
/// state length N defaults to the scene's without motors): `path` alone unless a rotor is
/// `driven`, else `path<n>`.
pub fn scene_trait(path: TokenStream, n: impl ToTokens, driven: bool) -> TokenStream {
    if driven { quote!(#path<#n>) } else { path }
}

/// `rotor_k` for each `rotor(...)` group of the `#[attribute]` attributes (read with `parse`,
/// the attribute's own parser) that has a `torque` key, k counting every rotor group: the
/// driven rotors' slot names, read from the syntax alone so the stubs emitted beside the
/// errors name them even when the values have errors (those are the expansion's to tell).
pub fn driven_names(
    input: &DeriveInput,
    attribute: &str,
    parse: fn(&Ctxt, &[&Attribute]) -> Parsed<Item>,
) -> Vec<String> {
    let attrs: Vec<&Attribute> = input
        .attrs
        .iter()
        .filter(|a| a.path().is_ident(attribute))
        .collect();
    let cx = Ctxt::new();
    let parsed = parse(&cx, &attrs);
    let _ = cx.check();
    parsed
        .items
        .iter()
        .filter_map(|item| match item {
            Item::Group { name, keys } if name == keys::ROTOR => Some(keys),
            _ => None,
        })
        .enumerate()
        .filter(|(_, keys)| keys.iter().any(|kv| kv.key == keys::TORQUE))
        .map(|(k, _)| format!("rotor_{k}"))
        .collect()
}
