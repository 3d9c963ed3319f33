//! From a mechanism and its loop closures to what [`super::LoopDynamics`] needs: M(q) and
//! f(q, q̇) of the tree cut open (Kane's method), the closure rows φ(q) = 0 with their
//! Jacobian A = ∂φ/∂q and Ȧq̇, all exact, and each planar loop's sides for the closure rule.

use super::scene::{LoopClosure, LoopSide};
use crate::lagrange::{Constraints, Coordinates, EquationsOfMotion};
use crate::mechanism::error::MechanismError;
use crate::mechanism::kinematics::{BodyKinematics, unit_axis};
use crate::mechanism::routes::kane::MassEntries;
use crate::mechanism::scene::{JointKind, MechanismScene, Parent};
use crate::sym::mat3::{dot, mat_vec};
use crate::sym::{Arena, ExprId};

/// Everything derived from a mechanism with closed loops.
#[derive(Clone, Debug, PartialEq)]
pub struct LoopDerivation {
    /// The unconstrained equations M q̈ = f of the tree (every coordinate).
    pub equations: EquationsOfMotion,
    /// The time symbol.
    pub time: ExprId,
    /// The closure rows: φ (positions) and A (coefficients), each closure's components in
    /// ground axes x, y, z with the identically zero ones left out.
    pub constraints: Constraints,
    /// Ȧq̇, one per row (unexpanded: [`Constraints::rate_terms_shared`]).
    pub rate_terms: Vec<ExprId>,
    /// For each row, its closure and the ground axis (0, 1, 2) of its component.
    pub rows: Vec<(usize, usize)>,
    /// For each closure, the sides of its loop when the loop is planar (every joint on it
    /// a revolute about one axis), else `None`.
    pub sides: Vec<Option<Vec<LoopSide>>>,
    /// T.
    pub kinetic: ExprId,
    /// V (gravity and springs).
    pub potential: ExprId,
    /// Σ Q_i q̇_i of the non-conservative loads.
    pub power: ExprId,
}

impl LoopDerivation {
    /// q, q̇ and q̈ symbols.
    pub fn coordinates(&self) -> &Coordinates {
        &self.equations.coords
    }
}

impl MechanismScene {
    /// Derives the mechanism with its loops closed by `closures`.
    ///
    /// # Errors
    /// As [`MechanismScene::validate`]; [`MechanismError::UnknownClosureBody`];
    /// [`MechanismError::TooManyClosureRows`] when the rows leave no free coordinate;
    /// [`MechanismError::Sym`] and [`MechanismError::Lagrange`] if the engine fails.
    pub fn derive_loops(
        &self,
        arena: &mut Arena,
        closures: &[LoopClosure],
    ) -> Result<LoopDerivation, MechanismError> {
        let (lag, kin) = self.lagrangian(arena)?;
        let coords = lag.coords.clone();
        let mut constraints = Constraints::new();
        let mut rows = Vec::new();
        let mut sides = Vec::with_capacity(closures.len());
        for (c, closure) in closures.iter().enumerate() {
            let a = point(arena, &kin, Parent::Body(closure.body), &closure.at)?;
            let b = point(arena, &kin, closure.to, &closure.to_at)?;
            for axis in 0..3 {
                let phi = arena.sub(a[axis], b[axis]);
                let phi = arena.expand(phi);
                // A component the joints already hold (the z of a planar loop) is no row:
                // it would make A singular everywhere.
                if phi != arena.zero() {
                    constraints.holonomic(arena, &coords, phi)?;
                    rows.push((c, axis));
                }
            }
            sides.push(self.loop_sides(arena, closure)?);
        }
        if constraints.len() >= coords.len() {
            return Err(MechanismError::TooManyClosureRows {
                rows: constraints.len(),
                coordinates: coords.len(),
            });
        }
        let rate_terms = constraints.rate_terms_shared(arena, &coords);
        let equations = self.kane_from(arena, &lag, &kin, MassEntries::Expanded);
        let power = lag.power(arena);
        Ok(LoopDerivation {
            equations,
            time: lag.time,
            constraints,
            rate_terms,
            rows,
            sides,
            kinetic: lag.kinetic,
            potential: lag.potential,
            power,
        })
    }

