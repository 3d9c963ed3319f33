//! Meaning of the `#[contact(...)]` settings: the surface and the law read from their call
//! forms against the tables in `keys.rs`, values with the value rules of `lang::values` in
//! the same arena, and the rules on the values that are literals (fields meet the same rules
//! at run time, in the generated `ContactDynamics::check_parameters`). One function per rule,
//! its reason in a comment.

use precess_core::contact::{
    ContactError, ContactLaw, ContactScene, ContactValues, Friction, Surface, check_contact_values,
};
use precess_core::sym::ExprId;
use syn::{Attribute, Expr, Ident};

use crate::lang::check::Checker;
use crate::lang::keys::{self, CONTACT_KEYS, LAWS, SURFACES};
use crate::lang::syntax::{Item, KeyValue, Parsed};
use crate::rigid::check::CheckedBody;

/// The checked `#[contact(...)]` settings.
pub struct ContactSettings {
    /// The surface the body touches the table with.
    pub surface: Surface,
    /// The contact law.
    pub law: ContactLaw,
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

/// One argument of a call form: `key = value`, or a bare word (`frictionless`).
enum Arg<'a> {
    Key(&'a Ident, &'a Expr),
    Flag(&'a Ident),
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
            Some(keys::GRAVITY) => {
                gravity = at_least_zero(
                    ck,
                    value,
                    "`gravity`",
                    "it is g along −z; one pulling up would lift the body off the table",
                );
            }
            _ => ck.cx.error_spanned_by(
                key,
                format!(
                    "unknown key `{key}` in {in_contact}: expected {}{}",
                    CONTACT_KEYS.join(", "),
                    keys::did_you_mean(&key.to_string(), CONTACT_KEYS.iter().copied())
                ),
            ),
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
    Some(Some(ContactSettings {
        surface: surface?,
        law: law?,
        gravity: gravity?,
    }))
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
        format!(
            "unknown key `{name}` in `#[{}]`: expected {}{}",
            keys::CONTACT,
            CONTACT_KEYS.join(", "),
            keys::did_you_mean(&name.to_string(), CONTACT_KEYS.iter().copied())
        )
    }
}

/// The surfaces as the messages list them: `sphere(radius, center), …`.
fn surface_list() -> String {
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
fn law_list() -> String {
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
fn read_surface(ck: &mut Checker, value: &Expr) -> Option<Surface> {
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
    let placement = |ck: &mut Checker, key: &str| match value_of(&args, key) {
        Some(v) => ck.vector(v),
        None => Some([ck.arena.zero(); 3]),
    };
    match kind {
        "sphere" | "disk_rim" => {
            let radius = positive(ck, value_of(&args, keys::RADIUS)?, &of(keys::RADIUS));
            let center = placement(ck, keys::SURFACE_CENTER);
            let (radius, center) = (radius?, center?);
            Some(if kind == "sphere" {
                Surface::Sphere { center, radius }
            } else {
                Surface::DiskRim { center, radius }
            })
        }
        "ellipsoid" => {
            let semi_axes =
                positive_vector(ck, value_of(&args, keys::SEMI_AXES)?, &of(keys::SEMI_AXES));
            let center = placement(ck, keys::SURFACE_CENTER);
            Some(Surface::Ellipsoid {
                center: center?,
                semi_axes: semi_axes?,
            })
        }
        "torus" => {
            let radius = positive(ck, value_of(&args, keys::RADIUS)?, &of(keys::RADIUS));
            let tube_value = value_of(&args, keys::TUBE)?;
            let tube = positive(ck, tube_value, &of(keys::TUBE));
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
                &of(keys::CURVATURE_RADIUS),
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
fn read_law(ck: &mut Checker, value: &Expr) -> Option<ContactLaw> {
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
    let coefficient = |ck: &mut Checker, key: &str| -> Option<Option<ExprId>> {
        match value_of(&args, key) {
            Some(v) => non_negative(ck, v, &format!("`{key}` of `{kind}`")).map(Some),
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
fn at_least_zero(ck: &mut Checker, value: &Expr, what: &str, why: &str) -> Option<ExprId> {
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

/// The centre of mass inside the surface, by the run-time rule of
/// [`check_contact_values`] (one rule for literals and fields), when the centre and the
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
    if let Err(e @ ContactError::CenterOutsideSurface { .. }) = check_contact_values(&values) {
        ck.cx.error_spanned_by(value, e);
    }
}
