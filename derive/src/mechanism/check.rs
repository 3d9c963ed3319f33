//! Meaning of the `#[body(...)]` and `#[mechanism(...)]` items: each link's keys, joint,
//! coordinates, loads and parts (the parts with the `#[rigid]` rules), then the tree: names
//! unique, parents known, no cycle. Every error is recorded, spanned on the offending tokens,
//! before any is given up on.

use precess_core::body::{Description, check_part, evaluate, mass_properties};
use precess_core::mechanism::{
    CoordinateLoad, JointKind, MechanismBody, MechanismScene, Parent, Spring,
};
use precess_core::rigid::AngleSequence;
use precess_core::sym::ExprId;
use syn::{Expr, Ident};

use super::attr::{LinkAttr, LinkItem, Links};
use crate::keys::{self, part_list};
use crate::rigid::attr::{Item, KeyValue, Parsed};
use crate::rigid::check::Checker;

/// How the accelerations are to be solved, as the user asked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RouteChoice {
    /// The cheapest by the engine's estimate.
    Auto,
    /// Symbolic inverse of the mass matrix.
    Symbolic,
    /// LDLᵀ of the mass matrix, unrolled.
    Factored,
    /// Articulated-body recursion, unrolled.
    Recursive,
}

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
    pub route: RouteChoice,
}

/// One link as read, before the tree is checked.
struct LinkSpec<'a> {
    name: &'a Ident,
    /// `None` for the ground.
    parent: Option<&'a Ident>,
    joint_name: Ident,
    /// False when the joint is named after its link.
    joint_named: bool,
    coordinates: Vec<Ident>,
    body: MechanismBody,
}

/// Checks every attribute; `None` after recording why the mechanism cannot be derived.
pub fn check(
    ck: &mut Checker,
    settings: &Parsed<KeyValue>,
    links: &Links,
) -> Option<CheckedMechanism> {
    let errors_before = ck.cx.error_count();
    let (gravity, route) = mechanism_settings(ck, settings);
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
    let parents = tree(ck, &specs)?;
    let coordinates: Vec<Ident> = specs
        .iter()
        .flat_map(|s| s.coordinates.iter().cloned())
        .collect();
    let bodies = specs
        .into_iter()
        .zip(parents)
        .map(|(mut spec, parent)| {
            spec.body.joint.parent = parent;
            spec.body
        })
        .collect();
    Some(CheckedMechanism {
        scene: MechanismScene { bodies, gravity },
        coordinates,
        efforts,
        route,
    })
}

/// `gravity = g` (along −z) or `gravity = [gx, gy, gz]`, and `route = ...`.
fn mechanism_settings(
    ck: &mut Checker,
    settings: &Parsed<KeyValue>,
) -> (Option<[ExprId; 3]>, RouteChoice) {
    let mut gravity = None;
    let mut route = RouteChoice::Auto;
    let mut seen: Vec<&Ident> = Vec::new();
    for KeyValue { key, value } in &settings.items {
        if seen.contains(&key) {
            ck.cx
                .error_spanned_by(key, format!("duplicate key `{key}`"));
            continue;
        }
        seen.push(key);
        match keys::MECHANISM_KEYS.iter().find(|&&k| key == k).copied() {
            Some(keys::GRAVITY) => gravity = ck.gravity(value),
            Some(keys::ROUTE) => route = ck.route(value),
            _ => ck.cx.error_spanned_by(
                key,
                format!(
                    "unknown key `{key}` in `#[{}]`: expected {}{}",
                    keys::MECHANISM,
                    keys::MECHANISM_KEYS.join(", "),
                    keys::did_you_mean(&key.to_string(), keys::MECHANISM_KEYS.iter().copied())
                ),
            ),
        }
    }
    (gravity, route)
}

