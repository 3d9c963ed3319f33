//! A top's derivation: its Lagrangian in Euler angles, the declared torques as generalised
//! forces, the Euler–Lagrange equations solved for q̈, and the same scene in Eulerian form.

use super::scene::TopScene;
use crate::lagrange::{Accelerations, Coordinates, EquationsOfMotion, LagrangeError};
use crate::rigid::AngleSequence;
use crate::sym::mat3::{Mat3, adjugate_times, cross, determinant, dot, mat_vec, transpose};
use crate::sym::{Arena, ExprId};

/// Everything derived from a [`TopScene`] in angle form.
#[derive(Clone, Debug, PartialEq)]
pub struct TopDerivation {
    /// The Euler–Lagrange equations.
    pub equations: EquationsOfMotion,
    /// Their solution q̈.
    pub accelerations: Accelerations,
    /// Body angular velocity ω = B(q) q̇.
    pub omega: [ExprId; 3],
    /// B(q).
    pub rate_matrix: Mat3,
    /// R(q), body to space.
    pub rotation: Mat3,
    /// Kinetic energy T = ½ ωᵀ I ω.
    pub kinetic: ExprId,
    /// Potential energy V = M g (R c)·ẑ.
    pub potential: ExprId,
    /// The rotors' term ω·h of the Lagrangian (zero without rotors): linear in q̇, so it
    /// changes the equations but not the conserved Jacobi integral T + V.
    pub gyrostatic: ExprId,
    /// The angle sequence of the coordinates.
    pub sequence: AngleSequence,
    /// The generalised forces of the non-potential torques, `Q = Bᵀ τ`.
    pub forces: Vec<ExprId>,
    /// For each coordinate, its momentum ∂L/∂q̇_i if it is conserved (L does not depend on
    /// q_i and no force acts on it), else `None`.
    pub conserved_momenta: Vec<Option<ExprId>>,
}

impl TopDerivation {
    /// The Lagrangian L = T + ω·h − V.
    pub fn lagrangian(&self, arena: &mut Arena) -> ExprId {
        let t = arena.add(self.kinetic, self.gyrostatic);
        arena.sub(t, self.potential)
    }

    /// The energy T + V, conserved when no non-potential torque is declared (with rotors
    /// too: it is the Jacobi integral Σ q̇ᵢ ∂L/∂q̇ᵢ − L, the linear ω·h dropping out).
    pub fn energy(&self, arena: &mut Arena) -> ExprId {
        arena.add(self.kinetic, self.potential)
    }

    /// The coordinates.
    pub fn coords(&self) -> &Coordinates {
        &self.equations.coords
    }

    /// The Jacobian of q̈ with respect to the state `(q, q̇)`: row i holds
    /// `(∂q̈_i/∂q_0, ∂q̈_i/∂q_1, ∂q̈_i/∂q_2, ∂q̈_i/∂q̇_0, ∂q̈_i/∂q̇_1, ∂q̈_i/∂q̇_2)`, for
    /// linearisation (stability of steady motions) and implicit steppers.
    pub fn jacobian(&self, arena: &mut Arena) -> [[ExprId; 6]; 3] {
        let c = self.coords().clone();
        let state: Vec<ExprId> = c.q.iter().chain(c.rates.iter()).copied().collect();
        let mut jac = [[arena.zero(); 6]; 3];
        for (i, row) in jac.iter_mut().enumerate() {
            for (j, entry) in row.iter_mut().enumerate() {
                if let Some(s) = arena.as_symbol(state[j]) {
                    *entry = arena.diff(self.accelerations.accel[i], s);
                }
            }
        }
        jac
    }

    /// The body angular acceleration `ω̇ = B q̈ + Ḃ q̇` as an expression in q, q̇ and the
    /// acceleration symbols q̈ (substitute the solved q̈ to evaluate it).
    pub fn omega_dot(&self, arena: &mut Arena) -> [ExprId; 3] {
        self.omega.map(|w| arena.dt(w))
    }
}

