//! A free body, described: its mass and principal moments and the forces and torques it
//! declares, as expressions (`derivation.rs` derives its equations).

use super::wrench::WrenchInputs;
use crate::rigid::{DrivenRotor, Rotor};
use crate::sym::mat3::Mat3;
use crate::sym::{Arena, ExprId};

/// Where a force acts on the body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ForcePoint {
    /// Through the centre of mass: the force makes no torque about it.
    Center,
    /// At a point of the body, in description coordinates (where the parts are placed).
    Body([ExprId; 3]),
}

/// A force applied at a point of the body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AppliedForce {
    /// The force: in description axes for a body-fixed force, in space axes for a
    /// space-fixed one.
    pub force: [ExprId; 3],
    /// Where it acts.
    pub at: ForcePoint,
}

/// A free body and what acts on it. Undeclared forces and torques (`None`, empty lists)
/// contribute no terms at all.
///
/// Frames: the body is described in description axes; its principal axes (about the
/// centre of mass) are `principal_rotation` away (principal → description, columns the
/// principal axes). The state's attitude and ω are principal.
#[derive(Clone, Debug, PartialEq)]
pub struct FreeScene {
    /// Total mass M.
    pub mass: ExprId,
    /// Centre of mass, description axes.
    pub center: [ExprId; 3],
    /// Principal moments about the centre of mass.
    pub moments: [ExprId; 3],
    /// From principal to description axes.
    pub principal_rotation: Mat3,
    /// Uniform gravity g, space axes (the weight M g acts at the centre of mass).
    pub gravity: Option<[ExprId; 3]>,
    /// Forces fixed in the body (description axes) at body points: thrusters.
    pub body_forces: Vec<AppliedForce>,
    /// Forces fixed in space (space axes) at body points.
    pub space_forces: Vec<AppliedForce>,
    /// A constant torque fixed in the body (description axes).
    pub body_torque: Option<[ExprId; 3]>,
    /// A constant torque fixed in space (space axes).
    pub space_torque: Option<[ExprId; 3]>,
    /// Linear drag on the centre of mass: the force −c v.
    pub drag: Option<ExprId>,
    /// Linear damping of the rotation: the torque −c ω.
    pub damping: Option<ExprId>,
    /// A force supplied at run time, space axes, as three input symbols.
    pub user_force: Option<[ExprId; 3]>,
    /// A torque about the centre of mass supplied at run time, description axes, as three
    /// input symbols.
    pub user_torque: Option<[ExprId; 3]>,
    /// A wrench supplied at run time (an [`super::AppliedWrench`] resolved into its four
    /// parts): forces through the centre of mass and torques about it, in space and in
    /// description axes.
    pub user_wrench: Option<WrenchInputs>,
    /// Internal rotors spinning at constant rates relative to the body: the body is then a
    /// gyrostat (see [`Rotor`]).
    pub rotors: Vec<Rotor>,
    /// Internal rotors turned by motor torques: each one's relative rate is a state slot
    /// after the 13 of [`super::layout`], in this order (see [`DrivenRotor`]).
    pub driven: Vec<DrivenRotor>,
}

impl FreeScene {
    /// A torque-free body with the given mass and principal moments, its principal axes along
    /// the description axes and its centre of mass at the description origin; set the other
    /// fields to declare forces.
    pub fn new(arena: &mut Arena, mass: ExprId, moments: [ExprId; 3]) -> FreeScene {
        let (z, o) = (arena.zero(), arena.one());
        FreeScene {
            mass,
            center: [z; 3],
            moments,
            principal_rotation: [[o, z, z], [z, o, z], [z, z, o]],
            gravity: None,
            body_forces: Vec::new(),
            space_forces: Vec::new(),
            body_torque: None,
            space_torque: None,
            drag: None,
            damping: None,
            user_force: None,
            user_torque: None,
            user_wrench: None,
            rotors: Vec::new(),
            driven: Vec::new(),
        }
    }

    /// True when nothing but uniform gravity is declared: the centre of mass then follows a
    /// parabola and the attitude the torque-free flow, both known exactly.
    pub fn is_exact(&self) -> bool {
        self.declared_beyond_gravity().is_none()
    }

    /// The first declared term other than gravity, by its name in the attribute language.
    pub fn declared_beyond_gravity(&self) -> Option<&'static str> {
        [
            (!self.body_forces.is_empty(), "a body force"),
            (!self.space_forces.is_empty(), "a space force"),
            (self.body_torque.is_some(), "a body torque"),
            (self.space_torque.is_some(), "a space torque"),
            (self.drag.is_some(), "drag"),
            (self.damping.is_some(), "damping"),
            (self.user_force.is_some(), "a user force"),
            (self.user_torque.is_some(), "a user torque"),
            (self.user_wrench.is_some(), "a user wrench"),
            (!self.rotors.is_empty(), "a rotor"),
            (!self.driven.is_empty(), "a driven rotor"),
        ]
        .into_iter()
        .find_map(|(declared, name)| declared.then_some(name))
    }
}
