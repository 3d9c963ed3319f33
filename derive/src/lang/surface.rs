//! The one reader of a rolling surface, `name(key = value, ...)`: a body's on a table
//! (`#[contact(surface = ..)]`) and a mechanism's wheel (`rolls = ..`) are one geometry,
//! precess-core's `rigid::Surface`, read here against one table ([`keys::SURFACES`]), each
//! size with one rule where it is a literal (fields meet the same rules at run time).
//!
//! Where each is written decides what it may be: a body on a table touches it with any of
//! the five surfaces, their axes along description axes; a wheel is a disk rim (`disk_rim`, or
//! `disk` as it was first spelt) about its `axle`, or a sphere. The placement is `center`
//! (`vertex` for a paraboloid), or `at` as the body language writes it, in both.

use precess_core::rigid::Surface;
use precess_core::sym::ExprId;
use syn::{Expr, Ident};

use super::check::Checker;
use super::keys::{self, SURFACES};
use super::units::Dim;

/// Where a surface is written, which decides the surfaces allowed and their keys.
#[derive(Clone, Copy)]
pub enum Place {
    /// `#[contact(surface = ..)]`: any surface, its axes along description axes.
    Table,
    /// `rolls = ..` on a mechanism's body: a disk rim about its axle, or a sphere. `axle`
    /// reads the axle (the mechanism's axis language).
    Wheel {
        /// The reader of `axle = ..`.
        axle: fn(&mut Checker, &Expr) -> Option<[ExprId; 3]>,
    },
}

impl Place {
    /// The surfaces allowed here, by their names in [`SURFACES`].
    fn allows(self, name: &str) -> bool {
        match self {
            Place::Table => true,
            Place::Wheel { .. } => keys::WHEEL_SURFACES.contains(&name),
        }
    }

    /// The keys of `name` here: its required ones, then its optional ones.
    fn keys(self, name: &str) -> (Vec<&'static str>, Vec<&'static str>) {
        let Some(&(_, required, optional)) = SURFACES.iter().find(|s| s.0 == name) else {
            return (Vec::new(), Vec::new());
        };
        let mut required = required.to_vec();
        let mut optional = optional.to_vec();
        if let Place::Wheel { .. } = self
            && name == keys::DISK_RIM
        {
            required.push(keys::AXLE);
        }
        optional.push(keys::AT);
        (required, optional)
    }

    /// What a surface is called in the messages.
    fn what(self) -> &'static str {
        match self {
            Place::Table => "surface",
            Place::Wheel { .. } => "rolling surface",
        }
    }
}

/// The surfaces allowed at `place` as the messages list them: `sphere(radius, center)`, ….
pub fn surface_list(place: Place) -> String {
    let forms: Vec<String> = SURFACES
        .iter()
        .filter(|(name, _, _)| place.allows(name))
        .map(|(name, _, _)| {
            let (required, optional) = place.keys(name);
            let keys: Vec<&str> = required.iter().chain(&optional).copied().collect();
            format!("`{name}({})`", keys.join(", "))
        })
        .collect();
    let synonym = match place {
        Place::Table => "",
        Place::Wheel { .. } => " (or `disk(..)`, the same rim)",
    };
    format!("{}{synonym}", forms.join(", "))
}

/// A surface as read: the shared surface and, for a wheel's disk rim, its axle.
pub struct ReadSurface {
    /// The surface, placed in description (body) axes.
    pub surface: Surface,
    /// A wheel's axle (body axes, not necessarily a unit vector).
    pub axle: Option<[ExprId; 3]>,
}

