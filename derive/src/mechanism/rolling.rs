//! Meaning of the rolling keys: a body's `rolls = disk(..)` or `rolls = sphere(..)` and the
//! mechanism's `up = ..` and `speeds = [..]`. What the derivation alone can tell (the number
//! of speeds the wheels leave free) is mapped to spanned errors by `expand/rolling.rs`.

use precess_core::mechanism::rolling::{RollingScene, RollingWheel, WheelSurface};
use precess_core::sym::ExprId;
use syn::{Expr, Ident};

use super::joint::path_ident;
use crate::lang::check::Checker;
use crate::lang::keys;
use crate::lang::syntax::KeyValue;
use crate::lang::units::Dim;

/// A body's rolling surface as read, with the tokens its errors are spanned on.
pub struct WheelSpec {
    /// The surface.
    pub surface: WheelSurface,
    /// The `rolls` key.
    pub key: Ident,
}

/// The rolling part of a checked mechanism.
pub struct CheckedRolling {
    /// The scene for the engine.
    pub scene: RollingScene,
    /// Each wheel's body name, in the order of `scene.wheels`.
    pub bodies: Vec<String>,
    /// The `speeds` value: the derivation's count of rows is known only after the check.
    pub speeds: Expr,
}

/// The rolling keys of `#[mechanism(...)]`, as written.
#[derive(Default)]
pub struct RollingSettings<'a> {
    /// `up = ..`.
    pub up: Option<&'a KeyValue>,
    /// `speeds = [..]`.
    pub speeds: Option<&'a KeyValue>,
    /// `route = ..`, refused beside rolling bodies.
    pub route: Option<&'a KeyValue>,
    /// `taylor = ..`, refused beside rolling bodies.
    pub taylor: Option<&'a KeyValue>,
}

impl Checker<'_> {
    /// `disk(radius = r, axle = y, at = [..])` or `sphere(radius = r, at = [..])`.
    pub(super) fn rolls(&mut self, e: &Expr) -> Option<WheelSurface> {
        let surfaces = || keys::ROLLING_SURFACES.iter().map(|s| s.0);
        let expected = "expected a rolling surface `disk(radius = .., axle = x|y|z|[..], at = [..])` or `sphere(radius = .., at = [..])`";
        let Expr::Call(call) = e else {
            self.cx.error_spanned_by(e, expected);
            return None;
        };
        let Some(name) = path_ident(&call.func) else {
            self.cx.error_spanned_by(e, expected);
            return None;
        };
        let written = name.to_string();
        let Some(&(kind, required, optional)) =
            keys::ROLLING_SURFACES.iter().find(|s| s.0 == written)
        else {
            self.cx.error_spanned_by(
                name,
                format!(
                    "unknown rolling surface `{written}`: {expected}{}",
                    keys::did_you_mean(&written, surfaces())
                ),
            );
            return None;
        };
        let allowed: Vec<&str> = required.iter().chain(optional).copied().collect();
        let mut given: Vec<(&Ident, &Expr)> = Vec::new();
        let mut ok = true;
        for arg in &call.args {
            let key = match arg {
                Expr::Assign(a) => path_ident(&a.left).map(|k| (k, &*a.right)),
                _ => None,
            };
            let Some((key, value)) = key else {
                self.cx.error_spanned_by(
                    arg,
                    format!(
                        "expected `key = value` in `{kind}(...)`: its keys are {}",
                        allowed.join(", ")
                    ),
                );
                ok = false;
                continue;
            };
            if !allowed.iter().any(|k| key == k) {
                self.cx.error_spanned_by(
                    key,
                    format!(
                        "unknown key `{key}` for the rolling `{kind}`: allowed keys are {}{}",
                        allowed.join(", "),
                        keys::did_you_mean(&key.to_string(), allowed.iter().copied())
                    ),
                );
                ok = false;
            } else if given.iter().any(|(g, _)| *g == key) {
                self.cx
                    .error_spanned_by(key, format!("duplicate key `{key}` in `{kind}`"));
                ok = false;
            } else {
                given.push((key, value));
            }
        }
        for &k in required {
            if !given.iter().any(|(g, _)| *g == k) {
                self.cx.error_spanned_by(
                    name,
                    format!("the rolling `{kind}` needs its `{k}`: {expected}"),
                );
                ok = false;
            }
        }
        if !ok {
            return None;
        }
        let value = |k: &str| given.iter().find(|(g, _)| *g == k).map(|(_, v)| *v);
        let radius = value(keys::RADIUS)
            .and_then(|v| self.expecting(Dim::LENGTH, keys::RADIUS, |ck| ck.rolling_radius(v)));
        let center = match value(keys::AT) {
            Some(v) => self.expecting(Dim::LENGTH, keys::AT, |ck| ck.vector(v)),
            None => Some([self.arena.zero(); 3]),
        };
        if kind == "sphere" {
            return Some(WheelSurface::Sphere {
                center: center?,
                radius: radius?,
            });
        }
        let axle = value(keys::AXLE).and_then(|v| self.joint_axis(v));
        Some(WheelSurface::Disk {
            center: center?,
            axle: axle?,
            radius: radius?,
        })
    }

    /// A radius: a literal must be positive (a field is checked at run time).
    fn rolling_radius(&mut self, e: &Expr) -> Option<ExprId> {
        let r = self.scalar(e)?;
        if self.arena.free_symbols(r).is_empty() {
            let value = self.arena.eval(r, &[]);
            if value.is_nan() || value <= 0.0 {
                self.cx
                    .error_spanned_by(e, format!("a rolling radius must be positive, got {value}"));
                return None;
            }
        }
        Some(r)
    }

    /// `up = x`, `-x`, …, `-z`: the floor's upward normal.
    pub(super) fn floor_up(&mut self, e: &Expr) -> Option<[ExprId; 3]> {
        let (inner, negated) = match e {
            Expr::Unary(u) if matches!(u.op, syn::UnOp::Neg(_)) => (&*u.expr, true),
            _ => (e, false),
        };
        let k = match path_ident(inner).map(Ident::to_string).as_deref() {
            Some("x") => 0,
            Some("y") => 1,
            Some("z") => 2,
            _ => {
                self.cx.error_spanned_by(
                    e,
                    format!(
                        "`{}` is the floor's upward normal, a signed ground axis: expected `x`, `-x`, `y`, `-y`, `z` or `-z`",
                        keys::UP
                    ),
                );
                return None;
            }
        };
        let mut up = [self.arena.zero(); 3];
        up[k] = self.arena.integer(if negated { -1 } else { 1 });
        Some(up)
    }

    /// `speeds = [a, b, ..]`: coordinates, each once.
    pub(super) fn speeds(&mut self, e: &Expr, coordinates: &[Ident]) -> Option<Vec<String>> {
        let Expr::Array(list) = e else {
            self.cx.error_spanned_by(
                e,
                format!(
                    "expected the free speeds' coordinates, `{} = [a, b]`",
                    keys::SPEEDS
                ),
            );
            return None;
        };
        let names: Vec<String> = coordinates.iter().map(Ident::to_string).collect();
        let mut out: Vec<String> = Vec::new();
        let mut ok = true;
        for item in &list.elems {
            let Some(name) = path_ident(item) else {
                self.cx
                    .error_spanned_by(item, "expected the name of a coordinate, such as `phi`");
                ok = false;
                continue;
            };
            let name = name.to_string();
            if out.contains(&name) {
                self.cx.error_spanned_by(
                    item,
                    format!("free speed `{name}` is named twice: name each coordinate once"),
                );
                ok = false;
            } else if !names.contains(&name) {
                self.cx.error_spanned_by(
                    item,
                    format!(
                        "free speed `{name}` is not a coordinate: the coordinates are {}{}",
                        names.join(", "),
                        keys::did_you_mean(&name, names.iter().map(String::as_str))
                    ),
                );
                ok = false;
            } else {
                out.push(name);
            }
        }
        ok.then_some(out)
    }
}

