//! The tree's rules on the bodies as read: names unique, parents known, every chain of
//! parents ending at the ground, and a free joint only on the one base body.

use precess_core::mechanism::{JointKind, Parent};

use super::check::LinkSpec;
use crate::lang::check::Checker;
use crate::lang::keys;

/// The parent of each link: names unique, parents known, every chain reaching the ground.
pub(super) fn tree(ck: &Checker, specs: &[LinkSpec]) -> Option<Vec<Parent>> {
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
    free_joints(ck, specs, &parents);
    (ck.cx.error_count() == errors_before).then_some(parents)
}

/// A free joint flies the base body: it hangs from the ground, and there is one at most
/// (the rules of `MechanismScene::validate`, spanned on the joint).
fn free_joints(ck: &Checker, specs: &[LinkSpec], parents: &[Parent]) {
    let mut first: Option<&LinkSpec> = None;
    for (spec, parent) in specs.iter().zip(parents) {
        if !matches!(spec.body.joint.kind, JointKind::Free { .. }) {
            continue;
        }
        if let (Parent::Body(_), Some(p)) = (parent, spec.parent) {
            ck.cx.error_spanned_by(
                &spec.joint_kind,
                format!(
                    "a `free` joint attaches the base body to `{}`, but `{}` hangs from `{p}`: give it `{} = {}`, or join it to `{p}` by a spherical, universal, revolute or prismatic joint",
                    keys::GROUND,
                    spec.name,
                    keys::PARENT,
                    keys::GROUND
                ),
            );
            continue;
        }
        match first {
            Some(f) => ck.cx.error_spanned_by(
                &spec.joint_kind,
                format!(
                    "a second `free` joint: `{}` already flies free, and a mechanism has one base body; join `{}` to the mechanism's bodies by another joint",
                    f.name, spec.name
                ),
            ),
            None => first = Some(spec),
        }
    }
}
