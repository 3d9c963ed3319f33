//! The call forms of `#[contact]`'s values, `name` or `name(key = value, ...)`: the
//! surface and the law read against the tables in `keys.rs`, each dimension and coefficient
//! with the rule it must meet where it is a literal (fields meet the same rules at run time).

use precess_core::contact::{ContactLaw, Friction, Surface};
use precess_core::sym::ExprId;
use syn::{Expr, Ident};

use crate::lang::check::Checker;
use crate::lang::keys::{self, LAWS, SURFACES};
use crate::lang::units::Dim;

/// One argument of a call form: `key = value`, or a bare word (`frictionless`).
enum Arg<'a> {
    Key(&'a Ident, &'a Expr),
    Flag(&'a Ident),
}

/// The surfaces as the messages list them: `sphere(radius, center), …`.
pub fn surface_list() -> String {
    let forms: Vec<String> = SURFACES
        .iter()
        .map(|(name, required, optional)| {
            let keys: Vec<&str> = required.iter().chain(*optional).copied().collect();
            format!("`{name}({})`", keys.join(", "))
        })
        .collect();
    forms.join(", ")
}

/// The laws as the messages list them.
pub fn law_list() -> String {
    format!(
        "`{r}`, `{r}({rr} = c, {sr} = c)`, `{s}({v} = c)`, `{s}({c} = μ)`, `{s}({f})` or `{ss}({mu} = μ)`",
        r = keys::ROLLING,
        rr = keys::ROLLING_RESISTANCE,
        sr = keys::SPIN_RESISTANCE,
        s = keys::SLIDING,
        v = keys::VISCOUS,
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
        let Some(&k) = allowed.iter().find(|&&k| key == k) else {
            ck.cx.error_spanned_by(
                key,
                format!(
                    "unknown key `{key}` for `{name}`: allowed keys are {}{}",
                    allowed.join(", "),
                    keys::did_you_mean(&key.to_string(), allowed.iter().copied())
                ),
            );
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

/// `surface = name(key = value, ...)`, one of [`SURFACES`].
pub fn read_surface(ck: &mut Checker, value: &Expr) -> Option<Surface> {
    let what = format!("a surface: {}", surface_list());
    let (name, args) = call_form(ck, value, &what)?;
    let Some(&(kind, required, optional)) = SURFACES.iter().find(|(s, _, _)| name == s) else {
        let names = SURFACES.iter().map(|(s, _, _)| *s);
        ck.cx.error_spanned_by(
            name,
            format!(
                "unknown surface `{name}`: expected {}{}",
                surface_list(),
                keys::did_you_mean(&name.to_string(), names)
            ),
        );
        return None;
    };
    let allowed: Vec<&'static str> = required.iter().chain(optional).copied().collect();
    let args = keyed(ck, name, &args, &allowed)?;
    // Every required dimension: a surface without its size has no support point.
    let mut missing = false;
    for key in required {
        if value_of(&args, key).is_none() {
            ck.cx
                .error_spanned_by(value, format!("`{kind}` needs `{key} = ...`"));
            missing = true;
        }
    }
    if missing {
        return None;
    }
    let of = |key: &str| format!("`{key}` of `{kind}`");
    let placement = |ck: &mut Checker, key: &'static str| match value_of(&args, key) {
        Some(v) => ck.expecting(Dim::LENGTH, key, |ck| ck.vector(v)),
        None => Some([ck.arena.zero(); 3]),
    };
    // Every size of a surface is a length.
    let positive = |ck: &mut Checker, value: &Expr, key: &'static str| {
        ck.expecting(Dim::LENGTH, key, |ck| positive(ck, value, &of(key)))
    };
    match kind {
        "sphere" | "disk_rim" => {
            let radius = positive(ck, value_of(&args, keys::RADIUS)?, keys::RADIUS);
            let center = placement(ck, keys::SURFACE_CENTER);
            let (radius, center) = (radius?, center?);
            Some(if kind == "sphere" {
                Surface::Sphere { center, radius }
            } else {
                Surface::DiskRim { center, radius }
            })
        }
        "ellipsoid" => {
            let semi_axes = ck.expecting(Dim::LENGTH, keys::SEMI_AXES, |ck| {
                positive_vector(ck, value_of(&args, keys::SEMI_AXES)?, &of(keys::SEMI_AXES))
            });
            let center = placement(ck, keys::SURFACE_CENTER);
            Some(Surface::Ellipsoid {
                center: center?,
                semi_axes: semi_axes?,
            })
        }
        "torus" => {
            let radius = positive(ck, value_of(&args, keys::RADIUS)?, keys::RADIUS);
            let tube_value = value_of(&args, keys::TUBE)?;
            let tube = positive(ck, tube_value, keys::TUBE);
            let center = placement(ck, keys::SURFACE_CENTER);
            let (radius, tube, center) = (radius?, tube?, center?);
            tube_within(ck, tube_value, radius, tube)?;
            Some(Surface::Torus {
                center,
                radius,
                tube,
            })
        }
        _ => {
            let curvature_radius = positive(
                ck,
                value_of(&args, keys::CURVATURE_RADIUS)?,
                keys::CURVATURE_RADIUS,
            );
            let vertex = placement(ck, keys::VERTEX);
            Some(Surface::Paraboloid {
                vertex: vertex?,
                curvature_radius: curvature_radius?,
            })
        }
    }
}

/// A torus's tube no thicker than its radius: with r > R the tube crosses the axis and the
/// outer half's support map is no longer the convex surface's (the inner half would touch
/// the table first).
fn tube_within(ck: &mut Checker, tube_value: &Expr, radius: ExprId, tube: ExprId) -> Option<()> {
    let excess = ck.arena.sub(tube, radius);
    if let Some(r) = ck.arena.as_rational(excess)
        && !r.is_negative()
        && !r.is_zero()
    {
        let (t, big) = (ck.arena.eval(tube, &[]), ck.arena.eval(radius, &[]));
        ck.cx.error_spanned_by(
            tube_value,
            format!("`{}` of `torus` is {t}, larger than its `{}` {big}: the surface would not be convex; the tube must be at most the radius", keys::TUBE, keys::RADIUS),
        );
        return None;
    }
    Some(())
}

/// `law = name` or `law = name(key = value, ...)`, one of [`LAWS`].
pub fn read_law(ck: &mut Checker, value: &Expr) -> Option<ContactLaw> {
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
            _ => (
                Dim::NONE,
                Some("a pure number (a friction coefficient has no units)"),
            ),
        };
        match value_of(&args, key) {
            Some(v) => ck
                .expecting_as(dim, what, key, |ck| {
                    non_negative(ck, v, &format!("`{key}` of `{kind}`"))
                })
                .map(Some),
            None => Some(None),
        }
    };
    match kind {
        keys::ROLLING => {
            let rolling_resistance = coefficient(ck, keys::ROLLING_RESISTANCE);
            let spin_resistance = coefficient(ck, keys::SPIN_RESISTANCE);
            Some(ContactLaw::Rolling {
                rolling_resistance: rolling_resistance?,
                spin_resistance: spin_resistance?,
            })
        }
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
                        "`{kind}` {which} friction: `{kind}({} = c)`, `{kind}({} = μ)` or `{kind}({})`",
                        keys::VISCOUS,
                        keys::COULOMB,
                        keys::FRICTIONLESS
                    ),
                );
                return None;
            }
            let viscous = coefficient(ck, keys::VISCOUS)?;
            let coulomb = coefficient(ck, keys::COULOMB)?;
            Some(ContactLaw::Sliding(match (viscous, coulomb) {
                (Some(c), _) => Friction::Viscous(c),
                (_, Some(mu)) => Friction::Coulomb(mu),
                _ => Friction::Frictionless,
            }))
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
            Some(ContactLaw::StickSlip { mu })
        }
    }
}

