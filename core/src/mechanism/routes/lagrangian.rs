//! The Lagrangian route: T, V and the non-conservative generalised forces Q of a
//! mechanism, the Euler–Lagrange equations `M(q) q̈ = f(q, q̇, t)` they give, and the block
//! adjugate solve of M for few coordinates ([`Route::Symbolic`]).
//!
//! - Kinetic energy T = Σ_b ½ m_b |v_c|² + ½ ω_bᵀ I_b ω_b (ω_b in body axes, I_b about the
//!   centre of mass in the body's axes; see [`crate::mechanism::BodyKinematics`]).
//! - Potential V = −Σ_b m_b g·c_b + Σ ½ k (q − rest)² (gravity and joint springs).
//! - Non-conservative generalised forces Q_i = −c_i q̇_i + e_i + Σ_b τ_b·∂ω_b/∂q̇_i, with
//!   τ_b the body torque plus R_bᵀ times the space torque.
//! - [`EquationsOfMotion::derive`] turns L = T − V and Q into M q̈ = f.
//!
//! Kane's route ([`super::kane`]) and the rolling derivation start from the same pieces.
//!
//! [`Route::Symbolic`]: crate::mechanism::Route::Symbolic

use crate::lagrange::{Coordinates, EquationsOfMotion, LagrangeError};
use crate::mechanism::error::MechanismError;
use crate::mechanism::kinematics::{BodyKinematics, MAX_LAGRANGIAN};
use crate::mechanism::scene::MechanismScene;
use crate::sym::mat3::{dot, mat_vec, transpose};
use crate::sym::{Arena, ExprId, Rational};

/// The Lagrangian pieces shared by the routes (and the rolling derivation).
pub(crate) struct Lagrangian {
    pub(crate) coords: Coordinates,
    pub(crate) time: ExprId,
    pub(crate) kinetic: ExprId,
    pub(crate) potential: ExprId,
    pub(crate) forces: Vec<ExprId>,
}

fn half(arena: &mut Arena) -> ExprId {
    arena.constant(Rational::new(1, 2).unwrap_or(Rational::ONE))
}

/// −c q̇ + effort per coordinate (no springs: they are in V).
fn non_conservative_joint_forces(
    arena: &mut Arena,
    scene: &MechanismScene,
    coords: &Coordinates,
) -> Vec<ExprId> {
    let mut out = Vec::with_capacity(coords.len());
    let mut i = 0;
    for body in &scene.bodies {
        for load in &body.joint.loads {
            let mut terms = Vec::new();
            if let Some(c) = load.damper {
                let t = arena.mul(c, coords.rates[i]);
                terms.push(arena.neg(t));
            }
            if let Some(e) = load.effort {
                terms.push(e);
            }
            out.push(arena.sum(&terms));
            i += 1;
        }
    }
    out
}

impl Lagrangian {
    /// L = T − V.
    pub(crate) fn lagrangian(&self, arena: &mut Arena) -> ExprId {
        arena.sub(self.kinetic, self.potential)
    }

    /// The power of the non-conservative loads, dE/dt = Σ Q_i q̇_i (unexpanded).
    pub(crate) fn power(&self, arena: &mut Arena) -> ExprId {
        let terms: Vec<ExprId> = self
            .forces
            .iter()
            .zip(&self.coords.rates)
            .map(|(&f, &r)| arena.mul(f, r))
            .collect();
        arena.sum(&terms)
    }

    /// The Euler–Lagrange equations of L = T − V under Q.
    pub(crate) fn equations(&self, arena: &mut Arena) -> Result<EquationsOfMotion, MechanismError> {
        let l = self.lagrangian(arena);
        Ok(EquationsOfMotion::derive(
            arena,
            l,
            self.coords.clone(),
            &self.forces,
        )?)
    }
}