    /// The bodies from `from` up to the ground, `from` first.
    fn chain(&self, from: Parent) -> Vec<usize> {
        let mut out = Vec::new();
        let mut at = from;
        while let Parent::Body(b) = at {
            // A cycle of parents is refused by `validate` before this is reached; the
            // bound keeps a malformed scene from looping here.
            if out.contains(&b) || b >= self.bodies.len() {
                break;
            }
            out.push(b);
            at = self.bodies[b].joint.parent;
        }
        out
    }

    /// The sides of the loop `closure` closes, when every joint on it is a revolute about
    /// one common axis (a planar loop); `None` otherwise (a slider, a spatial loop).
    fn loop_sides(
        &self,
        arena: &mut Arena,
        closure: &LoopClosure,
    ) -> Result<Option<Vec<LoopSide>>, MechanismError> {
        let left = self.chain(Parent::Body(closure.body));
        let right = self.chain(closure.to);
        // The loop's bodies: each chain up to the first body both share (or the ground).
        let common = left.iter().copied().find(|b| right.contains(b));
        let cut = |chain: &[usize]| -> Vec<usize> {
            chain
                .iter()
                .copied()
                .take_while(|&b| Some(b) != common)
                .collect()
        };
        let (left, right) = (cut(&left), cut(&right));
        let mut axis: Option<[ExprId; 3]> = None;
        for &b in left.iter().chain(&right) {
            let JointKind::Revolute { axis: a } = &self.bodies[b].joint.kind else {
                return Ok(None);
            };
            let unit = unit_axis(arena, a)?;
            if axis.is_some_and(|u| u != unit) {
                return Ok(None);
            }
            axis = Some(unit);
        }
        let Some(axis) = axis else {
            return Ok(None);
        };
        let zero = [arena.zero(); 3];
        let mut sides = Vec::new();
        // Each body's side: from its own joint (its frame's origin) to the next point on the
        // loop, its child's joint on the chain or the closing point.
        for (chain, end) in [(&left, closure.at), (&right, closure.to_at)] {
            for (k, &b) in chain.iter().enumerate() {
                let exit = if k == 0 {
                    end
                } else {
                    self.bodies[chain[k - 1]].joint.at
                };
                let name = self.bodies[b].name.clone();
                sides.push(side(arena, name, &exit, &zero, &axis));
            }
        }
        // The common body's (or the ground's) side: between the two chains' entries.
        let entry = |chain: &[usize], end: [ExprId; 3]| match chain.last() {
            Some(&b) => self.bodies[b].joint.at,
            None => end,
        };
        let (p, q) = (entry(&left, closure.at), entry(&right, closure.to_at));
        let name = common.map_or_else(|| "ground".to_owned(), |b| self.bodies[b].name.clone());
        sides.push(side(arena, name, &p, &q, &axis));
        Ok(Some(sides))
    }
}

/// The side from `q` to `p` across the unit `axis`: |p − q|² − ((p − q)·axis)².
fn side(
    arena: &mut Arena,
    body: String,
    p: &[ExprId; 3],
    q: &[ExprId; 3],
    axis: &[ExprId; 3],
) -> LoopSide {
    let d = [0, 1, 2].map(|i| arena.sub(p[i], q[i]));
    let length = dot(arena, &d, &d);
    let along = dot(arena, &d, axis);
    let along = arena.mul(along, along);
    let squared = arena.sub(length, along);
    LoopSide {
        body,
        squared: arena.expand(squared),
    }
}

/// The ground position of the point `p` of `frame`'s body (the ground's own point for the
/// ground), expanded.
fn point(
    arena: &mut Arena,
    kin: &[BodyKinematics],
    frame: Parent,
    p: &[ExprId; 3],
) -> Result<[ExprId; 3], MechanismError> {
    match frame {
        Parent::Ground => Ok(*p),
        Parent::Body(b) => {
            let Some(k) = kin.get(b) else {
                return Err(MechanismError::UnknownClosureBody {
                    body: b,
                    count: kin.len(),
                });
            };
            let lever = mat_vec(arena, &k.rotation, p);
            Ok([0, 1, 2].map(|i| {
                let t = arena.add(k.origin[i], lever[i]);
                arena.expand(t)
            }))
        }
    }
}
