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
    /// Viscous friction scaled by the normal force, F = −μ N u (μ in s/m): the tippe top's
    /// law of Rauch-Wojciechowski and of Cohen 1977's "viscous-type" friction. Unlike
    /// Coulomb's it is smooth where the slip stops, so a sliding run needs no stick.
    NormalViscous(ExprId),
}

/// Torques on a body on a table beyond its law's friction: resistances at the contact
/// against its turning, and a couple supplied at run time. Each acts in every phase the law
/// derives (rolling and sliding alike under stick–slip).
///
/// - rolling resistance −c_r ω_∥ and spin resistance −c_s ω_⊥, ω_⊥ = (ω·γ) γ the spin about
///   the vertical and ω_∥ = ω − ω_⊥ (linear, in N·m·s);
/// - pivoting friction −ℓ_p N sign(ω·γ) γ, ℓ_p = μ_p r_p (a length: the pivoting
///   coefficient times the radius of the contact patch): Coulomb's law for the spin, so it
///   stops a spin in finite time (Leine & Glocker; Le Saux, Leine & Glocker 2005);
/// - a user couple: three input symbols (description axes) the run supplies.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ContactTorques {
    /// Rolling resistance c_r, if declared.
    pub rolling_resistance: Option<ExprId>,
    /// Spin resistance c_s, if declared.
    pub spin_resistance: Option<ExprId>,
    /// Pivoting friction ℓ_p = μ_p r_p, if declared.
    pub pivoting: Option<ExprId>,
    /// A couple supplied at run time, description axes, as three input symbols.
    pub user: Option<[ExprId; 3]>,
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

/// The mode of a run of a body on a table: the phase of the contact and whether pivoting
/// friction holds the spin about the vertical at zero.
///
/// With the spin held the phase's equations are those of the phase with the constraint
/// ω·γ = 0 added, kept by a pivot couple λγ whose value solves the equations with it
/// (`pivot.rs`); the mode lasts while |λ| ≤ ℓ_p N.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ContactMode {
    /// The phase of the contact.
    pub phase: Phase,
    /// Whether the spin ω·γ is held at zero by pivoting friction.
    pub spin_held: bool,
}

impl ContactMode {
    /// `phase` with the spin free.
    pub fn free(phase: Phase) -> Self {
        Self {
            phase,
            spin_held: false,
        }
    }

    /// `phase` with the spin held at zero.
    pub fn held(phase: Phase) -> Self {
        Self {
            phase,
            spin_held: true,
        }
    }
}

impl From<Phase> for ContactMode {
    fn from(phase: Phase) -> Self {
        Self::free(phase)
    }
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

/// The coefficients of a law and its further torques by the names the run-time rule
/// ([`super::ContactValues`]) and the messages give them, in one order for the interpreted
/// model and the derive: the law's friction (`mu`, `viscous`, `normal_viscous`), then
/// `rolling_resistance`, `spin_resistance`, `pivoting`.
pub fn coefficients(law: &ContactLaw, torques: &ContactTorques) -> Vec<(&'static str, ExprId)> {
    let friction = match *law {
        ContactLaw::Sliding(Friction::Viscous(c)) => Some(("viscous", c)),
        ContactLaw::Sliding(Friction::NormalViscous(mu)) => Some(("normal_viscous", mu)),
        ContactLaw::Sliding(Friction::Coulomb(mu)) | ContactLaw::StickSlip { mu } => {
            Some(("mu", mu))
        }
        ContactLaw::Sliding(Friction::Frictionless) | ContactLaw::Rolling { .. } => None,
    };
    // A rolling law's own resistances are the torques' once merged; before, they are read
    // from the law.
    let (rolling, spin) = match *law {
        ContactLaw::Rolling {
            rolling_resistance,
            spin_resistance,
        } => (
            rolling_resistance.or(torques.rolling_resistance),
            spin_resistance.or(torques.spin_resistance),
        ),
        _ => (torques.rolling_resistance, torques.spin_resistance),
    };
    friction
        .into_iter()
        .chain(
            [
                ("rolling_resistance", rolling),
                ("spin_resistance", spin),
                ("pivoting", torques.pivoting),
            ]
            .into_iter()
            .filter_map(|(n, c)| c.map(|c| (n, c))),
        )
        .collect()
}
