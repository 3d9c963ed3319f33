//! Meaning of the `#[body(...)]` and `#[mechanism(...)]` items: each body's keys,
//! coordinates and parts (the parts by the part language of `lang::parts`) here, its joint in `joint.rs`,
//! its loads in `loads.rs`, then the tree's rules in `tree.rs`. Every error is recorded, spanned on the offending tokens,
//! before any is given up on.

use precess_core::body::{Description, check_part, evaluate, mass_properties};
use precess_core::mechanism::loops::LoopClosure;
use precess_core::mechanism::{JointKind, MechanismBody, MechanismScene, Parent, Route};
use precess_core::sym::ExprId;
use syn::{Expr, Ident};

use super::attr::{LinkAttr, LinkItem, Links};
use super::closes::{CLOSES, ClosesSpec};
use super::joint::path_ident;
use super::loads::Coordinate;
use super::rolling::{CheckedRolling, RollingSettings, WheelSpec};
use crate::lang::check::Checker;
use crate::lang::keys::{self, part_list};
use crate::lang::syntax::{Item, KeyValue, Parsed, distinct};
use crate::lang::units::Dim;

/// A coordinate's generalised force computed by a user function `f(&self, t, &q, &qdot)`.
pub struct UserEffort {
    /// The function's path.
    pub path: syn::Path,
    /// The input symbol standing for its value in the derivation.
    pub symbol: ExprId,
    /// Its number among the mechanism's user efforts.
    pub index: usize,
}

/// The checked mechanism: the scene and what the generated code names.
pub struct CheckedMechanism {
    /// The scene for the engine.
    pub scene: MechanismScene,
    /// The coordinates as written, in state order.
    pub coordinates: Vec<Ident>,
    /// The user functions giving efforts.
    pub efforts: Vec<UserEffort>,
    /// The route asked for.
    pub route: Route,
    /// Each body's parts as written, in the order of `scene.bodies`: those made of fields are
    /// checked at run time with the rules literal parts met here.
    pub parts: Vec<Description<ExprId>>,
    /// The wheels, the floor and the free speeds, when bodies roll.
    pub rolling: Option<CheckedRolling>,
    /// The loop closures (`closes = ..`), in the order of the bodies, with their tokens.
    pub loops: Vec<(LoopClosure, ClosesSpec)>,
}

/// One link as read, before the tree is checked.
pub(super) struct LinkSpec<'a> {
    /// The body's name.
    pub(super) name: &'a Ident,
    /// `None` for the ground.
    pub(super) parent: Option<&'a Ident>,
    /// The joint's name.
    pub(super) joint_name: Ident,
    /// False when the joint is named after its body.
    pub(super) joint_named: bool,
    /// The joint's kind as written.
    pub(super) joint_kind: Ident,
    /// The joint's coordinates.
    pub(super) coordinates: Vec<Ident>,
    /// The body for the scene (its parent set once the tree is checked).
    pub(super) body: MechanismBody,
    /// Its parts as written.
    pub(super) parts: Description<ExprId>,
    /// Its rolling surface, if it rolls.
    pub(super) rolls: Option<WheelSpec>,
    /// The loop it closes, if it closes one.
    pub(super) closes: Option<ClosesSpec>,
}