/// `name(key = value, ...)`, one of the surfaces allowed at `place`. `None` after an error
/// (recorded, spanned on the offending tokens).
pub fn read_surface(ck: &mut Checker, value: &Expr, place: Place) -> Option<ReadSurface> {
    let what = place.what();
    let expected = || format!("expected a {what}: {}", surface_list(place));
    let (func, args): (&Expr, Vec<&Expr>) = match value {
        Expr::Call(call) => (&call.func, call.args.iter().collect()),
        Expr::Path(_) => (value, Vec::new()),
        _ => {
            ck.cx.error_spanned_by(value, expected());
            return None;
        }
    };
    let Some(name) = path_ident(func) else {
        ck.cx.error_spanned_by(value, expected());
        return None;
    };
    let written = name.to_string();
    // `disk` is how a wheel's rim was first spelt: the same surface.
    let kind = match written.as_str() {
        keys::DISK if matches!(place, Place::Wheel { .. }) => keys::DISK_RIM,
        other => other,
    };
    if !place.allows(kind) || !SURFACES.iter().any(|s| s.0 == kind) {
        let names = SURFACES.iter().map(|s| s.0).filter(|s| place.allows(s));
        let elsewhere = match place {
            Place::Wheel { .. } if SURFACES.iter().any(|s| s.0 == kind) => {
                format!(" (`{kind}` is a surface of a body on a table, not of a wheel)")
            }
            _ => String::new(),
        };
        ck.cx.error_spanned_by(
            name,
            format!(
                "unknown {what} `{written}`{elsewhere}: expected {}{}",
                surface_list(place),
                keys::did_you_mean(&written, names)
            ),
        );
        return None;
    }
    let (required, optional) = place.keys(kind);
    let allowed: Vec<&str> = required.iter().chain(&optional).copied().collect();
    let mut given: Vec<(&'static str, &Ident, &Expr)> = Vec::new();
    let mut ok = true;
    for arg in args {
        let Some((key, v)) = (match arg {
            Expr::Assign(a) => path_ident(&a.left).map(|k| (k, &*a.right)),
            _ => None,
        }) else {
            ck.cx.error_spanned_by(
                arg,
                format!(
                    "expected `key = value` in `{written}(...)`: its keys are {}",
                    allowed.join(", ")
                ),
            );
            ok = false;
            continue;
        };
        let Some(k) = keys::known_key(ck.cx, key, &format!("for `{written}`"), &allowed) else {
            ok = false;
            continue;
        };
        // Each key once, and one placement: two radii or two centres would be ambiguous.
        let placement = |k: &str| k == keys::AT || !required.contains(&k) && k != keys::AXLE;
        if let Some((seen, _, _)) = given
            .iter()
            .find(|(g, _, _)| *g == k || placement(g) && placement(k))
        {
            let msg = if *seen == k {
                format!("duplicate key `{key}` in `{written}`")
            } else {
                format!("`{key}` places `{written}` again: `{seen}` already did; keep one")
            };
            ck.cx.error_spanned_by(key, msg);
            ok = false;
            continue;
        }
        given.push((k, key, v));
    }
    // A bad key is told alone: the required keys it may have misspelt are not missing too.
    if !ok {
        return None;
    }
    // Every required key: a surface without its size has no support point.
    for key in &required {
        if !given.iter().any(|(g, _, _)| g == key) {
            ck.cx.error_spanned_by(
                value,
                format!(
                    "`{written}` needs `{key} = ...`: its keys are {}",
                    allowed.join(", ")
                ),
            );
            ok = false;
        }
    }
    if !ok {
        return None;
    }
    let value_of = |key: &str| given.iter().find(|(g, _, _)| *g == key).map(|(_, _, v)| *v);
    let placement = given
        .iter()
        .find(|(g, _, _)| optional.contains(g))
        .map(|(g, _, v)| (*g, *v));
    let place_at = match placement {
        Some((key, v)) => ck.expecting(Dim::LENGTH, key, |ck| ck.vector(v))?,
        None => [ck.arena.zero(); 3],
    };
    let of = |key: &str| format!("`{key}` of `{written}`");
    let length = |ck: &mut Checker, key: &'static str| -> Option<ExprId> {
        let v = value_of(key)?;
        ck.expecting(Dim::LENGTH, key, |ck| ck.positive(v, &of(key), None))
    };
    let surface = match kind {
        "sphere" | keys::DISK_RIM => {
            let radius = length(ck, keys::RADIUS)?;
            if kind == "sphere" {
                Surface::Sphere {
                    center: place_at,
                    radius,
                }
            } else {
                Surface::DiskRim {
                    center: place_at,
                    radius,
                }
            }
        }
        "ellipsoid" => {
            let v = value_of(keys::SEMI_AXES)?;
            let semi_axes = ck.expecting(Dim::LENGTH, keys::SEMI_AXES, |ck| {
                ck.positive_vector(v, &of(keys::SEMI_AXES))
            })?;
            Surface::Ellipsoid {
                center: place_at,
                semi_axes,
            }
        }
        "torus" => {
            let radius = length(ck, keys::RADIUS);
            let tube = length(ck, keys::TUBE);
            let (radius, tube) = (radius?, tube?);
            tube_within(ck, value_of(keys::TUBE)?, radius, tube)?;
            Surface::Torus {
                center: place_at,
                radius,
                tube,
            }
        }
        _ => Surface::Paraboloid {
            vertex: place_at,
            curvature_radius: length(ck, keys::CURVATURE_RADIUS)?,
        },
    };
    let axle = match (place, value_of(keys::AXLE)) {
        (Place::Wheel { axle }, Some(v)) => Some(axle(ck, v)?),
        _ => None,
    };
    Some(ReadSurface { surface, axle })
}

/// The single identifier a path expression is, if it is one.
fn path_ident(e: &Expr) -> Option<&Ident> {
    match e {
        Expr::Path(p) if p.qself.is_none() => p.path.get_ident(),
        _ => None,
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
