//! The call forms of `#[contact]`'s values, `name` or `name(key = value, ...)`: the
//! surface (by `lang::surface`, the reader a mechanism's wheel shares) and the law read
//! against the tables in `keys.rs`, each dimension and coefficient
//! with the rule it must meet where it is a literal (fields meet the same rules at run time).

use precess_core::contact::{ContactLaw, ContactTorques, Friction, Surface};
use precess_core::sym::ExprId;
use syn::{Expr, Ident};

use crate::lang::check::Checker;
use crate::lang::keys::{self, LAWS};
use crate::lang::surface::{self, Place};
use crate::lang::units::Dim;

/// One argument of a call form: `key = value`, or a bare word (`frictionless`).
enum Arg<'a> {
    Key(&'a Ident, &'a Expr),
    Flag(&'a Ident),
}

/// The surfaces as the messages list them: `sphere(radius, center, at)`, … (the one reader's
/// list, [`crate::lang::surface`]).
pub fn surface_list() -> String {
    surface::surface_list(Place::Table)
}

/// The laws as the messages list them.
pub fn law_list() -> String {
    format!(
        "`{r}`, `{r}({rr} = c, {sr} = c, {p} = ℓ)`, `{s}({v} = c)`, `{s}({nv} = μ)`, `{s}({c} = μ)`, `{s}({f})` or `{ss}({mu} = μ, {rr} = c, {sr} = c, {p} = ℓ)`",
        r = keys::ROLLING,
        rr = keys::ROLLING_RESISTANCE,
        sr = keys::SPIN_RESISTANCE,
        p = keys::PIVOTING,
        s = keys::SLIDING,
        v = keys::VISCOUS,
        nv = keys::NORMAL_VISCOUS,
        c = keys::COULOMB,
        f = keys::FRICTIONLESS,
        ss = keys::STICK_SLIP,
        mu = keys::MU,
    )
}

/// `name` or `name(args)`: the name and its arguments, or an error spanned on `e` saying
/// what `what` (a surface, a law) looks like.
fn call_form<'a>(ck: &Checker, e: &'a Expr, what: &str) -> Option<(&'a Ident, Vec<Arg<'a>>)> {
    let (func, args): (&Expr, Vec<&Expr>) = match e {
        Expr::Call(call) => (&call.func, call.args.iter().collect()),
        Expr::Path(_) => (e, Vec::new()),
        _ => {
            ck.cx.error_spanned_by(e, format!("expected {what}"));
            return None;
        }
    };
    let Some(name) = path_ident(func) else {
        ck.cx.error_spanned_by(e, format!("expected {what}"));
        return None;
    };
    let mut out = Vec::new();
    let mut ok = true;
    for arg in args {
        match arg {
            Expr::Assign(a) => match path_ident(&a.left) {
                Some(key) => out.push(Arg::Key(key, &a.right)),
                None => {
                    ck.cx
                        .error_spanned_by(&a.left, format!("expected a key of `{name}`"));
                    ok = false;
                }
            },
            _ => match path_ident(arg) {
                Some(flag) => out.push(Arg::Flag(flag)),
                None => {
                    ck.cx
                        .error_spanned_by(arg, format!("expected `key = value` in `{name}(...)`"));
                    ok = false;
                }
            },
        }
    }
    ok.then_some((name, out))
}

/// The single identifier a path expression is, if it is one.
fn path_ident(e: &Expr) -> Option<&Ident> {
    match e {
        Expr::Path(p) if p.qself.is_none() => p.path.get_ident(),
        _ => None,
    }
}

