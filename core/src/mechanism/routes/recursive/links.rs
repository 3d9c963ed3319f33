//! A mechanism flattened into a chain-tree of one-degree-of-freedom links, the form both
//! articulated-body algorithms (the symbolic one here and the numeric [`MechanismAba`]) run
//! over.
//!
//! A universal joint becomes two revolutes and a spherical joint three (the elementary axes of
//! its angle sequence), joined through massless intermediate frames: each elementary rotation
//! is about an axis fixed in both the frame before it and the frame after it, which is exactly
//! how the scene defines the joints, so the chain reproduces the joint's kinematics with no
//! extra algebra. The alternative, a 3-dof articulated block, needs a symbolic 3×3 inverse of
//! Sᵀ Iᴬ S per joint; the chain needs three scalar pivots instead, and those pivots are what the
//! singular-mass check wants (the gimbal lock of the Euler angles shows up as a zero pivot,
//! where the mass matrix of those angles is singular too).
//!
//! [`MechanismAba`]: crate::mechanism::MechanismAba

use crate::mechanism::{JointKind, MechanismError, MechanismScene, Parent};
use crate::sym::{Arena, ExprId};

/// How a link moves relative to its parent.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Motion {
    /// A rotation by q about the unit axis.
    Turn,
    /// A translation by q along the unit axis.
    Slide,
}

/// One degree of freedom: a frame that moves relative to its parent link's frame.
#[derive(Clone, Debug)]
pub(crate) struct Link {
    /// The parent link (`None`: the ground).
    pub parent: Option<usize>,
    /// Rotation or translation.
    pub motion: Motion,
    /// The unit axis, the same in the parent's and in this link's frame.
    pub axis: [ExprId; 3],
    /// This frame's origin at zero coordinate, in the parent link's frame.
    pub at: [ExprId; 3],
    /// The coordinate index (state order).
    pub coordinate: usize,
    /// The body whose frame this link is (the last link of each joint), if any.
    pub body: Option<usize>,
}

/// `v / |v|`, exact where |v|² is the square of a rational.
fn normalised(
    arena: &mut Arena,
    v: &[ExprId; 3],
    joint: &str,
) -> Result<[ExprId; 3], MechanismError> {
    let squares: Vec<ExprId> = v.iter().map(|&c| arena.mul(c, c)).collect();
    let norm2 = arena.sum(&squares);
    if norm2 == arena.zero() {
        return Err(MechanismError::ZeroAxis {
            joint: joint.to_owned(),
            squared_length: None,
        });
    }
    if norm2 == arena.one() {
        return Ok(*v);
    }
    let norm = arena.sqrt(norm2)?;
    let inv = arena.powi(norm, -1)?;
    Ok(v.map(|c| arena.mul(c, inv)))
}

/// The unit vector along elementary axis `k` (0 = x, 1 = y, 2 = z).
fn unit(arena: &Arena, k: usize) -> [ExprId; 3] {
    let mut e = [arena.zero(); 3];
    if let Some(c) = e.get_mut(k) {
        *c = arena.one();
    }
    e
}

/// The links of `scene`, parents before children, and per body the index of its last link.
///
/// # Errors
/// As [`MechanismScene::validate`] (the one rule for a well-formed tree, whatever the
/// route), and [`MechanismError::ZeroAxis`] for an axis that is identically zero.
pub(crate) fn flatten(
    arena: &mut Arena,
    scene: &MechanismScene,
) -> Result<(Vec<Link>, Vec<usize>), MechanismError> {
    let order = scene.validate(arena)?;
    let mut first_coordinate = Vec::with_capacity(scene.bodies.len());
    let mut next = 0;
    for b in &scene.bodies {
        first_coordinate.push(next);
        next += b.joint.kind.dof();
    }
    let zero = arena.zero();
    let mut links: Vec<Link> = Vec::with_capacity(scene.dof());
    let mut body_link = vec![usize::MAX; scene.bodies.len()];
    for &i in &order {
        let b = &scene.bodies[i];
        let joint = &b.joint;
        let mut parent = match joint.parent {
            Parent::Ground => None,
            Parent::Body(p) => Some(body_link[p]),
        };
        let axes: Vec<(Motion, [ExprId; 3])> = match &joint.kind {
            JointKind::Revolute { axis } => {
                vec![(Motion::Turn, normalised(arena, axis, &joint.name)?)]
            }
            JointKind::Prismatic { axis } => {
                vec![(Motion::Slide, normalised(arena, axis, &joint.name)?)]
            }
            JointKind::Universal { axes } => vec![
                (Motion::Turn, normalised(arena, &axes[0], &joint.name)?),
                (Motion::Turn, normalised(arena, &axes[1], &joint.name)?),
            ],
            JointKind::Spherical { sequence } => sequence
                .axes()
                .iter()
                .map(|&k| (Motion::Turn, unit(arena, k)))
                .collect(),
            // Three slides along the parent's axes (a slide leaves the frame's axes where
            // they were, so each is along the parent's), then the spherical joint's turns.
            JointKind::Free { sequence } => (0..3)
                .map(|k| (Motion::Slide, unit(arena, k)))
                .chain(
                    sequence
                        .axes()
                        .iter()
                        .map(|&k| (Motion::Turn, unit(arena, k))),
                )
                .collect(),
        };
        let last = axes.len() - 1;
        for (k, (motion, axis)) in axes.into_iter().enumerate() {
            links.push(Link {
                parent,
                motion,
                axis,
                at: if k == 0 { joint.at } else { [zero; 3] },
                coordinate: first_coordinate[i] + k,
                body: (k == last).then_some(i),
            });
            parent = Some(links.len() - 1);
        }
        body_link[i] = links.len() - 1;
    }
    Ok((links, body_link))
}