impl TopScene {
    /// Derives the angle-form equations of motion from L = ½ ωᵀ I ω + ω·h − V, with h the
    /// rotors' relative momentum ([`TopScene::rotor_momentum`]).
    ///
    /// # Errors
    /// As [`EquationsOfMotion::derive`] and [`EquationsOfMotion::solve`]; a singular inertia
    /// tensor gives [`LagrangeError::SingularMassMatrix`]; a rotor with an identically zero
    /// axis [`LagrangeError::Sym`].
    pub fn derive(&self, arena: &mut Arena) -> Result<TopDerivation, LagrangeError> {
        let coords = self.sequence.coordinates(arena);
        let rotation = self.sequence.rotation(arena, &coords.q);
        let omega = self.sequence.body_rates(arena, &coords);
        let b = self.sequence.rate_matrix(arena, &coords, &omega);
        let i_omega = mat_vec(arena, &self.inertia, &omega);
        let two_t = dot(arena, &omega, &i_omega);
        let half =
            arena.constant(crate::sym::Rational::new(1, 2).unwrap_or(crate::sym::Rational::ONE));
        let kinetic = arena.mul(half, two_t);
        let kinetic = arena.expand(kinetic);
        let potential = match self.gravity {
            // V = M g ẑ·(R c): the height of the centre of mass.
            Some(g) => {
                let height = dot(arena, &rotation[2], &self.center);
                let v = arena.product(&[self.mass, g, height]);
                arena.expand(v)
            }
            None => arena.zero(),
        };
        let gyrostatic = match self.rotor_momentum(arena)? {
            Some(h) => {
                let wh = dot(arena, &omega, &h);
                arena.expand(wh)
            }
            None => arena.zero(),
        };
        let lagrangian = arena.add(kinetic, gyrostatic);
        let lagrangian = arena.sub(lagrangian, potential);
        let tau = self.applied_torque(arena, &rotation, &omega);
        let bt = transpose(&b);
        let forces: Vec<ExprId> = mat_vec(arena, &bt, &tau)
            .iter()
            .map(|&f| arena.expand(f))
            .collect();
        let equations = EquationsOfMotion::derive(arena, lagrangian, coords, &forces)?;
        let accelerations = equations.solve(arena)?;
        let conserved_momenta = (0..3)
            .map(|i| {
                let s = arena.as_symbol(equations.coords.q[i])?;
                let d = arena.diff(lagrangian, s);
                let d = arena.expand(d);
                (d == arena.zero() && forces[i] == arena.zero()).then_some(equations.momenta[i])
            })
            .collect();
        Ok(TopDerivation {
            equations,
            accelerations,
            omega,
            rate_matrix: b,
            rotation,
            sequence: self.sequence,
            kinetic,
            potential,
            gyrostatic,
            forces,
            conserved_momenta,
        })
    }

    /// The Eulerian form `ω̇ = I⁻¹ (τ − ω × (I ω + h))` with the gravity torque
    /// `c × (Rᵀ(−M g ẑ))` and the rotors' momentum h (none without rotors), in terms of
    /// the attitude matrix entries `rotation` (body to space) and the body angular velocity
    /// `omega`, both supplied as expressions (usually input symbols).
    ///
    /// # Errors
    /// [`LagrangeError::SingularMassMatrix`] if the inertia tensor is singular;
    /// [`LagrangeError::Sym`] for a rotor with an identically zero axis.
    pub fn eulerian_rhs(
        &self,
        arena: &mut Arena,
        rotation: &Mat3,
        omega: &[ExprId; 3],
    ) -> Result<[ExprId; 3], LagrangeError> {
        let mut tau = self.applied_torque(arena, rotation, omega);
        if let Some(g) = self.gravity {
            // Rᵀ ẑ is the third row of R; the weight is −M g times it, in body axes.
            let up = rotation[2];
            let mg = arena.mul(self.mass, g);
            let w = up.map(|u| {
                let t = arena.mul(mg, u);
                arena.neg(t)
            });
            let gt = cross(arena, &self.center, &w);
            for k in 0..3 {
                tau[k] = arena.add(tau[k], gt[k]);
            }
        }
        let mut momentum = mat_vec(arena, &self.inertia, omega);
        if let Some(h) = self.rotor_momentum(arena)? {
            momentum = std::array::from_fn(|k| arena.add(momentum[k], h[k]));
        }
        let gyro = cross(arena, omega, &momentum);
        let rhs: Vec<ExprId> = (0..3).map(|k| arena.sub(tau[k], gyro[k])).collect();
        let m: Vec<Vec<ExprId>> = self.inertia.iter().map(|r| r.to_vec()).collect();
        let det = determinant(arena, &m);
        let det = arena.expand(det);
        if det == arena.zero() {
            return Err(LagrangeError::SingularMassMatrix {
                block: vec![0, 1, 2],
            });
        }
        let inv_det = arena.recip(det)?;
        let num = adjugate_times(arena, &m, &rhs);
        Ok(std::array::from_fn(|r| {
            let num = arena.expand(num[r]);
            arena.mul(num, inv_det)
        }))
    }
}
