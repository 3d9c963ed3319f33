//! The description of a mechanism: a tree of rigid bodies, each joined to its parent (or the
//! ground) by one joint, and the loads declared on it. Everything is symbolic (`ExprId`s of
//! one [`Arena`]), so literals stay exact and `f64` fields are parameters.
//!
//! # Frames
//!
//! - The ground frame is inertial. Every body has a frame of its own; its parts (mass,
//!   centre, inertia) are described in it.
//! - A joint sits at `at` in its parent's frame (the ground frame for the ground). At zero
//!   coordinates the child's frame is the parent's frame translated to `at`; the joint then
//!   moves it: a revolute turns it by q about `axis`, a prismatic slides it by q along `axis`,
//!   a universal turns it by q₁ about `axes[0]` and then by q₂ about `axes[1]` (the second
//!   axis in the once-turned frame), a spherical turns it by the Euler angles of `sequence`,
//!   and a free joint slides it by (x, y, z) along the parent's axes and then turns it by the
//!   Euler angles of `sequence` (six coordinates: a base body flying free of the ground).
//! - Axes are in the parent's frame and need not be unit vectors (they are normalised).

use crate::rigid::AngleSequence;
use crate::sym::mat3::Mat3;
use crate::sym::{Arena, ExprId};

/// Where a joint attaches.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Parent {
    /// The inertial ground frame.
    Ground,
    /// Another body of the mechanism, by its index in [`MechanismScene::bodies`].
    Body(usize),
}

/// The kind of a joint and its geometry, in the parent's frame.
#[derive(Clone, Debug, PartialEq)]
pub enum JointKind {
    /// One rotation about `axis` (one coordinate, an angle).
    Revolute {
        /// The rotation axis.
        axis: [ExprId; 3],
    },
    /// One translation along `axis` (one coordinate, a length).
    Prismatic {
        /// The sliding direction.
        axis: [ExprId; 3],
    },
    /// Two rotations, about `axes[0]` and then about `axes[1]` of the turned frame (a gimbal;
    /// two coordinates).
    Universal {
        /// The outer and the inner axis.
        axes: [[ExprId; 3]; 2],
    },
    /// Three Euler angles of `sequence` (three coordinates), singular where the sequence is.
    Spherical {
        /// The angle sequence (the tops' [`AngleSequence`]).
        sequence: AngleSequence,
    },
    /// Six coordinates: the body frame's origin slides by (x, y, z) along the parent's axes
    /// (the ground's, since a free joint attaches a base body to the ground), then turns by
    /// the three Euler angles of `sequence`, charted and re-charted as a spherical joint's
    /// are. A free-floating mechanism: a satellite with a panel, a thrown linkage.
    Free {
        /// The angle sequence of the three rotations.
        sequence: AngleSequence,
    },
}

impl JointKind {
    /// How many coordinates the joint has.
    pub fn dof(&self) -> usize {
        match self {
            JointKind::Revolute { .. } | JointKind::Prismatic { .. } => 1,
            JointKind::Universal { .. } => 2,
            JointKind::Spherical { .. } => 3,
            JointKind::Free { .. } => 6,
        }
    }

    /// The kinds' names in the attribute language (`joint = revolute(..)`): the one list,
    /// which the derive reads too.
    pub const NAMES: [&'static str; 5] =
        ["revolute", "prismatic", "universal", "spherical", "free"];

    /// The kind's name in the attribute language, one of [`JointKind::NAMES`].
    pub fn name(&self) -> &'static str {
        match self {
            JointKind::Revolute { .. } => JointKind::NAMES[0],
            JointKind::Prismatic { .. } => JointKind::NAMES[1],
            JointKind::Universal { .. } => JointKind::NAMES[2],
            JointKind::Spherical { .. } => JointKind::NAMES[3],
            JointKind::Free { .. } => JointKind::NAMES[4],
        }
    }

    /// The Euler-angle sequence and the offset of the first angle among the joint's
    /// coordinates, for the joints whose rotation is three Euler angles (spherical: 0,
    /// free: 3, after its translations); `None` for the others.
    pub fn euler_angles(&self) -> Option<(AngleSequence, usize)> {
        match self {
            JointKind::Spherical { sequence } => Some((*sequence, 0)),
            JointKind::Free { sequence } => Some((*sequence, 3)),
            _ => None,
        }
    }
}

