//! The part language, shared by `#[rigid(...)]` and a mechanism body's `parts(...)`: each
//! part `name(key = value, ...)` against the table in `keys.rs`, its values read by the
//! checker into the arena. The rules on the whole body are the attribute's own.

use precess_core::body::{About, Axis, BodyError, ORTHONORMAL_TOLERANCE, Part, Shape};
use precess_core::sym::{ExprId, Rational};
use proc_macro2::TokenStream;
use quote::ToTokens;
use syn::parse::ParseStream;
use syn::{Expr, Ident};

use super::check::Checker;
use super::keys::{self, PartKeys, PartKind, part_list};
use super::syntax::{Item, KeyValue};
use super::units::Dim;

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

/// Why the part takes no density, if it takes none: it has no volume.
fn no_volume(table: &PartKeys) -> Option<&'static str> {
    match table.kind {
        _ if table.solid => None,
        PartKind::Particle => Some("a particle is a point: it has no volume"),
        PartKind::Shell | PartKind::Disk | PartKind::Ring | PartKind::Rod => {
            Some("it is thin: its mass lies on a surface or a line, with no volume")
        }
        _ => Some("it is given by its mass properties, with no shape to take a volume of"),
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
            if let (keys::DENSITY, Some(why)) = (written.as_str(), no_volume(table)) {
                self.cx.error_spanned_by(
                    &kv.key,
                    format!(
                        "`{}` takes no `density`: {why}; give its `mass`",
                        table.name
                    ),
                );
                // Its mass is what is missing: said here, not again.
                suggested.push(keys::MASS);
                ok = false;
                continue;
            }
            let Some(key) = table.key(&written) else {
                // The explicit body's alias is a key one may have meant too.
                let alias = (table.kind == keys::PartKind::Explicit).then_some(keys::CENTER);
                let near = keys::closest(&written, table.allowed().chain(alias));
                suggested.extend(near.and_then(|k| table.key(k)));
                self.cx
                    .error_spanned_by(&kv.key, table.unknown_key(&written));
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
        // A density stands for the mass: both would be two values of one quantity.
        let has = |k: &str| given.iter().any(|(g, _)| *g == k);
        if has(keys::MASS)
            && let Some((_, kv)) = given.iter().find(|(g, _)| *g == keys::DENSITY)
        {
            self.cx.error_spanned_by(
                &kv.key,
                format!(
                    "`{}` takes `mass` or `density`, not both: its mass is density × volume",
                    table.name
                ),
            );
            ok = false;
        }
        if has(keys::DENSITY) {
            suggested.push(keys::MASS);
        }
        // Every required key: a solid needs all its dimensions.
        let missing: Vec<String> = table
            .required
            .iter()
            .filter(|r| !has(r) && !suggested.contains(r))
            .map(|m| format!("`{m}`"))
            .collect();
        if !missing.is_empty() {
            let needs: Vec<String> = table
                .required
                .iter()
                .map(|&k| match k {
                    keys::MASS if table.solid => "mass (or density)".to_owned(),
                    k => k.to_owned(),
                })
                .collect();
            self.cx.error_spanned_by(
                name,
                format!(
                    "`{name}` is missing {}: it needs {}",
                    missing.join(", "),
                    needs.join(", ")
                ),
            );
            ok = false;
        }
        if !ok {
            return None;
        }
        // An error on the mass a density gives is spanned on the density.
        let spans = given
            .iter()
            .map(|(k, kv)| (*k, kv.value.to_token_stream()))
            .chain(
                given
                    .iter()
                    .filter(|(k, _)| *k == keys::DENSITY)
                    .map(|(_, kv)| (keys::MASS, kv.value.to_token_stream())),
            )
            .collect();
        let value = |k: &str| given.iter().find(|(g, _)| *g == k).map(|(_, kv)| &kv.value);
        // Every value is read, so each of its errors is reported, before any is given up on.
        let shape = self.shape(table.kind, &value);
        let at = match value(keys::AT) {
            Some(e) => self.expecting(Dim::LENGTH, keys::AT, |ck| ck.vector(e)),
            None => Some([self.arena.zero(); 3]),
        };
        let orientation = match value(keys::ROTATE) {
            Some(e) => self.expecting(Dim::ANGLE, keys::ROTATE, |ck| {
                ck.orientation(e, table.name).map(Some)
            }),
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

    /// The shape of `kind` from its key values (all required keys are present, and a
    /// solid's `density` may stand for its `mass`).
    fn shape<'e>(
        &mut self,
        kind: PartKind,
        value: &dyn Fn(&str) -> Option<&'e Expr>,
    ) -> Option<Shape<ExprId>> {
        let length_of = |ck: &mut Self, k: &'static str| {
            value(k).and_then(|e| ck.expecting(Dim::LENGTH, k, |ck| ck.scalar(e)))
        };
        let (radius, length) = (length_of(self, keys::RADIUS), length_of(self, keys::LENGTH));
        let (height, inner) = (length_of(self, keys::HEIGHT), length_of(self, keys::INNER));
        let outer = length_of(self, keys::OUTER);
        let vector_of = |ck: &mut Self, k: &'static str| {
            value(k).and_then(|e| ck.expecting(Dim::LENGTH, k, |ck| ck.vector(e)))
        };
        let (size, semi_axes) = (
            vector_of(self, keys::SIZE),
            vector_of(self, keys::SEMI_AXES),
        );
        let (axis, reversed) = match value(keys::AXIS) {
            Some(e) => self.axis(e)?,
            None => (Axis::Z, false),
        };
        let mass = match (value(keys::MASS), value(keys::DENSITY)) {
            (Some(e), _) => self.expecting(Dim::MASS, keys::MASS, |ck| ck.scalar(e)),
            (None, Some(e)) => {
                let rho = self.expecting(Dim::DENSITY, keys::DENSITY, |ck| ck.scalar(e));
                let volume = self.volume(
                    kind,
                    [radius, length, height, inner, outer],
                    size,
                    semi_axes,
                );
                self.density_mass(e, rho?, volume?)
            }
            (None, None) => None,
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
            PartKind::Cuboid => Shape::Cuboid { mass, size: size? },
            PartKind::Ellipsoid => Shape::Ellipsoid {
                mass,
                semi_axes: semi_axes?,
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
                let inertia = value(keys::INERTIA)?;
                Shape::Explicit {
                    mass,
                    inertia: self
                        .expecting(Dim::INERTIA, keys::INERTIA, |ck| ck.tensor(inertia))?,
                    about,
                }
            }
        })
    }

    /// The volume of a solid of `kind` from its dimensions `[radius, length, height, inner,
    /// outer]`, its size or its semi-axes: exact but for π, which enters as its f64.
    fn volume(
        &mut self,
        kind: PartKind,
        [radius, length, height, inner, outer]: [Option<ExprId>; 5],
        size: Option<[ExprId; 3]>,
        semi_axes: Option<[ExprId; 3]>,
    ) -> Option<ExprId> {
        let a = &mut *self.arena;
        let pi = a.float(std::f64::consts::PI).ok()?;
        let third = a.constant(Rational::new(1, 3)?);
        let four_thirds_pi = {
            let f = a.constant(Rational::new(4, 3)?);
            a.mul(f, pi)
        };
        let sq = |a: &mut precess_core::sym::Arena, x: ExprId| a.mul(x, x);
        Some(match kind {
            // 4/3 π r³
            PartKind::Sphere => {
                let r = radius?;
                let r3 = a.product(&[r, r, r]);
                a.mul(four_thirds_pi, r3)
            }
            // a b c
            PartKind::Cuboid => {
                let [x, y, z] = size?;
                a.product(&[x, y, z])
            }
            // 4/3 π a b c
            PartKind::Ellipsoid => {
                let [x, y, z] = semi_axes?;
                a.product(&[four_thirds_pi, x, y, z])
            }
            // π r² l
            PartKind::Cylinder => {
                let r2 = sq(a, radius?);
                a.product(&[pi, r2, length?])
            }
            // π (outer² − inner²) l
            PartKind::Tube => {
                let (o2, i2) = (sq(a, outer?), sq(a, inner?));
                let ring = a.sub(o2, i2);
                a.product(&[pi, ring, length?])
            }
            // π r² h / 3
            PartKind::Cone => {
                let r2 = sq(a, radius?);
                a.product(&[third, pi, r2, height?])
            }
            // Refused in `part`: no volume.
            _ => return None,
        })
    }

    /// The mass ρ V of a solid; a density written as a number must be positive (one of
    /// fields is checked with the mass it gives, at run time).
    fn density_mass(&mut self, tokens: &Expr, rho: ExprId, volume: ExprId) -> Option<ExprId> {
        let what = format!("`{}`", keys::DENSITY);
        self.positive_constant(tokens, rho, &what)
            .then(|| self.arena.mul(rho, volume))
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
