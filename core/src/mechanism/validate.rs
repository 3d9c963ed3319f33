//! Checks that a [`MechanismScene`] describes a tree the engine can derive, and orders its
//! bodies parents first.

use std::collections::HashSet;

use super::error::MechanismError;
use super::rules::{check_axis, check_universal_axes};
use super::scene::{Joint, JointKind, MechanismScene, Parent};
use crate::sym::{Arena, ExprId};

impl MechanismScene {
    /// Checks the tree and returns the bodies' indices in topological order (every parent
    /// before its children; ties in listed order).
    ///
    /// Checked: at least one joint; every coordinate and load count equals the joint's
    /// degrees of freedom; body, joint and coordinate names are unique; every parent exists;
    /// the parents form no cycle; no axis is identically zero, and axes of constants meet
    /// [`crate::mechanism::check_axis`] and, for a universal joint,
    /// [`crate::mechanism::check_universal_axes`] (axes of parameters are checked for their
    /// values by the run-time model, by the same functions); a free joint hangs from the
    /// ground, and there is at most one.
    ///
    /// # Errors
    /// [`MechanismError::NoMovingJoint`], [`MechanismError::WrongCoordinateCount`],
    /// [`MechanismError::WrongLoadCount`], [`MechanismError::DuplicateName`],
    /// [`MechanismError::UnknownParent`], [`MechanismError::Cycle`],
    /// [`MechanismError::ZeroAxis`], [`MechanismError::ParallelAxes`],
    /// [`MechanismError::FreeJointNotOnGround`], [`MechanismError::SecondFreeJoint`], each
    /// naming the body,
    /// joint or coordinate.
    ///
    /// # Examples
    ///
    /// ```
    /// use precess_core::mechanism::{JointKind, MechanismError, MechanismScene, Parent};
    /// use precess_core::sym::Arena;
    /// let mut a = Arena::new();
    /// let (o, z) = (a.one(), a.zero());
    /// let hinge = JointKind::Revolute { axis: [z, z, o] };
    /// let mut scene = MechanismScene::new();
    /// scene.bodies.push(MechanismScene::body(&mut a, "upper", Parent::Ground, hinge.clone(), &["q1"]));
    /// scene.bodies.push(MechanismScene::body(&mut a, "lower", Parent::Body(0), hinge, &["q2"]));
    /// assert_eq!(scene.validate(&a)?, vec![0, 1]);
    /// // The upper body hung from the lower one closes a loop.
    /// scene.bodies[0].joint.parent = Parent::Body(1);
    /// assert!(matches!(scene.validate(&a), Err(MechanismError::Cycle { .. })));
    /// # Ok::<(), MechanismError>(())
    /// ```
    pub fn validate(&self, arena: &Arena) -> Result<Vec<usize>, MechanismError> {
        if self.bodies.is_empty() {
            return Err(MechanismError::NoMovingJoint);
        }
        let mut bodies = HashSet::new();
        let mut joints = HashSet::new();
        let mut coordinates = HashSet::new();
        for body in &self.bodies {
            let joint = &body.joint;
            let (kind, expected) = (joint.kind.name(), joint.kind.dof());
            if joint.coordinates.len() != expected {
                return Err(MechanismError::WrongCoordinateCount {
                    joint: joint.name.clone(),
                    kind,
                    expected,
                    got: joint.coordinates.len(),
                });
            }
            if joint.loads.len() != expected {
                return Err(MechanismError::WrongLoadCount {
                    joint: joint.name.clone(),
                    kind,
                    expected,
                    got: joint.loads.len(),
                });
            }
            let duplicate = |kind, name: &str| MechanismError::DuplicateName {
                kind,
                name: name.to_owned(),
            };
            if !bodies.insert(body.name.as_str()) {
                return Err(duplicate("body", &body.name));
            }
            if !joints.insert(joint.name.as_str()) {
                return Err(duplicate("joint", &joint.name));
            }
            for c in &joint.coordinates {
                if !coordinates.insert(c.as_str()) {
                    return Err(duplicate("coordinate", c));
                }
            }
            if let Parent::Body(p) = joint.parent
                && p >= self.bodies.len()
            {
                return Err(MechanismError::UnknownParent {
                    body: body.name.clone(),
                    parent: p,
                    count: self.bodies.len(),
                });
            }
            literal_axes(arena, joint)?;
        }
        self.free_joints()?;
        self.topological_order()
    }