/// The arguments of `name(...)` against its allowed keys, each at most once: a value for
/// every key but `frictionless`, which stands alone. `None` after an error (recorded).
fn keyed<'a>(
    ck: &Checker,
    name: &Ident,
    args: &[Arg<'a>],
    allowed: &[&'static str],
) -> Option<Vec<(&'static str, Option<&'a Expr>, &'a Ident)>> {
    let mut out: Vec<(&'static str, Option<&'a Expr>, &'a Ident)> = Vec::new();
    let mut ok = true;
    for arg in args {
        let (key, value) = match arg {
            Arg::Key(key, value) => (*key, Some(*value)),
            Arg::Flag(key) => (*key, None),
        };
        let Some(k) = keys::known_key(ck.cx, key, &format!("for `{name}`"), allowed) else {
            ok = false;
            continue;
        };
        // Only `frictionless` stands alone; every other key carries a number.
        let flag = k == keys::FRICTIONLESS;
        if flag != value.is_none() {
            let msg = if flag {
                format!("`{k}` takes no value: write `{name}({k})`")
            } else {
                format!("`{k}` needs a value: write `{k} = ...`")
            };
            ck.cx.error_spanned_by(key, msg);
            ok = false;
            continue;
        }
        // Each key once: two radii would be ambiguous.
        if out.iter().any(|(seen, _, _)| *seen == k) {
            ck.cx
                .error_spanned_by(key, format!("duplicate key `{key}` in `{name}`"));
            ok = false;
            continue;
        }
        out.push((k, value, key));
    }
    ok.then_some(out)
}

/// The value of `key` among `args`, if given.
fn value_of<'a>(
    args: &[(&'static str, Option<&'a Expr>, &'a Ident)],
    key: &str,
) -> Option<&'a Expr> {
    args.iter()
        .find(|(k, _, _)| *k == key)
        .and_then(|(_, v, _)| *v)
}

/// `surface = name(key = value, ...)`, read by the one reader of rolling surfaces.
pub fn read_surface(ck: &mut Checker, value: &Expr) -> Option<Surface> {
    surface::read_surface(ck, value, Place::Table).map(|s| s.surface)
}

/// `law = name` or `law = name(key = value, ...)`, one of [`LAWS`]: the law, and the
/// torques it declares beyond a rolling law's own resistances (the resistances of
/// stick–slip, pivoting friction).
pub fn read_law(ck: &mut Checker, value: &Expr) -> Option<(ContactLaw, ContactTorques)> {
    let what = format!("a contact law: {}", law_list());
    let (name, args) = call_form(ck, value, &what)?;
    let Some(&(kind, allowed)) = LAWS.iter().find(|(l, _)| name == l) else {
        let names = LAWS.iter().map(|(l, _)| *l);
        ck.cx.error_spanned_by(
            name,
            format!(
                "unknown contact law `{name}`: expected {}{}",
                law_list(),
                keys::did_you_mean(&name.to_string(), names)
            ),
        );
        return None;
    };
    let args = keyed(ck, name, &args, allowed)?;
    // A resistance is a torque per angular rate, viscous friction a force per slip speed,
    // a friction coefficient a pure number.
    let coefficient = |ck: &mut Checker, key: &'static str| -> Option<Option<ExprId>> {
        let (dim, what) = match key {
            keys::ROLLING_RESISTANCE | keys::SPIN_RESISTANCE => (Dim::ROTARY_DAMPING, None),
            keys::VISCOUS => (Dim::DRAG, None),
            // ℓ_p = μ_p r_p, a friction coefficient times the contact patch's radius.
            keys::PIVOTING => (
                Dim::LENGTH,
                Some("a length (m): the pivoting coefficient times the contact patch's radius"),
            ),
            // μ of F = −μ N u: a force per newton per slip speed, s/m.
            keys::NORMAL_VISCOUS => (
                Dim::DRAG.times(Dim::FORCE.pow(-1)?)?,
                Some("an inverse speed (s/m): F = −μ N u"),
            ),
            _ => (
                Dim::NONE,
                Some("a pure number (a friction coefficient has no units)"),
            ),
        };
        match value_of(&args, key) {
            Some(v) => ck
                .expecting_as(dim, what, key, |ck| {
                    ck.non_negative(v, &format!("`{key}` of `{kind}`"), FEEDS_ENERGY)
                })
                .map(Some),
            None => Some(None),
        }
    };
    // Every law but sliding takes the resistances; each is read (and its errors told)
    // before any is refused.
    let (rolling_resistance, spin_resistance, pivoting) = if kind == keys::SLIDING {
        (Some(None), Some(None), Some(None))
    } else {
        (
            coefficient(ck, keys::ROLLING_RESISTANCE),
            coefficient(ck, keys::SPIN_RESISTANCE),
            coefficient(ck, keys::PIVOTING),
        )
    };
    let (rolling_resistance, spin_resistance) = (rolling_resistance?, spin_resistance?);
    let mut torques = ContactTorques {
        pivoting: pivoting?,
        ..ContactTorques::default()
    };
    let law = match kind {
        keys::ROLLING => ContactLaw::Rolling {
            rolling_resistance,
            spin_resistance,
        },
        keys::SLIDING => {
            // One friction law: two would be two different tables.
            if args.len() != 1 {
                let which = if args.is_empty() {
                    "needs"
                } else {
                    "takes one"
                };
                ck.cx.error_spanned_by(
                    value,
                    format!(
                        "`{kind}` {which} friction: `{kind}({} = c)`, `{kind}({} = μ)`, `{kind}({} = μ)` or `{kind}({})`",
                        keys::VISCOUS,
                        keys::NORMAL_VISCOUS,
                        keys::COULOMB,
                        keys::FRICTIONLESS
                    ),
                );
                return None;
            }
            let viscous = coefficient(ck, keys::VISCOUS)?;
            let normal_viscous = coefficient(ck, keys::NORMAL_VISCOUS)?;
            let coulomb = coefficient(ck, keys::COULOMB)?;
            ContactLaw::Sliding(match (viscous, normal_viscous, coulomb) {
                (Some(c), _, _) => Friction::Viscous(c),
                (_, Some(mu), _) => Friction::NormalViscous(mu),
                (_, _, Some(mu)) => Friction::Coulomb(mu),
                _ => Friction::Frictionless,
            })
        }
        _ => {
            let Some(mu) = coefficient(ck, keys::MU)? else {
                ck.cx.error_spanned_by(
                    value,
                    format!(
                        "`{kind}` needs its friction coefficient: `{kind}({} = μ)`",
                        keys::MU
                    ),
                );
                return None;
            };
            torques.rolling_resistance = rolling_resistance;
            torques.spin_resistance = spin_resistance;
            ContactLaw::StickSlip { mu }
        }
    };
    Some((law, torques))
}

/// Why friction or resistance must not be negative.
const FEEDS_ENERGY: Option<&str> = Some("a negative one feeds energy in");