/// A scalar that must be positive where it is a literal: a size, gravity.
fn positive(ck: &mut Checker, value: &Expr, what: &str) -> Option<ExprId> {
    let v = ck.scalar(value)?;
    if let Some(r) = ck.arena.as_rational(v)
        && (r.is_negative() || r.is_zero())
    {
        ck.cx.error_spanned_by(
            value,
            format!("{what} is {}: it must be positive", r.to_f64()),
        );
        return None;
    }
    Some(v)
}

/// `[a, b, c]`, each positive where it is a literal, the error on the element.
fn positive_vector(ck: &mut Checker, value: &Expr, what: &str) -> Option<[ExprId; 3]> {
    let v = ck.vector(value)?;
    let mut ok = true;
    if let Expr::Array(a) = value {
        for (k, (e, tokens)) in v.iter().zip(&a.elems).enumerate() {
            if let Some(r) = ck.arena.as_rational(*e)
                && (r.is_negative() || r.is_zero())
            {
                ck.cx.error_spanned_by(
                    tokens,
                    format!(
                        "{what} has {} in place {}: each must be positive",
                        r.to_f64(),
                        k + 1
                    ),
                );
                ok = false;
            }
        }
    }
    ok.then_some(v)
}

/// A coefficient that must not be negative where it is a literal: negative friction or
/// resistance feeds energy in.
fn non_negative(ck: &mut Checker, value: &Expr, what: &str) -> Option<ExprId> {
    at_least_zero(ck, value, what, "a negative one feeds energy in")
}

/// A scalar that must not be negative where it is a literal, `why` said in the error.
pub fn at_least_zero(ck: &mut Checker, value: &Expr, what: &str, why: &str) -> Option<ExprId> {
    let v = ck.scalar(value)?;
    if let Some(r) = ck.arena.as_rational(v)
        && r.is_negative()
    {
        ck.cx.error_spanned_by(
            value,
            format!(
                "{what} is {}: it must be zero or positive ({why})",
                r.to_f64()
            ),
        );
        return None;
    }
    Some(v)
}