/// The parent of each link: names unique, parents known, every chain reaching the ground.
fn tree(ck: &Checker, specs: &[LinkSpec]) -> Option<Vec<Parent>> {
    let errors_before = ck.cx.error_count();
    // Links, joints and coordinates each name one thing: two of a name are ambiguous.
    let mut seen_links: Vec<String> = Vec::new();
    let mut seen_joints: Vec<String> = Vec::new();
    let mut seen_coordinates: Vec<String> = Vec::new();
    for spec in specs {
        let name = spec.name.to_string();
        let duplicate_link = seen_links.contains(&name);
        if name == keys::GROUND {
            ck.cx.error_spanned_by(
                spec.name,
                format!(
                    "a body cannot be called `{}`: the name is the inertial frame's",
                    keys::GROUND
                ),
            );
        } else if seen_links.contains(&name) {
            ck.cx.error_spanned_by(
                spec.name,
                format!("duplicate body name `{name}`: each body needs its own name"),
            );
        }
        seen_links.push(name);
        let joint = spec.joint_name.to_string();
        // A joint named after a duplicate link is that one mistake, reported once.
        if seen_joints.contains(&joint) && (spec.joint_named || !duplicate_link) {
            ck.cx.error_spanned_by(
                &spec.joint_name,
                format!("duplicate joint name `{joint}`: each joint needs its own name (a joint is named after its body unless given `{} = ...`)", keys::NAME),
            );
        }
        seen_joints.push(joint);
        for c in &spec.coordinates {
            // The coordinates become associated consts in capitals: `theta` and `Theta`
            // would be one const.
            let upper = c.to_string().to_uppercase();
            if seen_coordinates.contains(&upper) {
                ck.cx.error_spanned_by(
                    c,
                    format!("duplicate coordinate name `{c}`: each coordinate needs its own name (case aside: they become the consts `Self::{upper}`)"),
                );
            }
            seen_coordinates.push(upper);
        }
    }
    let mut parents = Vec::with_capacity(specs.len());
    for spec in specs {
        let parent = match spec.parent {
            None => Some(Parent::Ground),
            Some(p) => match specs.iter().position(|s| s.name == p) {
                Some(i) => Some(Parent::Body(i)),
                None => {
                    let known = specs
                        .iter()
                        .map(|s| s.name.to_string())
                        .chain([keys::GROUND.to_owned()])
                        .collect::<Vec<_>>();
                    ck.cx.error_spanned_by(
                        p,
                        format!(
                            "unknown parent `{p}`: a parent is `{}` or another body ({}){}",
                            keys::GROUND,
                            known
                                .iter()
                                .map(|k| format!("`{k}`"))
                                .collect::<Vec<_>>()
                                .join(", "),
                            keys::did_you_mean(&p.to_string(), known.iter().map(String::as_str))
                        ),
                    );
                    None
                }
            },
        };
        parents.push(parent);
    }
    if ck.cx.error_count() > errors_before {
        return None;
    }
    let parents: Vec<Parent> = parents.into_iter().flatten().collect();
    // A chain of parents that never reaches the ground is a loop, not a tree: report each
    // loop once, on the parent of its first link.
    let mut reported: Vec<usize> = Vec::new();
    for start in 0..specs.len() {
        let mut path = vec![start];
        let mut at = start;
        while let Some(Parent::Body(next)) = parents.get(at).copied() {
            if let Some(k) = path.iter().position(|&p| p == next) {
                let cycle: Vec<usize> = path.split_off(k);
                if !cycle.iter().any(|c| reported.contains(c)) {
                    let first = cycle.iter().copied().min().unwrap_or(next);
                    let names: Vec<String> = cycle
                        .iter()
                        .chain(cycle.first())
                        .filter_map(|&c| specs.get(c))
                        .map(|s| format!("`{}`", s.name))
                        .collect();
                    if let Some(tokens) = specs.get(first).and_then(|s| s.parent) {
                        ck.cx.error_spanned_by(
                            tokens,
                            format!(
                                "the bodies form a cycle, each hanging from the next: {}; a mechanism is a tree whose every chain of parents ends at `{}`",
                                names.join(" → "),
                                keys::GROUND
                            ),
                        );
                    }
                    reported.extend(cycle);
                }
                break;
            }
            path.push(next);
            at = next;
        }
    }
    (ck.cx.error_count() == errors_before).then_some(parents)
}