/// Checks every attribute; `None` after recording why the mechanism cannot be derived.
pub fn check(
    ck: &mut Checker,
    settings: &Parsed<KeyValue>,
    links: &Links,
) -> Option<CheckedMechanism> {
    let errors_before = ck.cx.error_count();
    let (gravity, route, rolling_settings) = mechanism_settings(ck, settings);
    let mut specs: Vec<LinkSpec> = Vec::new();
    let mut efforts = Vec::new();
    for link in &links.links {
        if let Some(spec) = ck.link(link, &mut efforts) {
            specs.push(spec);
        }
    }
    if links.links.is_empty() && links.complete {
        ck.cx.error_spanned_by(
            ck.input.ident,
            format!(
                "a mechanism needs at least one moving joint: add `#[{}(name, {} = {}, {} = revolute(axis = x), {} = theta, {}(...))]`",
                keys::LINK,
                keys::PARENT,
                keys::GROUND,
                keys::JOINT,
                keys::COORDINATES,
                keys::PARTS_GROUP
            ),
        );
    }
    if !links.complete || !settings.complete || ck.cx.error_count() > errors_before {
        return None;
    }
    let parents = super::tree::tree(ck, &specs)?;
    let coordinates: Vec<Ident> = specs
        .iter()
        .flat_map(|s| s.coordinates.iter().cloned())
        .collect();
    let names: Vec<String> = coordinates.iter().map(Ident::to_string).collect();
    if !ck.refuse_coordinate_names(&names, "the mechanism") {
        return None;
    }
    let loops = super::closes::resolve(ck, &specs)?;
    let mut wheels = Vec::new();
    let mut bodies = Vec::with_capacity(specs.len());
    let mut parts = Vec::with_capacity(specs.len());
    for (index, (mut spec, parent)) in specs.into_iter().zip(parents).enumerate() {
        spec.body.joint.parent = parent;
        if let Some(rolls) = spec.rolls {
            wheels.push((index, spec.name.to_string(), rolls));
        }
        bodies.push(spec.body);
        parts.push(spec.parts);
    }
    let rolling = super::rolling::rolling(ck, &rolling_settings, wheels, &coordinates)?;
    if let (Some(_), Some((_, closes))) = (&rolling, loops.first()) {
        ck.cx.error_spanned_by(
            &closes.key,
            format!("`{CLOSES}` cannot be used with rolling bodies (`{}`): a mechanism either rolls or closes loops", keys::ROLLS),
        );
        return None;
    }
    Some(CheckedMechanism {
        scene: MechanismScene { bodies, gravity },
        coordinates,
        efforts,
        route,
        parts,
        rolling,
        loops,
    })
}

/// `gravity = g` (along −z) or `gravity = [gx, gy, gz]`, `route = ...`, and the rolling
/// keys as written (read once the bodies are known).
fn mechanism_settings<'s>(
    ck: &mut Checker,
    settings: &'s Parsed<KeyValue>,
) -> (Option<[ExprId; 3]>, Route, RollingSettings<'s>) {
    let mut gravity = None;
    let mut route = Route::Auto;
    // The first of each (a repeat is an error of `distinct`).
    let first = |k: &str| settings.items.iter().find(|kv| kv.key == k);
    let rolling = RollingSettings {
        up: first(keys::UP),
        speeds: first(keys::SPEEDS),
        route: first(keys::ROUTE),
        taylor: first(keys::TAYLOR),
    };
    let in_mechanism = format!("`#[{}]`", keys::MECHANISM);
    let cx = ck.cx;
    for KeyValue { key, value } in distinct(cx, &settings.items, &in_mechanism) {
        match keys::MECHANISM_KEYS.iter().find(|&&k| key == k).copied() {
            Some(keys::GRAVITY) => gravity = ck.gravity(value),
            Some(keys::ROUTE) => route = ck.route(value),
            // Read once the bodies are known.
            Some(keys::UP | keys::SPEEDS) => {}
            _ => {
                let groups = [crate::lang::variational::listed()];
                let place = format!("in {in_mechanism}");
                let message = keys::unknown_key(key, &place, keys::MECHANISM_KEYS, &groups);
                ck.cx.error_spanned_by(key, message);
            }
        }
    }
    (gravity, route, rolling)
}

/// A link's mass, centre and inertia about the centre, and its parts as written.
type LinkParts = (ExprId, [ExprId; 3], [[ExprId; 3]; 3], Description<ExprId>);

/// Values of one link as written, by key.
#[derive(Default)]
pub(super) struct LinkKeys<'a> {
    pub(super) parent: Option<&'a Expr>,
    pub(super) joint: Option<&'a Expr>,
    pub(super) coordinates: Option<&'a Expr>,
    pub(super) damper: Option<&'a Expr>,
    pub(super) effort: Option<&'a Expr>,
    pub(super) body_torque: Option<&'a Expr>,
    pub(super) space_torque: Option<&'a Expr>,
    pub(super) spring: Option<(&'a Ident, &'a [KeyValue])>,
    pub(super) rolls: Option<(&'a Ident, &'a Expr)>,
    pub(super) closes: Option<(&'a Ident, &'a Expr)>,
    pub(super) parts: Option<(&'a Ident, &'a [Item])>,
}

