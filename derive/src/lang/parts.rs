//! The part language, shared by `#[rigid(...)]` and a mechanism body's `parts(...)`: each
//! part `name(key = value, ...)` against the table in `keys.rs`, its values read by the
//! checker into the arena. The rules on the whole body are the attribute's own.

use precess_core::body::{About, Axis, BodyError, ORTHONORMAL_TOLERANCE, Part, Shape};
use precess_core::sym::ExprId;
use proc_macro2::TokenStream;
use quote::ToTokens;
use syn::parse::ParseStream;
use syn::{Expr, Ident};

use super::check::Checker;
use super::keys::{self, PartKind, part_list};
use super::syntax::{Item, KeyValue};

/// The tokens of each key's value in one part.
pub(crate) type KeySpans = Vec<(&'static str, TokenStream)>;

/// What a rejected rotation is told, without the part's number (the span shows the part).
pub fn rotation_message(e: &BodyError) -> String {
    match *e {
        BodyError::ZeroRotationAxis { axis, .. } => format!(
            "the rotation axis {axis:?} has no direction: give a non-zero axis such as [0.0, 0.0, 1.0]"
        ),
        BodyError::NotOrthonormal { deviation, .. } => format!(
            "the matrix is not a rotation: its columns are not orthonormal (|RᵀR − E| reaches {deviation:.1e}; at most {ORTHONORMAL_TOLERANCE:e} is allowed)"
        ),
        BodyError::ImproperRotation { determinant, .. } => format!(
            "the matrix is a reflection (det = {determinant}), not a rotation: a rotation has det = +1; negate one column, or swap two"
        ),
        _ => e.to_string(),
    }
}

impl Checker<'_> {
    /// One part: known name, known and unique keys, every required key, then its values.
    pub(crate) fn part(
        &mut self,
        name: &Ident,
        keys: &[KeyValue],
    ) -> Option<(Part<ExprId>, KeySpans)> {
        let Some(table) = keys::find_part(&name.to_string()) else {
            self.cx.error_spanned_by(
                name,
                format!(
                    "unknown part `{name}`: expected one of {}{}",
                    part_list(),
                    keys::did_you_mean_part(&name.to_string())
                ),
            );
            return None;
        };
        let mut given: Vec<(&'static str, &KeyValue)> = Vec::new();
        let mut ok = true;
        // Keys a misspelling was taken for: their absence is the same mistake, said once.
        let mut suggested: Vec<&'static str> = Vec::new();
        for kv in keys {
            let written = kv.key.to_string();
            let Some(key) = table.key(&written) else {
                let allowed: Vec<&str> = table.allowed().collect();
                // The explicit body's alias is a key one may have meant too.
                let alias = (table.kind == keys::PartKind::Explicit).then_some(keys::CENTER);
                let known = allowed.iter().copied().chain(alias);
                let near = keys::closest(&written, known.clone());
                suggested.extend(near.and_then(|k| table.key(k)));
                self.cx.error_spanned_by(
                    &kv.key,
                    format!(
                        "unknown key `{}` for `{}`: allowed keys are {}{}",
                        kv.key,
                        table.name,
                        allowed.join(", "),
                        keys::did_you_mean(&written, known)
                    ),
                );
                ok = false;
                continue;
            };
            // Each key once: two values for one quantity are ambiguous.
            if given.iter().any(|(g, _)| *g == key) {
                self.cx.error_spanned_by(
                    &kv.key,
                    format!(
                        "duplicate key `{}` in `{}`: give each key once",
                        kv.key, table.name
                    ),
                );
                ok = false;
                continue;
            }
            given.push((key, kv));
        }
        // Every required key: a solid needs all its dimensions.
        let missing: Vec<String> = table
            .required
            .iter()
            .filter(|r| !given.iter().any(|(g, _)| g == *r) && !suggested.contains(r))
            .map(|m| format!("`{m}`"))
            .collect();
        if !missing.is_empty() {
            self.cx.error_spanned_by(
                name,
                format!(
                    "`{name}` is missing {}: it needs {}",
                    missing.join(", "),
                    table.required.join(", ")
                ),
            );
            ok = false;
        }
        if !ok {
            return None;
        }
        let spans = given
            .iter()
            .map(|(k, kv)| (*k, kv.value.to_token_stream()))
            .collect();
        let value = |k: &str| given.iter().find(|(g, _)| *g == k).map(|(_, kv)| &kv.value);
        // Every value is read, so each of its errors is reported, before any is given up on.
        let shape = self.shape(table.kind, &value);
        let at = match value(keys::AT) {
            Some(e) => self.vector(e),
            None => Some([self.arena.zero(); 3]),
        };
        let orientation = match value(keys::ROTATE) {
            Some(e) => self.orientation(e, table.name).map(Some),
            None => Some(None),
        };
        let (shape, at, orientation) = (shape?, at?, orientation?);
        Some((
            Part {
                shape,
                at,
                orientation,
            },
            spans,
        ))
    }

    /// The shape of `kind` from its key values (all required keys are present).
    fn shape<'e>(
        &mut self,
        kind: PartKind,
        value: &dyn Fn(&str) -> Option<&'e Expr>,
    ) -> Option<Shape<ExprId>> {
        let mut scalar = |k: &str| value(k).and_then(|e| self.scalar(e));
        let (mass, radius) = (scalar(keys::MASS), scalar(keys::RADIUS));
        let (length, height) = (scalar(keys::LENGTH), scalar(keys::HEIGHT));
        let (inner, outer) = (scalar(keys::INNER), scalar(keys::OUTER));
        let (axis, reversed) = match value(keys::AXIS) {
            Some(e) => self.axis(e)?,
            None => (Axis::Z, false),
        };
        let mass = mass?;
        Some(match kind {
            PartKind::Particle => Shape::Particle { mass },
            PartKind::Sphere => Shape::Sphere {
                mass,
                radius: radius?,
            },
            PartKind::Shell => Shape::Shell {
                mass,
                radius: radius?,
            },
            PartKind::Cuboid => Shape::Cuboid {
                mass,
                size: self.vector(value(keys::SIZE)?)?,
            },
            PartKind::Ellipsoid => Shape::Ellipsoid {
                mass,
                semi_axes: self.vector(value(keys::SEMI_AXES)?)?,
            },
            PartKind::Cylinder => Shape::Cylinder {
                mass,
                radius: radius?,
                length: length?,
                axis,
            },
            PartKind::Tube => Shape::Tube {
                mass,
                inner: inner?,
                outer: outer?,
                length: length?,
                axis,
            },
            PartKind::Disk => Shape::Disk {
                mass,
                radius: radius?,
                axis,
            },
            PartKind::Ring => Shape::Ring {
                mass,
                radius: radius?,
                axis,
            },
            PartKind::Rod => Shape::Rod {
                mass,
                length: length?,
                axis,
            },
            PartKind::Cone => Shape::Cone {
                mass,
                radius: radius?,
                height: height?,
                axis,
                reversed,
            },
            PartKind::Explicit => {
                let about = match value(keys::ABOUT) {
                    Some(e) => self.about(e)?,
                    None => About::Center,
                };
                Shape::Explicit {
                    mass,
                    inertia: self.tensor(value(keys::INERTIA)?)?,
                    about,
                }
            }
        })
    }
}

/// A list of parts, `part(key = value, ...), ...` (a mechanism body's `parts(...)`).
pub fn parse_parts(input: ParseStream) -> syn::Result<Vec<Item>> {
    Item::parse_list(input, |name| {
        format!(
            "expected a part `{name}(key = value, ...)`: {}",
            part_list()
        )
    })
}