/// A linear spring on one joint coordinate: the generalised force −k (q − rest).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spring {
    /// The stiffness k ≥ 0 (N·m/rad or N/m).
    pub stiffness: ExprId,
    /// The rest value of the coordinate.
    pub rest: ExprId,
}

/// What acts along one joint coordinate. Undeclared terms contribute nothing at all.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CoordinateLoad {
    /// A spring −k (q − rest).
    pub spring: Option<Spring>,
    /// A damper −c q̇ (c ≥ 0).
    pub damper: Option<ExprId>,
    /// A generalised force (torque for an angle, force for a length): a parameter or the
    /// input symbol of a user function's value.
    pub effort: Option<ExprId>,
}

/// A joint: how a body hangs from its parent.
#[derive(Clone, Debug, PartialEq)]
pub struct Joint {
    /// The joint's name (unique in the mechanism).
    pub name: String,
    /// What it attaches to.
    pub parent: Parent,
    /// Where it sits, in the parent's frame.
    pub at: [ExprId; 3],
    /// Its kind and axes.
    pub kind: JointKind,
    /// The names of its coordinates, `kind.dof()` of them, unique in the mechanism.
    pub coordinates: Vec<String>,
    /// The load on each coordinate, `kind.dof()` of them.
    pub loads: Vec<CoordinateLoad>,
}

/// One rigid body of a mechanism with the joint that attaches it.
#[derive(Clone, Debug, PartialEq)]
pub struct MechanismBody {
    /// The body's name (unique in the mechanism).
    pub name: String,
    /// Its mass m ≥ 0 (a massless body is allowed; a singular mass matrix is an error at
    /// run time).
    pub mass: ExprId,
    /// Its centre of mass, in its own frame.
    pub center: [ExprId; 3],
    /// Its inertia tensor about the centre of mass, in its own frame.
    pub inertia: Mat3,
    /// The joint to its parent.
    pub joint: Joint,
    /// A torque fixed in the body (its own axes), if declared.
    pub body_torque: Option<[ExprId; 3]>,
    /// A torque fixed in space (ground axes), if declared.
    pub space_torque: Option<[ExprId; 3]>,
}

/// A tree of rigid bodies and what acts on it.
#[derive(Clone, Debug, PartialEq)]
pub struct MechanismScene {
    /// The bodies, in any order; parents are named by index.
    pub bodies: Vec<MechanismBody>,
    /// Uniform gravity g in ground axes (each weight m g acts at its centre of mass).
    pub gravity: Option<[ExprId; 3]>,
}

impl MechanismScene {
    /// An empty mechanism without gravity.
    pub fn new() -> MechanismScene {
        MechanismScene {
            bodies: Vec::new(),
            gravity: None,
        }
    }

    /// The number of coordinates (the sum of the joints' degrees of freedom).
    pub fn dof(&self) -> usize {
        self.bodies.iter().map(|b| b.joint.kind.dof()).sum()
    }

    /// The coordinate names in state order: body by body as listed, each joint's in order.
    pub fn coordinate_names(&self) -> Vec<&str> {
        self.bodies
            .iter()
            .flat_map(|b| b.joint.coordinates.iter().map(String::as_str))
            .collect()
    }

    /// A body whose frame is its parent's at zero coordinates, its centre at its origin and
    /// no load on its joint: set the fields to describe it.
    pub fn body(
        arena: &mut Arena,
        name: &str,
        parent: Parent,
        kind: JointKind,
        coordinates: &[&str],
    ) -> MechanismBody {
        let z = arena.zero();
        MechanismBody {
            name: name.to_owned(),
            mass: z,
            center: [z; 3],
            inertia: [[z; 3]; 3],
            joint: Joint {
                name: name.to_owned(),
                parent,
                at: [z; 3],
                loads: vec![CoordinateLoad::default(); kind.dof()],
                kind,
                coordinates: coordinates.iter().map(|&c| c.to_owned()).collect(),
            },
            body_torque: None,
            space_torque: None,
        }
    }
}

impl Default for MechanismScene {
    fn default() -> MechanismScene {
        MechanismScene::new()
    }
}