/// The rolling scene of a mechanism whose bodies `wheels` (index in the bodies, name,
/// surface) roll, or `None` with the errors recorded: `up` and `speeds` go with rolling
/// bodies and only with them, and `route` and `taylor` do not.
pub(super) fn rolling(
    ck: &mut Checker,
    settings: &RollingSettings,
    wheels: Vec<(usize, String, WheelSpec)>,
    coordinates: &[Ident],
) -> Option<Option<CheckedRolling>> {
    let errors_before = ck.cx.error_count();
    if wheels.is_empty() {
        for kv in [settings.up, settings.speeds].into_iter().flatten() {
            ck.cx.error_spanned_by(
                &kv.key,
                format!(
                    "`{}` is a setting of a mechanism whose bodies roll on the floor, and no body declares `{} = disk(..)` or `{} = sphere(..)`",
                    kv.key,
                    keys::ROLLS,
                    keys::ROLLS
                ),
            );
        }
        return (ck.cx.error_count() == errors_before).then_some(None);
    }
    for kv in [settings.route, settings.taylor].into_iter().flatten() {
        ck.cx.error_spanned_by(
            &kv.key,
            format!(
                "`{}` is not supported for a mechanism with rolling bodies: its equations are finished by a projection at each evaluation; remove `{}`",
                kv.key, kv.key
            ),
        );
    }
    // The struct's consts are named after the coordinates, beside `STATE` and `SPEEDS`.
    for c in coordinates {
        let upper = c.to_string().to_uppercase();
        if upper == "STATE" || upper == "SPEEDS" {
            ck.cx.error_spanned_by(
                c,
                format!(
                    "a rolling mechanism's struct gets the consts `STATE` and `SPEEDS`, so a coordinate may not be named `{c}`: rename it"
                ),
            );
        }
    }
    let (first_body, first_key) = match wheels.first() {
        Some((_, name, spec)) => (name.clone(), spec.key.clone()),
        None => return Some(None),
    };
    let missing = |what: &str, example: &str| {
        format!(
            "body `{first_body}` rolls: the mechanism needs {what}: add `{example}` to `#[{}(...)]`",
            keys::MECHANISM
        )
    };
    let up = match settings.up {
        Some(kv) => ck.floor_up(&kv.value),
        None => {
            ck.cx
                .error_spanned_by(&first_key, missing("the floor's upward normal", "up = z"));
            None
        }
    };
    let speeds = match settings.speeds {
        Some(kv) => ck
            .speeds(&kv.value, coordinates)
            .map(|s| (s, kv.value.clone())),
        None => {
            ck.cx.error_spanned_by(
                &first_key,
                missing(
                    "the coordinates whose rates are its free speeds",
                    "speeds = [a, b]",
                ),
            );
            None
        }
    };
    if ck.cx.error_count() > errors_before {
        return None;
    }
    let (up, (speeds, speeds_expr)) = (up?, speeds?);
    let bodies = wheels.iter().map(|(_, name, _)| name.clone()).collect();
    let wheels = wheels
        .into_iter()
        .map(|(body, _, spec)| RollingWheel {
            body,
            surface: spec.surface,
        })
        .collect();
    Some(Some(CheckedRolling {
        scene: RollingScene { up, wheels, speeds },
        bodies,
        speeds: speeds_expr,
    }))
}