/// Values of one link as written, by key.
#[derive(Default)]
struct LinkKeys<'a> {
    parent: Option<&'a Expr>,
    joint: Option<&'a Expr>,
    coordinates: Option<&'a Expr>,
    damper: Option<&'a Expr>,
    effort: Option<&'a Expr>,
    body_torque: Option<&'a Expr>,
    space_torque: Option<&'a Expr>,
    spring: Option<(&'a Ident, &'a [KeyValue])>,
    parts: Option<(&'a Ident, &'a [Item])>,
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
                LinkItem::Setting(kv) => &kv.key,
                LinkItem::Parts { keyword, .. } => keyword,
                LinkItem::Group { name, .. } => name,
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
                LinkItem::Group { name, keys: list } if name == keys::SPRING => {
                    k.spring = Some((name, list));
                }
                LinkItem::Group { name, .. } => self.cx.error_spanned_by(
                    name,
                    format!(
                        "unknown group `{name}(...)` in `#[{}]`: expected `{}(...)` or `{}({} = .., {} = ..)`{}",
                        keys::LINK,
                        keys::PARTS_GROUP,
                        keys::SPRING,
                        keys::STIFFNESS,
                        keys::REST,
                        keys::did_you_mean(&name.to_string(), known())
                    ),
                ),
                LinkItem::Setting(kv) => {
                    let slot = match kv.key.to_string().as_str() {
                        keys::PARENT => &mut k.parent,
                        keys::JOINT => &mut k.joint,
                        keys::COORDINATES => &mut k.coordinates,
                        keys::DAMPER => &mut k.damper,
                        keys::EFFORT => &mut k.effort,
                        keys::BODY_TORQUE => &mut k.body_torque,
                        keys::SPACE_TORQUE => &mut k.space_torque,
                        _ => {
                            self.cx.error_spanned_by(
                                &kv.key,
                                format!(
                                    "unknown key `{}` in `#[{}]`: expected {}, or the groups {}(...), {}(...){}",
                                    kv.key,
                                    keys::LINK,
                                    keys::LINK_KEYS.join(", "),
                                    keys::PARTS_GROUP,
                                    keys::SPRING,
                                    keys::did_you_mean(&kv.key.to_string(), known())
                                ),
                            );
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
                    format!("body `{name}` has no joint: add `{} = revolute(axis = x)` (or prismatic, universal, spherical)", keys::JOINT),
                );
                None
            }
        };
        let coordinates = match (k.coordinates, &joint) {
            (Some(e), Some(j)) => self.coordinates(e, &j.kind),
            (None, _) => {
                self.cx.error_spanned_by(
                    name,
                    format!("body `{name}` does not name its joint's coordinates: add `{} = name` (or `{} = [a, b]`, `[a, b, c]` for universal and spherical joints)", keys::COORDINATES, keys::COORDINATES),
                );
                None
            }
            (Some(_), None) => None,
        };
        let dof = joint.as_ref().map_or(1, |j| j.kind.dof());
        let loads = self.loads(&k, dof, efforts);
        let body_torque = k.body_torque.map(|e| self.vector(e));
        let space_torque = k.space_torque.map(|e| self.vector(e));
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
        let joint_name = joint.name.unwrap_or_else(|| name.clone());
        let mut body = MechanismBody {
            name: name.to_string(),
            mass: parts.0,
            center: parts.1,
            inertia: parts.2,
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
            coordinates,
            body,
        })
    }

    /// The mass, centre and inertia about the centre of a link's parts, in its frame. Literal
    /// parts meet the `#[rigid]` rules now; a massless link (field masses that are zero) is
    /// the run time's singular mass matrix.
    fn link_parts(
        &mut self,
        keyword: &Ident,
        items: &[Item],
    ) -> Option<(ExprId, [ExprId; 3], [[ExprId; 3]; 3])> {
        let mut description = Description::default();
        let mut ok = true;
        for item in items {
            match item {
                Item::Part { name, keys } => match self.part(name, keys) {
                    Some((part, _)) => {
                        let single = Description {
                            parts: vec![part.clone()],
                            pivot: None,
                        };
                        if let Some(numeric) = evaluate(self.arena, &single)
                            && let Some(p) = numeric.parts.first()
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
        match mass_properties(self.arena, &description) {
            Ok(props) => Some((props.mass, props.center, props.inertia_cm)),
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
                _ => format!("`{} = [a, b, c]`", keys::COORDINATES),
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

    /// The loads of a joint's coordinates: spring, damper and effort, one value each per
    /// coordinate (`[a, b]` for a joint of two).
    fn loads(
        &mut self,
        k: &LinkKeys,
        dof: usize,
        efforts: &mut Vec<UserEffort>,
    ) -> Option<Vec<CoordinateLoad>> {
        let mut loads = vec![CoordinateLoad::default(); dof];
        let mut ok = true;
        if let Some(e) = k.damper {
            match self.per_coordinate(e, dof, keys::DAMPER) {
                Some(values) => {
                    for (load, v) in loads.iter_mut().zip(values) {
                        load.damper = self.non_negative(v, keys::DAMPER);
                        ok &= load.damper.is_some();
                    }
                }
                None => ok = false,
            }
        }
        if let Some(e) = k.effort {
            match self.per_coordinate(e, dof, keys::EFFORT) {
                Some(values) => {
                    for (load, v) in loads.iter_mut().zip(values) {
                        load.effort = self.effort(v, efforts);
                        ok &= load.effort.is_some();
                    }
                }
                None => ok = false,
            }
        }
        if let Some((name, list)) = k.spring {
            let mut stiffness = None;
            let mut rest = None;
            for kv in list {
                let slot = match kv.key.to_string().as_str() {
                    keys::STIFFNESS => &mut stiffness,
                    keys::REST => &mut rest,
                    _ => {
                        let known = [keys::STIFFNESS, keys::REST];
                        self.cx.error_spanned_by(
                            &kv.key,
                            format!(
                                "unknown key `{}` for `{}`: allowed keys are {}, {}{}",
                                kv.key,
                                keys::SPRING,
                                keys::STIFFNESS,
                                keys::REST,
                                keys::did_you_mean(&kv.key.to_string(), known)
                            ),
                        );
                        ok = false;
                        continue;
                    }
                };
                if slot.is_some() {
                    self.cx.error_spanned_by(
                        &kv.key,
                        format!("duplicate key `{}` in `{}`", kv.key, keys::SPRING),
                    );
                    ok = false;
                }
                *slot = Some(&kv.value);
            }
            match stiffness {
                None => {
                    self.cx.error_spanned_by(
                        name,
                        format!(
                            "`{}` needs its stiffness `{} = ..` (the rest value defaults to 0)",
                            keys::SPRING,
                            keys::STIFFNESS
                        ),
                    );
                    ok = false;
                }
                Some(ke) => {
                    let ks = self.per_coordinate(ke, dof, keys::STIFFNESS);
                    let rests = match rest {
                        Some(r) => self.per_coordinate(r, dof, keys::REST),
                        None => None,
                    };
                    match ks {
                        Some(ks) => {
                            for (i, (load, kv)) in loads.iter_mut().zip(ks).enumerate() {
                                let stiffness = self.non_negative(kv, keys::STIFFNESS);
                                let rest = match (&rests, rest) {
                                    (Some(r), _) => r.get(i).and_then(|&r| self.scalar(r)),
                                    (None, None) => Some(self.arena.zero()),
                                    (None, Some(_)) => None,
                                };
                                match (stiffness, rest) {
                                    (Some(stiffness), Some(rest)) => {
                                        load.spring = Some(Spring { stiffness, rest });
                                    }
                                    _ => ok = false,
                                }
                            }
                        }
                        None => ok = false,
                    }
                }
            }
        }
        ok.then_some(loads)
    }

    /// The values of a load key, one per coordinate.
    fn per_coordinate<'e>(&mut self, e: &'e Expr, dof: usize, key: &str) -> Option<Vec<&'e Expr>> {
        if dof == 1 {
            return Some(vec![e]);
        }
        match e {
            Expr::Array(a) if a.elems.len() == dof => Some(a.elems.iter().collect()),
            _ => {
                self.cx.error_spanned_by(
                    e,
                    format!("`{key}` of a joint with {dof} coordinates takes one value per coordinate, `[{}]`", vec!["..";dof].join(", ")),
                );
                None
            }
        }
    }

    /// A coefficient that is a literal must not be negative (a field's sign is the user's).
    fn non_negative(&mut self, e: &Expr, key: &str) -> Option<ExprId> {
        let v = self.scalar(e)?;
        match self.arena.as_rational(v) {
            Some(r) if r.to_f64() < 0.0 => {
                self.cx.error_spanned_by(
                    e,
                    format!("`{key}` must not be negative, got {}", r.to_f64()),
                );
                None
            }
            _ => Some(v),
        }
    }

    /// An effort: a value, or the path of a function `f(&self, t, &q, &qdot) -> f64`. A
    /// single name is a field when the struct has one by that name, else a function.
    fn effort(&mut self, e: &Expr, efforts: &mut Vec<UserEffort>) -> Option<ExprId> {
        let function = match e {
            Expr::Path(p) if p.qself.is_none() => match p.path.get_ident() {
                Some(i) => self.input.field(i).is_none(),
                None => true,
            },
            _ => false,
        };
        if !function {
            return self.scalar(e);
        }
        let Expr::Path(p) = e else { return None };
        let index = efforts.len();
        let symbol = self.arena.input(&format!("effort_user_{index}"));
        efforts.push(UserEffort {
            path: p.path.clone(),
            symbol,
            index,
        });
        Some(symbol)
    }

    /// `gravity = g` (along −z) or `[gx, gy, gz]`.
    fn gravity(&mut self, e: &Expr) -> Option<[ExprId; 3]> {
        if let Expr::Array(_) = e {
            return self.vector(e);
        }
        let g = self.scalar(e)?;
        let z = self.arena.zero();
        Some([z, z, self.arena.neg(g)])
    }

    fn route(&mut self, e: &Expr) -> RouteChoice {
        match path_ident(e).map(|i| i.to_string()).as_deref() {
            Some("auto") => RouteChoice::Auto,
            Some("symbolic") => RouteChoice::Symbolic,
            Some("factored") => RouteChoice::Factored,
            Some("recursive") => RouteChoice::Recursive,
            _ => {
                self.cx.error_spanned_by(
                    e,
                    format!(
                        "`{}` expects one of {}",
                        keys::ROUTE,
                        keys::ROUTES.join(", ")
                    ),
                );
                RouteChoice::Auto
            }
        }
    }
}

/// A joint as read.
struct JointSpec {
    /// `None`: named after its link.
    name: Option<Ident>,
    at: [ExprId; 3],
    kind: JointKind,
}

impl Checker<'_> {
    /// `kind(name = .., axis = .., at = ..)`.
    fn joint(&mut self, e: &Expr) -> Option<JointSpec> {
        const EXPECTED: &str = "expected a joint `revolute(axis = x, at = [x, y, z])`, `prismatic(axis = ..)`, `universal(axes = [x, y])` or `spherical(sequence = zxz)`";
        let (kind_ident, args): (&Ident, Vec<&Expr>) = match e {
            Expr::Call(c) => match path_ident(&c.func) {
                Some(i) => (i, c.args.iter().collect()),
                None => {
                    self.cx.error_spanned_by(e, EXPECTED);
                    return None;
                }
            },
            Expr::Path(_) => match path_ident(e) {
                Some(i) => (i, Vec::new()),
                None => {
                    self.cx.error_spanned_by(e, EXPECTED);
                    return None;
                }
            },
            _ => {
                self.cx.error_spanned_by(e, EXPECTED);
                return None;
            }
        };
        let kind_name = kind_ident.to_string();
        let allowed: &[&str] = match kind_name.as_str() {
            "revolute" | "prismatic" => &[keys::NAME, keys::AXIS, keys::AT],
            "universal" => &[keys::NAME, keys::AXES, keys::AT],
            "spherical" => &[keys::NAME, keys::SEQUENCE, keys::AT],
            _ => {
                self.cx.error_spanned_by(
                    kind_ident,
                    format!(
                        "unknown joint `{kind_name}`: expected one of {}{}",
                        keys::JOINT_KINDS.join(", "),
                        keys::did_you_mean(&kind_name, keys::JOINT_KINDS.iter().copied())
                    ),
                );
                return None;
            }
        };
        let mut given: Vec<(&Ident, &Expr)> = Vec::new();
        let mut ok = true;
        for arg in args {
            let Expr::Assign(a) = arg else {
                self.cx.error_spanned_by(
                    arg,
                    format!(
                        "expected `key = value` in `{kind_name}(...)`: its keys are {}",
                        allowed.join(", ")
                    ),
                );
                ok = false;
                continue;
            };
            let Some(key) = path_ident(&a.left) else {
                self.cx.error_spanned_by(
                    &a.left,
                    format!("expected a key of `{kind_name}`: {}", allowed.join(", ")),
                );
                ok = false;
                continue;
            };
            if !allowed.iter().any(|k| key == k) {
                self.cx.error_spanned_by(
                    key,
                    format!(
                        "unknown key `{key}` for `{kind_name}`: allowed keys are {}{}",
                        allowed.join(", "),
                        keys::did_you_mean(&key.to_string(), allowed.iter().copied())
                    ),
                );
                ok = false;
                continue;
            }
            if given.iter().any(|(g, _)| *g == key) {
                self.cx
                    .error_spanned_by(key, format!("duplicate key `{key}` in `{kind_name}`"));
                ok = false;
                continue;
            }
            given.push((key, &a.right));
        }
        let value = |k: &str| given.iter().find(|(g, _)| *g == k).map(|(_, v)| *v);
        let name = match value(keys::NAME) {
            Some(v) => match path_ident(v) {
                Some(i) => Some(i.clone()),
                None => {
                    self.cx
                        .error_spanned_by(v, "expected the joint's name, such as `shoulder`");
                    None
                }
            },
            None => None,
        };
        let at = match value(keys::AT) {
            Some(v) => self.vector(v),
            None => Some([self.arena.zero(); 3]),
        };
        let kind = match kind_name.as_str() {
            "revolute" | "prismatic" => {
                let axis = match value(keys::AXIS) {
                    Some(v) => self.joint_axis(v),
                    None => {
                        self.cx.error_spanned_by(kind_ident, format!("`{kind_name}` needs its `{}`: `x`, `y`, `z` or `[x, y, z]` in the parent's frame", keys::AXIS));
                        None
                    }
                };
                axis.map(|axis| {
                    if kind_name == "revolute" {
                        JointKind::Revolute { axis }
                    } else {
                        JointKind::Prismatic { axis }
                    }
                })
            }
            "universal" => match value(keys::AXES) {
                Some(Expr::Array(a)) if a.elems.len() == 2 => {
                    let first = a.elems.first().and_then(|x| self.joint_axis(x));
                    let second = a.elems.last().and_then(|x| self.joint_axis(x));
                    Some(JointKind::Universal {
                        axes: [first?, second?],
                    })
                }
                Some(v) => {
                    self.cx.error_spanned_by(v, "expected the two axes of the universal joint, `[outer, inner]`, such as `[x, y]`");
                    None
                }
                None => {
                    self.cx.error_spanned_by(
                        kind_ident,
                        format!(
                            "`universal` needs its `{}`: `[outer, inner]`, such as `[x, y]`",
                            keys::AXES
                        ),
                    );
                    None
                }
            },
            _ => match value(keys::SEQUENCE) {
                None => Some(JointKind::Spherical {
                    sequence: AngleSequence::Zxz,
                }),
                Some(v) => match path_ident(v).map(|i| i.to_string()).as_deref() {
                    Some("zxz") => Some(JointKind::Spherical {
                        sequence: AngleSequence::Zxz,
                    }),
                    Some("zyx") => Some(JointKind::Spherical {
                        sequence: AngleSequence::Zyx,
                    }),
                    _ => {
                        self.cx.error_spanned_by(
                            v,
                            format!(
                                "`{}` expects `zxz` (φ, θ, ψ) or `zyx` (yaw, pitch, roll)",
                                keys::SEQUENCE
                            ),
                        );
                        None
                    }
                },
            },
        };
        if !ok {
            return None;
        }
        if name.is_none() && value(keys::NAME).is_some() {
            return None;
        }
        Some(JointSpec {
            name,
            at: at?,
            kind: kind?,
        })
    }

    /// `x`, `y`, `z` (or negated) or `[x, y, z]`; a literal axis of zero length has no
    /// direction.
    fn joint_axis(&mut self, e: &Expr) -> Option<[ExprId; 3]> {
        let (inner, negated) = match e {
            Expr::Unary(u) if matches!(u.op, syn::UnOp::Neg(_)) => (&*u.expr, true),
            _ => (e, false),
        };
        if let Some(i) = path_ident(inner) {
            let k = match i.to_string().as_str() {
                "x" => 0,
                "y" => 1,
                "z" => 2,
                _ => {
                    // Not an axis name: a field, and the scalar's error says so.
                    self.cx.error_spanned_by(
                        e,
                        "expected an axis `x`, `y`, `z` (or `-x`, …) or a vector `[x, y, z]`",
                    );
                    return None;
                }
            };
            let (z, one) = (self.arena.zero(), self.arena.one());
            let one = if negated { self.arena.neg(one) } else { one };
            let mut axis = [z; 3];
            axis[k] = one;
            return Some(axis);
        }
        if !matches!(e, Expr::Array(_)) {
            self.cx.error_spanned_by(
                e,
                "expected an axis `x`, `y`, `z` (or `-x`, …) or a vector `[x, y, z]`",
            );
            return None;
        }
        let axis = self.vector(e)?;
        let zero = self.arena.zero();
        if axis.iter().all(|&c| self.arena.expand(c) == zero) {
            self.cx.error_spanned_by(
                e,
                "the axis has zero length and so no direction: give a non-zero axis such as [0.0, 0.0, 1.0]",
            );
            return None;
        }
        Some(axis)
    }
}

/// The single identifier a path expression is, if it is one.
fn path_ident(e: &Expr) -> Option<&Ident> {
    match e {
        Expr::Path(p) if p.qself.is_none() => p.path.get_ident(),
        _ => None,
    }
}
