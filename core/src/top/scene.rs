//! A top about a fixed pivot, described: its body, the torques it declares and its internal
//! rotors, as expressions (`derivation.rs` derives its equations).

use crate::rigid::AngleSequence;
use crate::rigid::{Rotor, total_momentum};
use crate::sym::mat3::{Mat3, mat_vec, transpose};
use crate::sym::{Arena, ExprId, SymError};

/// A top: a rigid body turning about a fixed pivot at the space origin, under the torques
/// the scene declares. Undeclared torques (`None`) contribute no terms at all.
///
/// Every quantity is an expression, so literals fold and parameters stay symbolic.
#[derive(Clone, Debug, PartialEq)]
pub struct TopScene {
    /// The Euler-angle sequence of the generalised coordinates.
    pub sequence: AngleSequence,
    /// Inertia tensor about the pivot, in body axes.
    pub inertia: Mat3,
    /// Total mass M.
    pub mass: ExprId,
    /// Centre of mass relative to the pivot, in body axes.
    pub center: [ExprId; 3],
    /// Gravity g along −z in space, if declared.
    pub gravity: Option<ExprId>,
    /// A constant torque fixed in the body (body axes).
    pub body_torque: Option<[ExprId; 3]>,
    /// A constant torque fixed in space (space axes).
    pub space_torque: Option<[ExprId; 3]>,
    /// Linear damping: the torque −c ω (body axes).
    pub damping: Option<ExprId>,
    /// A torque supplied at run time, in body axes, as three input symbols.
    pub user_torque: Option<[ExprId; 3]>,
    /// Internal rotors at constant relative rates, which make the top a gyrostat: their
    /// relative momentum h = Σ J Ω â (body axes) adds ω·h to the Lagrangian and turns
    /// Euler's gyroscopic term into ω × (I ω + h). The inertia includes the wheels as if
    /// locked. Empty: the equations are exactly those of a top without rotors.
    pub rotors: Vec<Rotor>,
}

impl TopScene {
    /// A torque-free top with the given inertia about the pivot (mass 1, centre at the
    /// pivot); set the other fields to declare torques.
    pub fn free(arena: &mut Arena, inertia: Mat3) -> TopScene {
        let z = arena.zero();
        TopScene {
            sequence: AngleSequence::Zxz,
            inertia,
            mass: arena.one(),
            center: [z; 3],
            gravity: None,
            body_torque: None,
            space_torque: None,
            damping: None,
            user_torque: None,
            rotors: Vec::new(),
        }
    }

    /// The rotors' total relative angular momentum h = Σₖ Jₖ Ωₖ aₖ/|aₖ| in body axes, or
    /// `None` without rotors (so a top without one derives exactly what it did before).
    ///
    /// # Errors
    /// [`SymError`] (a division by zero) for a rotor whose axis is identically zero.
    pub fn rotor_momentum(&self, arena: &mut Arena) -> Result<Option<[ExprId; 3]>, SymError> {
        total_momentum(arena, &self.rotors).map_err(|(_, e)| e)
    }

    /// The sum of the non-potential torques in body axes (zero if none is declared).
    pub(super) fn applied_torque(
        &self,
        arena: &mut Arena,
        rotation: &Mat3,
        omega: &[ExprId; 3],
    ) -> [ExprId; 3] {
        let mut terms: Vec<[ExprId; 3]> = Vec::new();
        if let Some(g) = self.body_torque {
            terms.push(g);
        }
        if let Some(gs) = self.space_torque {
            let rt = transpose(rotation);
            terms.push(mat_vec(arena, &rt, &gs));
        }
        if let Some(c) = self.damping {
            let mc = arena.neg(c);
            terms.push(omega.map(|w| arena.mul(mc, w)));
        }
        if let Some(u) = self.user_torque {
            terms.push(u);
        }
        let mut total = [arena.zero(); 3];
        for (k, t) in total.iter_mut().enumerate() {
            let parts: Vec<ExprId> = terms.iter().map(|v| v[k]).collect();
            *t = arena.sum(&parts);
        }
        total
    }
}
