//! Meaning of the `#[rigid(...)]` items: parts and keys against the tables, values to
//! symbolic expressions, then the body's rules. One function per rule, the reason in a
//! comment; every error is recorded in the context, spanned on the offending tokens.

use precess_core::body::{
    About, Axis, BodyError, Description, Part, Shape, SymbolicBody, check_part, evaluate,
};
use precess_core::sym::{Arena, ExprId};
use proc_macro2::TokenStream;
use quote::ToTokens;
use syn::{Expr, Ident};

use crate::ast::Input;
use crate::attr::{self, Item, KeyValue};
use crate::ctxt::Ctxt;

mod values;

/// The keys of one part: required, then optional.
struct Spec {
    name: &'static str,
    required: &'static [&'static str],
    optional: &'static [&'static str],
}

const AT: &[&str] = &["at"];
const AT_AXIS: &[&str] = &["at", "axis"];

const PARTS: &[Spec] = &[
    Spec {
        name: "particle",
        required: &["mass"],
        optional: AT,
    },
    Spec {
        name: "sphere",
        required: &["mass", "radius"],
        optional: AT,
    },
    Spec {
        name: "shell",
        required: &["mass", "radius"],
        optional: AT,
    },
    Spec {
        name: "cuboid",
        required: &["mass", "size"],
        optional: AT,
    },
    Spec {
        name: "cylinder",
        required: &["mass", "radius", "length"],
        optional: AT_AXIS,
    },
    Spec {
        name: "tube",
        required: &["mass", "inner", "outer", "length"],
        optional: AT_AXIS,
    },
    Spec {
        name: "disk",
        required: &["mass", "radius"],
        optional: AT_AXIS,
    },
    Spec {
        name: "ring",
        required: &["mass", "radius"],
        optional: AT_AXIS,
    },
    Spec {
        name: "rod",
        required: &["mass", "length"],
        optional: AT_AXIS,
    },
    Spec {
        name: "cone",
        required: &["mass", "radius", "height"],
        optional: AT_AXIS,
    },
    Spec {
        name: "ellipsoid",
        required: &["mass", "semi_axes"],
        optional: AT,
    },
    Spec {
        name: "body",
        required: &["mass", "inertia"],
        optional: &["at", "about"],
    },
];

const PART_NAMES: &str = "particle, sphere, shell, cuboid (or box), cylinder, tube, disk, ring, rod, cone, ellipsoid, body";

/// The checked description and where each of its values came from.
pub struct Checked {
    /// The arena holding every value.
    pub arena: Arena,
    /// The body.
    pub description: Description<ExprId>,
    /// The symbolic body computed from it.
    pub body: SymbolicBody,
    /// The struct fields used as parameters, by name.
    pub fields: Vec<Ident>,
}