impl Checker<'_> {
    /// One link: its name first, its keys and groups, then their values.
    fn link<'l>(
        &mut self,
        link: &'l LinkAttr,
        efforts: &mut Vec<UserEffort>,
    ) -> Option<LinkSpec<'l>> {
        let errors_before = self.cx.error_count();
        let mut name: Option<&Ident> = None;
        let mut k = LinkKeys::default();
        let mut seen: Vec<&Ident> = Vec::new();
        let known = || keys::LINK_KEYS.iter().chain(keys::LINK_GROUPS).copied();
        for (index, item) in link.items.iter().enumerate() {
            let key = match item {
                LinkItem::Name(n) if index == 0 => {
                    name = Some(n);
                    continue;
                }
                LinkItem::Name(n) => {
                    self.cx.error_spanned_by(
                        n,
                        format!("expected `key = value` or `group(...)`: only the body's name, first in the list, stands alone{}", keys::did_you_mean(&n.to_string(), known())),
                    );
                    continue;
                }
                LinkItem::Item(Item::Setting(kv)) => &kv.key,
                LinkItem::Parts { keyword, .. } => keyword,
                LinkItem::Item(Item::Group { name, .. }) => name,
            };
            if seen.contains(&key) {
                self.cx
                    .error_spanned_by(key, format!("duplicate key `{key}` in `#[{}]`", keys::LINK));
                continue;
            }
            seen.push(key);
            match item {
                LinkItem::Name(_) => {}
                LinkItem::Parts { keyword, items } => k.parts = Some((keyword, items)),
                LinkItem::Item(Item::Group { name, keys: list }) if name == keys::SPRING => {
                    k.spring = Some((name, list));
                }
                LinkItem::Item(Item::Group { name, .. }) => self.cx.error_spanned_by(
                    name,
                    format!(
                        "unknown group `{name}(...)` in `#[{}]`: expected {}{}",
                        keys::LINK,
                        link_groups(),
                        keys::did_you_mean(&name.to_string(), known())
                    ),
                ),
                LinkItem::Item(Item::Setting(kv)) if kv.key == keys::ROLLS => {
                    k.rolls = Some((&kv.key, &kv.value));
                }
                LinkItem::Item(Item::Setting(kv)) if kv.key == CLOSES => {
                    k.closes = Some((&kv.key, &kv.value));
                }
                LinkItem::Item(Item::Setting(kv)) => {
                    let slot = match kv.key.to_string().as_str() {
                        keys::PARENT => &mut k.parent,
                        keys::JOINT => &mut k.joint,
                        keys::COORDINATES => &mut k.coordinates,
                        keys::DAMPER => &mut k.damper,
                        keys::EFFORT => &mut k.effort,
                        keys::BODY_TORQUE => &mut k.body_torque,
                        keys::SPACE_TORQUE => &mut k.space_torque,
                        _ => {
                            let place = format!("in `#[{}]`", keys::LINK);
                            let groups =
                                [(keys::LINK_GROUPS, format!("the groups {}", link_groups()))];
                            let message =
                                keys::unknown_key(&kv.key, &place, keys::LINK_KEYS, &groups);
                            self.cx.error_spanned_by(&kv.key, message);
                            continue;
                        }
                    };
                    *slot = Some(&kv.value);
                }
            }
        }
        let Some(name) = name else {
            self.cx.error_spanned_by(
                link.attr,
                format!(
                    "a body starts with its name: `#[{}(name, ...)]`",
                    keys::LINK
                ),
            );
            return None;
        };
        let parent = match k.parent {
            None => None,
            Some(e) => match path_ident(e) {
                Some(p) if p == keys::GROUND => None,
                Some(p) => Some(p),
                None => {
                    self.cx.error_spanned_by(
                        e,
                        format!("expected `{}` or the name of another body", keys::GROUND),
                    );
                    None
                }
            },
        };
        let joint = match k.joint {
            Some(e) => self.joint(e),
            None => {
                self.cx.error_spanned_by(
                    name,
                    format!("body `{name}` has no joint: add `{} = revolute(axis = x)` (or prismatic, universal, spherical, free)", keys::JOINT),
                );
                None
            }
        };
        let coordinates = match (k.coordinates, &joint) {
            (Some(e), Some(j)) => self.coordinates(e, &j.kind),
            (None, _) => {
                self.cx.error_spanned_by(
                    name,
                    format!("body `{name}` does not name its joint's coordinates: add `{} = name` (or `{} = [a, b]`, `[a, b, c]` for universal and spherical joints, six names for a free joint)", keys::COORDINATES, keys::COORDINATES),
                );
                None
            }
            (Some(_), None) => None,
        };
        let measures = joint
            .as_ref()
            .map_or(vec![Coordinate::Angle], |j| measures(&j.kind));
        let loads = self.loads(&k, &measures, efforts);
        let rolls = k.rolls.map(|(key, e)| {
            self.rolls(e).map(|surface| WheelSpec {
                surface,
                key: key.clone(),
            })
        });
        let closes = k.closes.map(|(key, e)| self.closes(key, e));
        let body_torque = k
            .body_torque
            .map(|e| self.expecting(Dim::TORQUE, keys::BODY_TORQUE, |ck| ck.vector(e)));
        let space_torque = k
            .space_torque
            .map(|e| self.expecting(Dim::TORQUE, keys::SPACE_TORQUE, |ck| ck.vector(e)));
        let parts = match k.parts {
            Some((keyword, items)) => self.link_parts(keyword, items),
            None => {
                self.cx.error_spanned_by(
                    name,
                    format!(
                        "body `{name}` has no parts: describe it with `{}(...)`, in its own frame whose origin is its joint: {}",
                        keys::PARTS_GROUP,
                        part_list()
                    ),
                );
                None
            }
        };
        if self.cx.error_count() > errors_before {
            return None;
        }
        let (joint, coordinates, loads, parts) = (joint?, coordinates?, loads?, parts?);
        let joint_named = joint.name.is_some();
        let joint_kind = joint.kind_ident.clone();
        let joint_name = joint.name.unwrap_or_else(|| name.clone());
        let (mass, center, inertia, description) = parts;
        let mut body = MechanismBody {
            name: name.to_string(),
            mass,
            center,
            inertia,
            joint: precess_core::mechanism::Joint {
                name: joint_name.to_string(),
                parent: Parent::Ground,
                at: joint.at,
                kind: joint.kind,
                coordinates: coordinates.iter().map(Ident::to_string).collect(),
                loads,
            },
            body_torque: None,
            space_torque: None,
        };
        body.body_torque = body_torque.flatten();
        body.space_torque = space_torque.flatten();
        Some(LinkSpec {
            name,
            parent,
            joint_name,
            joint_named,
            joint_kind,
            coordinates,
            body,
            parts: description,
            rolls: rolls.flatten(),
            closes: closes.flatten(),
        })
    }

    /// The mass, centre and inertia about the centre of a link's parts, in its frame. Literal
    /// parts meet the `#[rigid]` rules now, but for a zero mass: a massless part (a gimbal
    /// ring modelled without mass, say) is allowed, literal or field alike, and a chain with
    /// nothing to move is the singular mass matrix's concern.
    fn link_parts(&mut self, keyword: &Ident, items: &[Item]) -> Option<LinkParts> {
        let mut description = Description::default();
        let mut ok = true;
        for item in items {
            match item {
                Item::Group { name, keys } => match self.part(name, keys) {
                    Some((part, _)) => {
                        let single = Description {
                            parts: vec![part.clone()],
                            pivot: None,
                        };
                        if let Some(numeric) = evaluate(self.arena, &single)
                            && let Some(p) = massless_as_unit(&numeric).parts.first()
                            && let Err(e) = check_part(0, p)
                        {
                            // Core numbers the part; the span shows it.
                            let text = e.to_string();
                            let text = match text.split_once("): ") {
                                Some((head, rest)) if head.starts_with("part ") => rest.to_owned(),
                                _ => text,
                            };
                            self.cx.error_spanned_by(name, format!("`{name}`: {text}"));
                            ok = false;
                        }
                        description.parts.push(part);
                    }
                    None => ok = false,
                },
                Item::Setting(kv) => {
                    self.cx.error_spanned_by(
                        &kv.key,
                        format!(
                            "`{}` is not a part: a body's parts are {} (a body of a mechanism turns about its joint, so it has no pivot)",
                            kv.key,
                            part_list()
                        ),
                    );
                    ok = false;
                }
            }
        }
        if description.parts.is_empty() && ok {
            self.cx.error_spanned_by(
                keyword,
                format!(
                    "`{}()` is empty: a body needs at least one part: {}",
                    keys::PARTS_GROUP,
                    part_list()
                ),
            );
            return None;
        }
        if !ok {
            return None;
        }
        // A body of massless parts only has no centre to average over: it carries nothing.
        let zero = self.arena.zero();
        if description.parts.iter().all(|p| *p.shape.mass() == zero) {
            let z = zero;
            return Some((z, [z; 3], [[z; 3]; 3], description));
        }
        match mass_properties(self.arena, &description) {
            Ok(props) => Some((props.mass, props.center, props.inertia_cm, description)),
            Err(e) => {
                self.cx.error_spanned_by(keyword, e);
                None
            }
        }
    }

    /// `q = name` for one coordinate, `q = [a, b]` or `[a, b, c]` for more.
    fn coordinates(&mut self, e: &Expr, kind: &JointKind) -> Option<Vec<Ident>> {
        let dof = kind.dof();
        let names: Vec<&Expr> = match e {
            Expr::Array(a) => a.elems.iter().collect(),
            other => vec![other],
        };
        if names.len() != dof {
            let expected = match dof {
                1 => format!("`{} = name`", keys::COORDINATES),
                2 => format!("`{} = [a, b]`", keys::COORDINATES),
                3 => format!("`{} = [a, b, c]`", keys::COORDINATES),
                _ => format!(
                    "`{} = [x, y, z, a, b, c]` (three translations, then three angles)",
                    keys::COORDINATES
                ),
            };
            self.cx.error_spanned_by(
                e,
                format!(
                    "a {} joint has {dof} coordinate{}, got {}: write {expected}",
                    kind.name(),
                    if dof == 1 { "" } else { "s" },
                    names.len()
                ),
            );
            return None;
        }
        let mut out = Vec::with_capacity(dof);
        for n in names {
            match path_ident(n) {
                Some(i) => out.push(i.clone()),
                None => {
                    self.cx
                        .error_spanned_by(n, "expected the name of a coordinate, such as `theta`");
                    return None;
                }
            }
        }
        Some(out)
    }
}

