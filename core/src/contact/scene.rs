//! A body on a table, described: its mass properties, the surface it touches the table with,
//! the law of the contact and gravity, as expressions (`derivation.rs` derives its equations).

use crate::rigid::Surface;
use crate::sym::ExprId;
use crate::sym::mat3::Mat3;

/// The friction of a sliding contact: the tangential force on the body at the contact point,
/// against the slip velocity u of the contact point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Friction {
    /// No tangential force: the body glides on an ideal table.
    Frictionless,
    /// Viscous friction F = −c u (the tippe top's model of Cohen 1977 and Or 1994).
    Viscous(ExprId),
    /// Coulomb friction F = −μ N u/|u| while sliding.
    Coulomb(ExprId),
}

/// How the body and the table meet at the contact point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ContactLaw {
    /// Rolling without slip: the contact point of the body is at rest (a nonholonomic
    /// constraint). Optional resistances are torques against the rolling (ω in the table's
    /// plane) and the spin (ω about the vertical): −c_r ω_∥ and −c_s ω_⊥.
    Rolling {
        /// Rolling resistance c_r (torque per rad/s), if declared.
        rolling_resistance: Option<ExprId>,
        /// Spin resistance c_s (torque per rad/s), if declared.
        spin_resistance: Option<ExprId>,
    },
    /// Sliding under a friction law; the normal force keeps the body on the table.
    Sliding(Friction),
    /// Coulomb friction of coefficient μ with stick–slip: the body rolls while the friction
    /// it needs is within μ N and slides otherwise; the switches are events.
    StickSlip {
        /// The friction coefficient μ ≥ 0 (static and kinetic alike).
        mu: ExprId,
    },
}

/// A rigid body resting on a horizontal table (the plane z = 0 of space, gravity along −z),
/// touching it at one point of a convex surface fixed in the body.
///
/// Frames: everything is in description axes (where the parts are placed); the state's
/// attitude turns description axes into space axes and its ω is in description axes.
#[derive(Clone, Debug, PartialEq)]
pub struct ContactScene {
    /// Total mass M.
    pub mass: ExprId,
    /// Centre of mass, description axes.
    pub center: [ExprId; 3],
    /// Inertia tensor about the centre of mass, description axes (full, symmetric: the
    /// rattleback's product of inertia is an off-diagonal entry).
    pub inertia: Mat3,
    /// The surface the body touches the table with.
    pub surface: Surface,
    /// The contact law.
    pub law: ContactLaw,
    /// Gravity g along −z in space.
    pub gravity: ExprId,
}

/// The phase of a contact: which constraint holds at the contact point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Phase {
    /// The contact point is at rest (rolling without slip).
    Rolling,
    /// The contact point slides under the law's friction.
    Sliding,
}

/// The contact law without its coefficients: what a run needs to know of it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LawKind {
    /// Rolling without slip throughout ([`Phase::Rolling`] only).
    Rolling,
    /// Sliding throughout ([`Phase::Sliding`] only).
    Sliding,
    /// Coulomb stick–slip: both phases, switched at events.
    StickSlip,
}

impl LawKind {
    /// The law's name in the attribute language.
    pub fn name(self) -> &'static str {
        match self {
            LawKind::Rolling => "rolling",
            LawKind::Sliding => "sliding",
            LawKind::StickSlip => "stick_slip",
        }
    }

    /// Whether the law derives the equations of `phase`.
    pub fn has(self, phase: Phase) -> bool {
        matches!(
            (self, phase),
            (LawKind::Rolling, Phase::Rolling)
                | (LawKind::Sliding, Phase::Sliding)
                | (LawKind::StickSlip, _)
        )
    }

    /// The phase a run starts in when none is asked for: rolling for the rolling and
    /// stick–slip laws, sliding for the sliding law.
    pub fn first_phase(self) -> Phase {
        match self {
            LawKind::Sliding => Phase::Sliding,
            _ => Phase::Rolling,
        }
    }
}
