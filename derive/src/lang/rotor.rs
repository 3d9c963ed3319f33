//! `rotor(axis = [x, y, z], inertia = J, rate = Ω)`: an internal wheel spinning at a constant
//! rate relative to the body, shared by `#[free]` and `#[top]`. Its values go through the
//! same checker as every other value (units, fields, arithmetic), with the rules a rotor
//! adds: a positive inertia and a non-zero axis, checked now for literals and by
//! `check_parameters` at run time for fields.

use precess_core::codegen::Emitted;
use precess_core::rigid::Rotor;
use precess_core::sym::ExprId;
use proc_macro2::TokenStream;
use quote::quote;
use syn::{Expr, Ident};

use crate::lang::check::Checker;
use crate::lang::keys::{self, ROTOR_KEYS};
use crate::lang::symbols::Lowering;
use crate::lang::syntax::KeyValue;
use crate::lang::units::Dim;

/// A rate, 1/s (`rpm`, `Hz`, `rad/s`).
const RATE: Dim = Dim { m: 0, l: 0, t: -1 };

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

/// The message for `rotor = ..` written as a setting: a rotor is a group of its own keys.
pub fn written_as_setting() -> String {
    format!("`{}` is a part: write {}", keys::ROTOR, form())
}

/// Checks one `rotor(...)` group of the attribute `within` (`#[free]`, `#[top]`).
pub fn check(ck: &mut Checker, name: &Ident, kvs: &[KeyValue], within: &str) -> Option<Rotor> {
    let mut slots: [Option<&Expr>; 3] = [None; 3];
    let mut ok = true;
    for KeyValue { key, value } in kvs {
        let Some(at) = ROTOR_KEYS.iter().position(|&k| key == k) else {
            ck.cx.error_spanned_by(
                key,
                format!(
                    "unknown key `{key}` for `{}` in {within}: allowed keys are {}{}",
                    keys::ROTOR,
                    ROTOR_KEYS.join(", "),
                    keys::did_you_mean(&key.to_string(), ROTOR_KEYS.iter().copied())
                ),
            );
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
        slots[at] = Some(value);
    }
    // An unknown or repeated key is the error to fix first; a key it stood for would be
    // reported missing too.
    if !ok {
        return None;
    }
    let [axis, inertia, rate] = slots;
    let (Some(axis), Some(inertia), Some(rate)) = (axis, inertia, rate) else {
        // The wheel needs all three: which way it spins, how heavy it is, how fast.
        let missing: Vec<String> = ROTOR_KEYS
            .iter()
            .zip(slots)
            .filter(|(_, s)| s.is_none())
            .map(|(k, _)| format!("`{k}`"))
            .collect();
        ck.cx.error_spanned_by(
            name,
            format!(
                "`{}` needs {}: write `{}({} = [x, y, z], {} = J, {} = Ω)` (the axis fixed in the body, description axes; J the wheel's moment of inertia about it; Ω its spin relative to the body, e.g. `3000 rpm`)",
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
    let inertia = ck.expecting(Dim::INERTIA, keys::INERTIA, |ck| positive(ck, inertia));
    let rate = ck.expecting(RATE, keys::RATE, |ck| ck.scalar(rate));
    Some(Rotor {
        axis: axis?,
        inertia: inertia?,
        rate: rate?,
    })
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

/// The axial moment, positive when a literal: a wheel without inertia carries no momentum,
/// a negative one is unphysical.
fn positive(ck: &mut Checker, value: &Expr) -> Option<ExprId> {
    let v = ck.scalar(value)?;
    if let Some(r) = ck.arena.as_rational(v)
        && (r.is_negative() || r.is_zero())
    {
        ck.cx.error_spanned_by(
            value,
            format!(
                "the rotor's `{}` is {}: it must be positive (the wheel's moment of inertia about its axis, kg m^2)",
                keys::INERTIA,
                r.to_f64()
            ),
        );
        return None;
    }
    Some(v)
}

/// Statements for `check_parameters`: each rotor's inertia positive and axis non-zero for the
/// current field values (all finite already), else `<error>::InvalidRotor`, with `error`
/// the attribute's error enum (`FreeError`, `TopError`: both carry the variant).
pub fn check_tokens(
    low: &Lowering,
    arena: &precess_core::sym::Arena,
    rotors: &[Rotor],
    error: &TokenStream,
) -> TokenStream {
    let values: Vec<ExprId> = rotors
        .iter()
        .flat_map(|r| std::iter::once(r.inertia).chain(r.axis))
        .collect();
    if values.is_empty() {
        return TokenStream::new();
    }
    let Emitted { lets, outputs } = low.lower(arena, &values);
    let checks = outputs.chunks(4).enumerate().map(|(k, o)| {
        let (j, a) = (&o[0], &o[1..]);
        quote! {
            let __j: f64 = #j;
            let __a: f64 = (#((#a) * (#a))+*).sqrt();
            if !(__j.is_finite() && __j > 0.0 && __a.is_finite() && __a > 0.0) {
                return ::core::result::Result::Err(#error::InvalidRotor {
                    rotor: #k,
                    inertia: __j,
                    axis_norm: __a,
                });
            }
        }
    });
    quote!({ #lets #(#checks)* })
}