/// The part with a zero mass put to 1, so `check_part` judges the rest of a massless part
/// (its geometry) by the body language's rules; the same substitution the generated
/// `check_parameters` makes for a field's zero mass.
/// What each of a joint's coordinates measures, in the order of its coordinates.
fn measures(kind: &JointKind) -> Vec<Coordinate> {
    use Coordinate::{Angle, Length};
    match kind {
        JointKind::Prismatic { .. } => vec![Length],
        JointKind::Free { .. } => vec![Length, Length, Length, Angle, Angle, Angle],
        other => vec![Angle; other.dof()],
    }
}

fn massless_as_unit(numeric: &Description<f64>) -> Description<f64> {
    let mut index = 0;
    let indices = numeric.map(&mut |_| {
        index += 1;
        index - 1
    });
    let mass_index = indices.parts.first().map(|p| *p.shape.mass());
    let mut at = 0;
    numeric.map(&mut |&v| {
        at += 1;
        if Some(at - 1) == mass_index && v == 0.0 {
            1.0
        } else {
            v
        }
    })
}

/// The groups of `#[body(...)]` in their forms, as its messages list them.
fn link_groups() -> String {
    format!(
        "`{}(...)` or `{}({} = .., {} = ..)`",
        keys::PARTS_GROUP,
        keys::SPRING,
        keys::STIFFNESS,
        keys::REST
    )
}