    /// A free joint flies its body free of the ground: it must hang from the ground (a body
    /// free of another body is a second tree, or a six-coordinate joint the engine does not
    /// chart), and there is at most one, the base body's (two would be two mechanisms).
    fn free_joints(&self) -> Result<(), MechanismError> {
        let mut first: Option<&str> = None;
        for body in &self.bodies {
            let joint = &body.joint;
            if !matches!(joint.kind, JointKind::Free { .. }) {
                continue;
            }
            if let Parent::Body(p) = joint.parent {
                return Err(MechanismError::FreeJointNotOnGround {
                    joint: joint.name.clone(),
                    parent: self
                        .bodies
                        .get(p)
                        .map_or_else(|| p.to_string(), |b| b.name.clone()),
                });
            }
            if let Some(first) = first {
                return Err(MechanismError::SecondFreeJoint {
                    first: first.to_owned(),
                    second: joint.name.clone(),
                });
            }
            first = Some(&joint.name);
        }
        Ok(())
    }

    /// Parents before children, by repeated sweeps (trees are shallow next to the cost of
    /// deriving them); what never becomes placeable lies on or under a cycle.
    fn topological_order(&self) -> Result<Vec<usize>, MechanismError> {
        let n = self.bodies.len();
        let mut placed = vec![false; n];
        let mut order = Vec::with_capacity(n);
        loop {
            let before = order.len();
            for (i, body) in self.bodies.iter().enumerate() {
                let ready = match body.joint.parent {
                    Parent::Ground => true,
                    Parent::Body(p) => placed.get(p).copied().unwrap_or(false),
                };
                if !placed[i] && ready {
                    placed[i] = true;
                    order.push(i);
                }
            }
            if order.len() == n {
                return Ok(order);
            }
            if order.len() == before {
                return Err(MechanismError::Cycle {
                    bodies: self.cycle_from(&placed),
                });
            }
        }
    }

    /// The bodies of one cycle: walk parents from an unplaced body until one repeats.
    fn cycle_from(&self, placed: &[bool]) -> Vec<String> {
        let Some(start) = placed.iter().position(|&p| !p) else {
            return Vec::new();
        };
        let mut path = vec![start];
        let mut at = start;
        while let Some(Parent::Body(p)) = self.bodies.get(at).map(|b| b.joint.parent) {
            if let Some(first) = path.iter().position(|&b| b == p) {
                return path[first..]
                    .iter()
                    .map(|&b| self.bodies[b].name.clone())
                    .collect();
            }
            path.push(p);
            at = p;
        }
        path.iter().map(|&b| self.bodies[b].name.clone()).collect()
    }
}

/// The axis rules for a joint's axes made of constants: a zero axis is refused whatever it
/// is made of, the rest of the rules need values.
fn literal_axes(arena: &Arena, joint: &Joint) -> Result<(), MechanismError> {
    let zero = |axis: &[ExprId; 3]| axis.iter().all(|&e| e == arena.zero());
    let value = |axis: &[ExprId; 3]| -> Option<[f64; 3]> {
        let mut out = [0.0; 3];
        for (o, &e) in out.iter_mut().zip(axis) {
            *o = arena.as_rational(e)?.to_f64();
        }
        Some(out)
    };
    let name = joint.name.as_str();
    let axes: &[[ExprId; 3]] = match &joint.kind {
        JointKind::Revolute { axis } | JointKind::Prismatic { axis } => std::slice::from_ref(axis),
        JointKind::Universal { axes } => axes,
        JointKind::Spherical { .. } | JointKind::Free { .. } => &[],
    };
    if axes.iter().any(zero) {
        return Err(MechanismError::ZeroAxis {
            joint: name.to_owned(),
            squared_length: None,
        });
    }
    match (
        &joint.kind,
        axes.iter().map(value).collect::<Vec<_>>().as_slice(),
    ) {
        (JointKind::Universal { .. }, [Some(outer), Some(inner)]) => {
            check_universal_axes(name, *outer, *inner)
        }
        (_, values) => values
            .iter()
            .flatten()
            .try_for_each(|&v| check_axis(name, "axis", v)),
    }
}