impl MechanismScene {
    pub(crate) fn lagrangian(
        &self,
        arena: &mut Arena,
    ) -> Result<(Lagrangian, Vec<BodyKinematics>), MechanismError> {
        let order = self.validate(arena)?;
        let names = self.coordinate_names();
        let coords = Coordinates::new(arena, &names);
        let time = arena.time();
        let kin = self.kinematics(arena, &order, &coords)?;
        let h = half(arena);
        // The expanded T of a 3D chain grows far faster than the chain (a 10-link one did
        // not expand in minutes); past MAX_LAGRANGIAN coordinates only the energy reads T
        // and V, and their unexpanded, hash-consed forms lower to the same values.
        let expand = |arena: &mut Arena, e: ExprId| {
            if coords.len() <= MAX_LAGRANGIAN {
                arena.expand(e)
            } else {
                e
            }
        };
        let mut t_terms = Vec::new();
        let mut v_terms = Vec::new();
        for (body, k) in self.bodies.iter().zip(&kin) {
            let v2 = dot(arena, &k.center_velocity, &k.center_velocity);
            let i_omega = mat_vec(arena, &body.inertia, &k.omega);
            let w2 = dot(arena, &k.omega, &i_omega);
            let translational = arena.product(&[h, body.mass, v2]);
            let rotational = arena.mul(h, w2);
            let t = arena.add(translational, rotational);
            t_terms.push(expand(arena, t));
            if let Some(g) = self.gravity {
                let height = dot(arena, &g, &k.center);
                let v = arena.mul(body.mass, height);
                let v = arena.neg(v);
                v_terms.push(expand(arena, v));
            }
        }
        let mut i = 0;
        for body in &self.bodies {
            for load in &body.joint.loads {
                if let Some(spring) = load.spring {
                    let stretch = arena.sub(coords.q[i], spring.rest);
                    let v = arena.product(&[h, spring.stiffness, stretch, stretch]);
                    v_terms.push(expand(arena, v));
                }
                i += 1;
            }
        }
        let kinetic = arena.sum(&t_terms);
        let potential = arena.sum(&v_terms);
        let mut forces = non_conservative_joint_forces(arena, self, &coords);
        for (body, k) in self.bodies.iter().zip(&kin) {
            let mut tau: Option<[ExprId; 3]> = body.body_torque;
            if let Some(ts) = body.space_torque {
                let local = mat_vec(arena, &transpose(&k.rotation), &ts);
                tau = Some(match tau {
                    Some(tb) => [0, 1, 2].map(|j| arena.add(tb[j], local[j])),
                    None => local,
                });
            }
            let Some(tau) = tau else { continue };
            for (f, &rate) in forces.iter_mut().zip(&coords.rates) {
                let Some(s) = arena.as_symbol(rate) else {
                    continue;
                };
                let partial = k.omega.map(|w| arena.diff(w, s));
                let q = dot(arena, &tau, &partial);
                let total = arena.add(*f, q);
                *f = expand(arena, total);
            }
        }
        Ok((
            Lagrangian {
                coords,
                time,
                kinetic,
                potential,
                forces,
            },
            kin,
        ))
    }

    /// The Euler–Lagrange equations `M(q) q̈ = f(q, q̇, t)`, every entry expanded.
    ///
    /// # Errors
    /// As [`MechanismScene::validate`]; [`MechanismError::Lagrange`] if the engine fails.
    pub fn mass_matrix(&self, arena: &mut Arena) -> Result<EquationsOfMotion, MechanismError> {
        let (lag, _) = self.lagrangian(arena)?;
        lag.equations(arena)
    }
}

/// The size of the largest connected block of M's non-zero pattern.
pub(crate) fn largest_coupled_block(arena: &Arena, mass: &[Vec<ExprId>]) -> usize {
    let n = mass.len();
    let mut seen = vec![false; n];
    let mut largest = 0;
    for start in 0..n {
        if seen[start] {
            continue;
        }
        seen[start] = true;
        let mut stack = vec![start];
        let mut size = 0;
        while let Some(i) = stack.pop() {
            size += 1;
            for j in 0..n {
                if !seen[j] && mass[i][j] != arena.zero() {
                    seen[j] = true;
                    stack.push(j);
                }
            }
        }
        largest = largest.max(size);
    }
    largest
}

/// The block adjugate solve; pivots are the block determinants.
pub(crate) fn symbolic(
    arena: &mut Arena,
    eom: &EquationsOfMotion,
) -> Result<(Vec<ExprId>, Vec<ExprId>), MechanismError> {
    match eom.solve(arena) {
        Ok(acc) => Ok((acc.accel, acc.determinants)),
        Err(LagrangeError::SingularMassMatrix { block }) => {
            Err(MechanismError::SingularMassMatrix {
                pivot: block.first().copied().unwrap_or(0),
                value: 0.0,
            })
        }
        Err(e) => Err(e.into()),
    }
}
