//! `rotor(axis = [x, y, z], inertia = J, rate = Ω)`: an internal wheel spinning at a constant
//! rate relative to the body, shared by `#[free]` and `#[top]`; `rotor(axis = [x, y, z],
//! inertia = J, torque = path)`: a wheel turned by a motor, its rate a state variable. Its values go through the
//! same checker as every other value (units, fields, arithmetic), with the rules a rotor
//! adds: a positive inertia and a non-zero axis, checked now for literals and by
//! `check_parameters` at run time for fields.

use precess_core::codegen::Emitted;
use precess_core::rigid::Rotor;
use precess_core::sym::{Arena, ExprId};
use proc_macro2::TokenStream;
use quote::quote;
use syn::{Expr, Ident};

use crate::lang::check::Checker;
use crate::lang::ctxt::Ctxt;
use crate::lang::keys::{self, ROTOR_KEYS};
use crate::lang::symbols::Lowering;
use crate::lang::syntax::KeyValue;
use crate::lang::units::Dim;

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
    match value {
        Expr::Path(p) if p.qself.is_none() => Some(p.path.clone()),
        _ => {
            ck.cx.error_spanned_by(
                value,
                format!(
                    "the rotor's `{}` expects a path to a function `fn(&Self, f64, &[f64]) -> f64` (time and the whole state → the motor torque on the wheel about its axis, N m; the state's rotor slots are `Self::ROTOR_k`)",
                    keys::TORQUE
                ),
            );
            None
        }
    }
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

/// Statements for `check_parameters`: each rotor's inertia positive and axis non-zero for the
/// current field values (all finite already), else `<error>::InvalidRotor`, with `error` the
/// attribute's error enum (`FreeError`, `TopError`: both carry the variant); the rotors given
/// as (index among every rotor declared, axis, inertia).
pub fn check_tokens_indexed(
    low: &Lowering,
    arena: &precess_core::sym::Arena,
    rotors: &[(usize, [ExprId; 3], ExprId)],
    error: &TokenStream,
) -> TokenStream {
    let values: Vec<ExprId> = rotors
        .iter()
        .flat_map(|&(_, axis, inertia)| std::iter::once(inertia).chain(axis))
        .collect();
    if values.is_empty() {
        return TokenStream::new();
    }
    let Emitted { lets, outputs } = low.lower(arena, &values);
    let checks = outputs.chunks(4).zip(rotors).map(|(o, &(k, _, _))| {
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

/// Where the driven-rotor rule of [`literal_driven_inertia`] is read: the scene's word for
/// the body (`"top"`, `"body"`) and the point its inertia is about (`"the pivot"`, `"its
/// centre of mass"`), for the message.
pub struct InertiaAbout<'a> {
    /// The scene's word for the body.
    pub body: &'a str,
    /// The point the inertia is about.
    pub point: &'a str,
}

/// With literal values, the rule driven rotors add in every scene that has them: the body's
/// `inertia` (about `about.point`) stays positive definite as each wheel's axial moment is
/// taken out, I − Σ J â âᵀ. An error spanned on the first rotor's `inertia` that breaks it;
/// `None` after recording it. A value that reads a field is left to the generated run-time
/// check.
pub fn literal_driven_inertia(
    cx: &Ctxt,
    arena: &Arena,
    inertia: &[[ExprId; 3]; 3],
    driven: &[(usize, Driven)],
    about: InertiaAbout<'_>,
) -> Option<()> {
    let constant = |e: ExprId| arena.free_symbols(e).is_empty().then(|| arena.eval(e, &[]));
    let literal = || {
        let mut m = precess_core::nalgebra::Matrix3::zeros();
        for i in 0..3 {
            for j in 0..3 {
                m[(i, j)] = constant(inertia[i][j])?;
            }
        }
        let mut wheels = Vec::new();
        for (_, d) in driven {
            let axis = [
                constant(d.axis[0])?,
                constant(d.axis[1])?,
                constant(d.axis[2])?,
            ];
            wheels.push((axis, constant(d.inertia)?));
        }
        Some((m, wheels))
    };
    let Some((m, wheels)) = literal() else {
        return Some(());
    };
    let Some((k, smallest)) = precess_core::rigid::first_singular_driven(&m, &wheels) else {
        return Some(());
    };
    let (declared, d) = &driven[k];
    let InertiaAbout { body, point } = about;
    cx.error_spanned_by(
        &d.inertia_expr,
        format!(
            "rotor {declared}'s `inertia` is too large for the {body}: with its driven wheels turning freely the {body} keeps I − Σ J â âᵀ about {point}, whose smallest principal moment here is {} kg m^2; it must be positive beyond rounding (a wheel's J below the {body}'s own moment about the wheel's axis by more than {:.0e} of its largest moment)",
            readable(smallest),
            precess_core::rigid::DRIVEN_ROUNDING
        ),
    );
    None
}

/// A moment as the messages print it: four decimals where that shows it (`-0.0100`), else
/// four significant digits in exponent form (`4.441e-16`, where `{:.4}` printed `0.0000`).
fn readable(x: f64) -> String {
    if x == 0.0 || (1e-3..1e6).contains(&x.abs()) {
        format!("{x:.4}")
    } else {
        format!("{x:.3e}")
    }
}
