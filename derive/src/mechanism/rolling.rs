//! Meaning of the rolling keys: a body's `rolls = disk_rim(..)` or `rolls = sphere(..)` (read
//! by `lang::surface`, the reader `#[contact(surface = ..)]` shares) and the
//! mechanism's `up = ..` and `speeds = [..]`. What the derivation alone can tell (the number
//! of speeds the wheels leave free) is mapped to spanned errors by `expand/rolling.rs`.

use precess_core::mechanism::rolling::{RollingScene, RollingWheel, WheelSurface};
use precess_core::rigid::Surface;
use precess_core::sym::ExprId;
use syn::{Expr, Ident};

use super::joint::path_ident;
use crate::lang::check::Checker;
use crate::lang::keys;
use crate::lang::surface::{Place, read_surface};
use crate::lang::syntax::KeyValue;

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
    /// `disk_rim(radius = r, axle = y, at = [..])` (or `disk(..)`) or
    /// `sphere(radius = r, at = [..])`, read by the one reader of rolling surfaces: the
    /// surface of a body on a table, about the wheel's axle.
    pub(super) fn rolls(&mut self, e: &Expr) -> Option<WheelSurface> {
        let place = Place::Wheel {
            axle: |ck, e| ck.joint_axis(e),
        };
        let read = read_surface(self, e, place)?;
        match (read.surface, read.axle) {
            (Surface::DiskRim { center, radius }, Some(axle)) => Some(WheelSurface::Disk {
                center,
                axle,
                radius,
            }),
            (Surface::Sphere { center, radius }, _) => {
                Some(WheelSurface::Sphere { center, radius })
            }
            // The reader allows a wheel nothing else, and a disk rim not without its axle.
            _ => None,
        }
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
                    "`{}` is a setting of a mechanism whose bodies roll on the floor, and no body declares `{} = disk_rim(..)` or `{} = sphere(..)`",
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
