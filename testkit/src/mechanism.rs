//! A mechanism described by numbers alone (joints, masses, loads in f64), and an independent
//! recursive Newton–Euler algorithm over it ([`rnea`]): the reference the mechanism tests
//! check the derived q̈, mass matrix and Jacobians against. Here, optimised, because the
//! tests call it at 10³ states each and unoptimised nalgebra made it their whole run time.
#![warn(missing_docs)]

pub mod rnea;

use precess::nalgebra::Matrix3;
use precess::rigid::AngleSequence;

/// A joint with f64 geometry (axes in the parent's frame, not necessarily unit).
#[derive(Clone, Debug)]
pub enum NumJoint {
    /// A hinge about the axis.
    Revolute([f64; 3]),
    /// A slide along the axis.
    Prismatic([f64; 3]),
    /// A turn about the first axis, then about the second (turned with the first).
    Universal([f64; 3], [f64; 3]),
    /// Three angles of the sequence, each about a body axis.
    Spherical(AngleSequence),
}

impl NumJoint {
    /// How many coordinates the joint has.
    pub fn dof(&self) -> usize {
        match self {
            NumJoint::Revolute(_) | NumJoint::Prismatic(_) => 1,
            NumJoint::Universal(..) => 2,
            NumJoint::Spherical(_) => 3,
        }
    }
}

/// Per-coordinate loads with f64 values.
#[derive(Clone, Copy, Debug, Default)]
pub struct NumLoad {
    /// A linear spring: (stiffness, rest coordinate).
    pub spring: Option<(f64, f64)>,
    /// A linear damper's coefficient.
    pub damper: Option<f64>,
    /// A constant generalised force.
    pub effort: Option<f64>,
}

/// One body: its joint to `parent` (None: the ground) at `at`, and its mass properties in
/// its own frame (inertia about the centre of mass).
#[derive(Clone, Debug)]
pub struct NumBody {
    /// The parent body's index, None for the ground.
    pub parent: Option<usize>,
    /// Where the joint sits, in the parent's frame.
    pub at: [f64; 3],
    /// The joint to the parent.
    pub joint: NumJoint,
    /// The mass.
    pub mass: f64,
    /// The centre of mass in the body's frame.
    pub center: [f64; 3],
    /// The inertia about the centre of mass, body axes.
    pub inertia: Matrix3<f64>,
    /// One load per coordinate of the joint.
    pub loads: Vec<NumLoad>,
    /// A couple fixed in the body's axes.
    pub body_torque: Option<[f64; 3]>,
    /// A couple fixed in ground axes.
    pub space_torque: Option<[f64; 3]>,
}

impl NumBody {
    /// A unit mass with inertia 0.1 I at its joint's origin, no loads.
    pub fn new(parent: Option<usize>, at: [f64; 3], joint: NumJoint) -> NumBody {
        NumBody {
            parent,
            at,
            loads: vec![NumLoad::default(); joint.dof()],
            joint,
            mass: 1.0,
            center: [0.0; 3],
            inertia: Matrix3::identity() * 0.1,
            body_torque: None,
            space_torque: None,
        }
    }
}

/// A tree of bodies under uniform gravity; the coordinates are the joints' in body order.
#[derive(Clone, Debug)]
pub struct NumMechanism {
    /// The bodies (a parent may be listed after its child).
    pub bodies: Vec<NumBody>,
    /// The acceleration of gravity, ground axes.
    pub gravity: [f64; 3],
}

impl NumMechanism {
    /// How many coordinates the mechanism has.
    pub fn dof(&self) -> usize {
        self.bodies.iter().map(|b| b.joint.dof()).sum()
    }
}