/// The tokens of each key's value in one part.
type KeySpans = Vec<(&'static str, TokenStream)>;

/// Tokens of each value, to span errors found on the whole body.
struct Spans {
    parts: Vec<KeySpans>,
    pivot: Option<TokenStream>,
    whole: TokenStream,
}

impl Spans {
    fn of(&self, part: usize, key: &str) -> TokenStream {
        let found = self
            .parts
            .get(part)
            .and_then(|p| p.iter().find(|(k, _)| *k == key));
        match found {
            Some((_, t)) => t.clone(),
            None => self.whole.clone(),
        }
    }
}

/// Converts attribute values into the body's arena, recording every error.
pub struct Checker<'a, 'c> {
    /// Where errors go.
    pub cx: &'c mut Ctxt,
    input: &'a Input<'a>,
    /// The arena the values are built in.
    pub arena: Arena,
    fields: Vec<Ident>,
}

impl<'a, 'c> Checker<'a, 'c> {
    /// Resumes value conversion in the arena of a checked body, for the values of other
    /// attributes (`#[top]`): the same rules and errors as `#[rigid]` values.
    pub fn resume(cx: &'c mut Ctxt, input: &'a Input<'a>, checked: &mut Checked) -> Self {
        Checker {
            cx,
            input,
            arena: std::mem::take(&mut checked.arena),
            fields: std::mem::take(&mut checked.fields),
        }
    }

    /// Hands the arena and the fields used (now including the new values') back.
    pub fn suspend(self, checked: &mut Checked) {
        checked.arena = self.arena;
        checked.fields = self.fields;
    }
}

/// Checks the input's `#[rigid]` attributes and computes the symbolic body.
pub fn check(cx: &mut Ctxt, input: &Input) -> Option<Checked> {
    // The body is described only by the attribute: without one there is nothing to derive.
    if input.rigid.is_empty() {
        cx.error(input.ident, format!("`#[derive(RigidBody)]` needs a `#[rigid(...)]` attribute listing the body's parts: {PART_NAMES}"));
        return None;
    }
    let mut items = Vec::new();
    for attr in &input.rigid {
        match attr::parse(attr) {
            Ok(mut v) => items.append(&mut v),
            Err(e) => cx.push(e),
        }
    }
    let whole: TokenStream = input.rigid.iter().map(|a| a.to_token_stream()).collect();
    let mut ck = Checker {
        cx,
        input,
        arena: Arena::new(),
        fields: Vec::new(),
    };
    let mut description = Description::default();
    let mut spans = Spans {
        parts: Vec::new(),
        pivot: None,
        whole,
    };
    let mut pivot_key: Option<&Ident> = None;
    for item in &items {
        match item {
            Item::Part { name, keys } => {
                if let Some((part, part_spans)) = ck.part(name, keys) {
                    description.parts.push(part);
                    spans.parts.push(part_spans);
                }
            }
            Item::Setting(KeyValue { key, value }) if key == "pivot" => {
                // One pivot: a body turns about a single fixed point.
                if pivot_key.is_some() {
                    ck.cx
                        .error(key, "duplicate key `pivot`: a body has one pivot");
                    continue;
                }
                pivot_key = Some(key);
                description.pivot = ck.vector(value);
                spans.pivot = Some(value.to_token_stream());
            }
            Item::Setting(KeyValue { key, .. }) => {
                ck.cx.error(key, format!("unknown key `{key}`: at the top level only `pivot = [x, y, z]` and parts ({PART_NAMES}) are allowed"));
            }
        }
    }
    let Checker {
        cx, arena, fields, ..
    } = ck;
    if !cx.is_ok() {
        return None;
    }
    validate(cx, arena, description, &spans, fields)
}

/// Runs the body rules: each part whose values are all literals now, then the whole body.
fn validate(
    cx: &mut Ctxt,
    mut arena: Arena,
    description: Description<ExprId>,
    spans: &Spans,
    fields: Vec<Ident>,
) -> Option<Checked> {
    if description.parts.is_empty() {
        cx.error(
            &spans.whole,
            format!("a body needs at least one part: {PART_NAMES}"),
        );
        return None;
    }
    // Literal parts are checked at compile time; parametric ones by the generated validate().
    for (index, part) in description.parts.iter().enumerate() {
        let single = Description {
            parts: vec![part.clone()],
            pivot: None,
        };
        if let Some(numeric) = evaluate(&arena, &single)
            && let Err(e) = check_part(index, &numeric.parts[0])
        {
            report(cx, spans, &e);
        } else if let Shape::Explicit { inertia, .. } = &part.shape {
            symmetric_tensor(cx, &mut arena, inertia, &spans.of(index, "inertia"));
        }
    }
    if !cx.is_ok() {
        return None;
    }
    if let Some(numeric) = evaluate(&arena, &description)
        && let Err(e) = numeric.validate()
    {
        report(cx, spans, &e);
        return None;
    }
    match SymbolicBody::new(&mut arena, &description) {
        Ok(body) => Some(Checked {
            arena,
            description,
            body,
            fields,
        }),
        Err(e) => {
            report(cx, spans, &e);
            None
        }
    }
}

/// An explicit tensor with field entries must still be symmetric for every value of the
/// fields: I[i][j] and I[j][i] are the same quantity, so they must be the same expression.
fn symmetric_tensor(cx: &mut Ctxt, arena: &mut Arena, t: &[[ExprId; 3]; 3], tokens: &TokenStream) {
    for (i, j) in [(0, 1), (0, 2), (1, 2)] {
        let d = arena.sub(t[i][j], t[j][i]);
        if arena.expand(d) != arena.zero() {
            let (a, b) = (arena.display(t[i][j]), arena.display(t[j][i]));
            cx.error(tokens, format!("the inertia tensor must be symmetric, but I[{i}][{j}] = {a} and I[{j}][{i}] = {b}: write the same value in both"));
            return;
        }
    }
}

/// Records a body error on the tokens it is about, with what is allowed.
fn report(cx: &mut Ctxt, spans: &Spans, e: &BodyError) {
    let (tokens, msg) = match *e {
        BodyError::NoParts => (spans.whole.clone(), format!("a body needs at least one part: {PART_NAMES}")),
        BodyError::NonFinite { part, key, value, .. } => (spans.of(part, key), format!("`{key}` evaluates to {value}: values must be finite")),
        BodyError::NonFinitePivot { value } => (spans.pivot.clone().unwrap_or(spans.whole.clone()), format!("the pivot has the coordinate {value}: values must be finite")),
        BodyError::NonPositiveMass { part, value, .. } => (spans.of(part, "mass"), format!("mass must be positive, got {value}")),
        BodyError::NonPositiveDimension { part, key, value, .. } => (spans.of(part, key), format!("`{key}` must be positive, got {value}")),
        BodyError::TubeRadii { part, inner, outer } => (spans.of(part, "inner"), format!("the inner radius must satisfy 0 ≤ inner < outer, got inner = {inner} and outer = {outer}")),
        BodyError::NotSymmetric { part, row, col, upper, lower } => (
            spans.of(part, "inertia"),
            format!("the inertia tensor must be symmetric, but I[{row}][{col}] = {upper} and I[{col}][{row}] = {lower}"),
        ),
        BodyError::NotPositiveDefinite { part, moments } => (
            spans.of(part, "inertia"),
            format!("the inertia tensor must be positive definite, but its principal moments are {moments:?}"),
        ),
        BodyError::TriangleInequality { part, moments } => (
            spans.of(part, "inertia"),
            format!("the principal moments {moments:?} break the triangle inequality I1 + I2 ≥ I3, which every mass distribution satisfies"),
        ),
        BodyError::PivotRequired { part } => (spans.of(part, "about"), "`about = pivot` needs a pivot: declare `pivot = [x, y, z]`, or give the tensor `about = center`".to_owned()),
        BodyError::ZeroTotalMass => (spans.whole.clone(), "the total mass is zero: masses must be positive".to_owned()),
        BodyError::IdenticallyZeroMoment { .. } => (
            spans.whole.clone(),
            "the body has a principal moment that is zero whatever its fields: all its mass lies on a line through the reference point; Euler's equations need three positive moments".to_owned(),
        ),
        BodyError::Overflow { quantity, value } => (spans.whole.clone(), format!("the body's {quantity} overflows f64 (it evaluates to {value}): its values are too large for f64, whose largest finite value is about 1.8e308; use larger units")),
        BodyError::Underflow { moments } => (spans.whole.clone(), format!("the body's principal moments {moments:?} underflow f64: its values are too small for f64, whose smallest normal value is about 2.2e-308; use smaller units")),
        BodyError::ZeroPrincipalMoment { moments } => (
            spans.whole.clone(),
            format!("the body has a zero principal moment (moments {moments:?}): all its mass lies on a line through the reference point; Euler's equations need three positive moments"),
        ),
    };
    cx.error(tokens, msg);
}

impl Checker<'_, '_> {
    /// One part: known name, known and unique keys, every required key, then its values.
    fn part(&mut self, name: &Ident, keys: &[KeyValue]) -> Option<(Part<ExprId>, KeySpans)> {
        let written = name.to_string();
        let canonical = if written == "box" {
            "cuboid"
        } else {
            written.as_str()
        };
        let Some(spec) = PARTS.iter().find(|s| s.name == canonical) else {
            self.cx.error(
                name,
                format!("unknown part `{written}`: expected one of {PART_NAMES}"),
            );
            return None;
        };
        let mut given: Vec<(&'static str, &KeyValue)> = Vec::new();
        let mut ok = true;
        for kv in keys {
            let k = kv.key.to_string();
            let k = if spec.name == "body" && k == "center" {
                "at".to_owned()
            } else {
                k
            };
            let Some(&key) = spec.required.iter().chain(spec.optional).find(|&&s| s == k) else {
                let allowed: Vec<&str> =
                    spec.required.iter().chain(spec.optional).copied().collect();
                self.cx.error(
                    &kv.key,
                    format!(
                        "unknown key `{}` for `{}`: allowed keys are {}",
                        kv.key,
                        spec.name,
                        allowed.join(", ")
                    ),
                );
                ok = false;
                continue;
            };
            // Each key once: two values for one quantity are ambiguous.
            if given.iter().any(|(g, _)| *g == key) {
                self.cx.error(
                    &kv.key,
                    format!(
                        "duplicate key `{}` in `{}`: give each key once",
                        kv.key, spec.name
                    ),
                );
                ok = false;
                continue;
            }
            given.push((key, kv));
        }
        // Every required key: a solid needs all its dimensions.
        let missing: Vec<&str> = spec
            .required
            .iter()
            .filter(|r| !given.iter().any(|(g, _)| g == *r))
            .copied()
            .collect();
        if !missing.is_empty() {
            let keys: Vec<String> = missing.iter().map(|m| format!("`{m}`")).collect();
            self.cx.error(
                name,
                format!(
                    "`{written}` is missing {}: it needs {}",
                    keys.join(", "),
                    spec.required.join(", ")
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
        let get = |k: &str| given.iter().find(|(g, _)| *g == k).map(|(_, kv)| &kv.value);
        let shape = self.shape(spec.name, &get)?;
        let at = match get("at") {
            Some(e) => self.vector(e)?,
            None => [self.arena.zero(); 3],
        };
        Some((Part { shape, at }, spans))
    }

    /// The shape named `name` from its key values (all required keys are present).
    fn shape<'e>(
        &mut self,
        name: &str,
        get: &dyn Fn(&str) -> Option<&'e Expr>,
    ) -> Option<Shape<ExprId>> {
        let mut s = |k: &str| get(k).and_then(|e| self.scalar(e));
        let (mass, a, b, c) = (s("mass"), s("radius"), s("length"), s("height"));
        let (inner, outer) = (s("inner"), s("outer"));
        let (axis, reversed) = match get("axis") {
            Some(e) => self.axis(e)?,
            None => (Axis::Z, false),
        };
        let mass = mass?;
        Some(match name {
            "particle" => Shape::Particle { mass },
            "sphere" => Shape::Sphere { mass, radius: a? },
            "shell" => Shape::Shell { mass, radius: a? },
            "cuboid" => Shape::Cuboid {
                mass,
                size: self.vector(get("size")?)?,
            },
            "ellipsoid" => Shape::Ellipsoid {
                mass,
                semi_axes: self.vector(get("semi_axes")?)?,
            },
            "cylinder" => Shape::Cylinder {
                mass,
                radius: a?,
                length: b?,
                axis,
            },
            "tube" => Shape::Tube {
                mass,
                inner: inner?,
                outer: outer?,
                length: b?,
                axis,
            },
            "disk" => Shape::Disk {
                mass,
                radius: a?,
                axis,
            },
            "ring" => Shape::Ring {
                mass,
                radius: a?,
                axis,
            },
            "rod" => Shape::Rod {
                mass,
                length: b?,
                axis,
            },
            "cone" => Shape::Cone {
                mass,
                radius: a?,
                height: c?,
                axis,
                reversed,
            },
            _ => {
                let about = match get("about") {
                    Some(e) => self.about(e)?,
                    None => About::Center,
                };
                Shape::Explicit {
                    mass,
                    inertia: self.tensor(get("inertia")?)?,
                    about,
                }
            }
        })
    }
}
