//! A free body's derivation: the centre of mass under the declared forces and the rotation
//! about it under their torques, derived symbolically so that only what is declared appears.
//!
//! The state (see [`super::layout`]) is read through input symbols. The attitude matrix is
//! formed from the stored quaternion as R = (homogeneous form)/|q|², so a quaternion that
//! drifts off the unit sphere still gives a rotation, and only the entries a declared force
//! needs are ever lowered.

use super::error::FreeError;
use super::rotor::{fold, principal_momentum, reciprocal};
use super::scene::{ForcePoint, FreeScene};
use super::state::STATE_LEN;
use crate::rigid::{quaternion_rate, rotation_of_quaternion};
use crate::sym::mat3::{Mat3, cross, dot, mat_vec, transpose};
use crate::sym::{Arena, ExprId, Rational};

/// Everything derived from a [`FreeScene`], as expressions in the state symbols.
#[derive(Clone, Debug, PartialEq)]
pub struct FreeDerivation {
    /// The state symbols, in the order of [`super::layout`].
    pub state: [ExprId; STATE_LEN],
    /// The right-hand side ẏ: ẋ = v, v̇ = F/M, q̇ = ½ q ⊗ (0, ω), ω̇ = I⁻¹(τ − ω × (I ω + h))
    /// (h the rotors' relative momentum, principal axes; absent without rotors).
    pub rhs: [ExprId; STATE_LEN],
    /// The total force F, space axes.
    pub force: [ExprId; 3],
    /// The total torque τ about the centre of mass, principal axes.
    pub torque: [ExprId; 3],
    /// The energy E = ½ M |v|² + ½ Σ Iᵢ ωᵢ² − M g·x (with rotors at constant rate, the
    /// integral that is conserved: their motor's work is not in it).
    pub energy: ExprId,
    /// The power of every force but gravity, P = F'·v + τ·ω (F' = F − M g), so that
    /// dE/dt = P.
    pub power: ExprId,
    /// The linear momentum M v, space axes.
    pub linear_momentum: [ExprId; 3],
    /// The angular momentum about the space origin, x × M v + R (I ω + h), space axes.
    pub angular_momentum: [ExprId; 3],
    /// The driven rotors' relative rates Ωₖ: the state symbols after the 13 of
    /// [`super::layout`], in the order of [`FreeScene::driven`] (empty without).
    pub rotor_rates: Vec<ExprId>,
    /// Their rates of change, Ω̇ₖ = uₖ/Jₖ − âₖ·ω̇.
    pub rotor_rhs: Vec<ExprId>,
    /// For each driven rotor k, I − Σⱼ≤ₖ Jⱼ âⱼ âⱼᵀ in principal axes: the inertia the body
    /// keeps once the first k + 1 wheels turn freely, which must stay positive definite.
    pub driven_inertia: Vec<Mat3>,
    /// The principal moments about the centre of mass, every wheel counted as if locked: the
    /// scale the driven rule measures rounding against (the scene's
    /// [`FreeScene::moments`]).
    pub moments: [ExprId; 3],
}

impl FreeDerivation {
    /// The whole state: the 13 symbols of [`super::layout`], then the driven rotors' rates.
    pub fn full_state(&self) -> Vec<ExprId> {
        self.state
            .iter()
            .chain(&self.rotor_rates)
            .copied()
            .collect()
    }

    /// The whole right-hand side, in the order of [`FreeDerivation::full_state`].
    pub fn full_rhs(&self) -> Vec<ExprId> {
        self.rhs.iter().chain(&self.rotor_rhs).copied().collect()
    }
}

impl FreeScene {
    /// Derives the equations of motion, the wrench, the energy, its power balance and the
    /// momenta, over fresh input symbols for the state.
    ///
    /// # Errors
    /// [`FreeError::ZeroInertia`] if the mass or a principal moment is identically zero, or
    /// the determinant of I − Σ Jₖ âₖ âₖᵀ with driven rotors; [`FreeError::ZeroRotorAxis`] if
    /// a rotor's axis is (a driven rotor counted after the constant-rate ones).
    pub fn derive(&self, arena: &mut Arena) -> Result<FreeDerivation, FreeError> {
        const NAMES: [&str; STATE_LEN] = [
            "x", "y", "z", "v_x", "v_y", "v_z", "q_w", "q_x", "q_y", "q_z", "omega_1", "omega_2",
            "omega_3",
        ];
        let state: [ExprId; STATE_LEN] = std::array::from_fn(|k| arena.input(NAMES[k]));
        let pick = |at: usize| [state[at], state[at + 1], state[at + 2]];
        let (x, v, omega) = (pick(0), pick(3), pick(10));
        let q = [state[6], state[7], state[8], state[9]];
        let rotation = rotation_of_quaternion(arena, q)
            .map_err(|_| FreeError::ZeroInertia { quantity: "|q|²" })?;
        let Wrench {
            force,
            conservative,
            torque,
        } = self.wrench(arena, &rotation, &v, &omega);
        let inv_mass = reciprocal(arena, self.mass, "mass")?;
        let accel = force.map(|f| arena.mul(inv_mass, f));
        // A driven wheel's rate is a state slot; its momentum J Ω â reads that symbol.
        let rotor_rates: Vec<ExprId> = (0..self.driven.len())
            .map(|k| arena.input(&format!("Omega_rotor_{k}")))
            .collect();
        let mut wheels = self.rotors.clone();
        wheels.extend(
            self.driven
                .iter()
                .zip(&rotor_rates)
                .map(|(r, &rate)| r.at_rate(rate)),
        );
        let h = principal_momentum(arena, &wheels, &self.principal_rotation)?;
        let (omega_dot, rotor_rhs, driven_inertia) = match h {
            Some(h) if !self.driven.is_empty() => {
                self.driven_dynamics(arena, &omega, &torque, &h, &rotor_rates)?
            }
            Some(h) => {
                let euler = self.euler(arena, &omega, &torque)?;
                (
                    self.gyrostat(arena, &omega, &h, euler)?,
                    Vec::new(),
                    Vec::new(),
                )
            }
            None => (self.euler(arena, &omega, &torque)?, Vec::new(), Vec::new()),
        };
        let q_dot = quaternion_rate(arena, q, omega);
        let mut rhs = [arena.zero(); STATE_LEN];
        rhs[..3].copy_from_slice(&v);
        rhs[3..6].copy_from_slice(&accel);
        rhs[6..10].copy_from_slice(&q_dot);
        rhs[10..].copy_from_slice(&omega_dot);
        let half = arena.constant(Rational::new(1, 2).unwrap_or(Rational::ONE));
        let v2 = dot(arena, &v, &v);
        let translational = arena.product(&[half, self.mass, v2]);
        let i_omega: [ExprId; 3] = std::array::from_fn(|k| arena.mul(self.moments[k], omega[k]));
        let two_t = dot(arena, &omega, &i_omega);
        let mut rotational = arena.mul(half, two_t);
        if !self.driven.is_empty() {
            // The driven wheels' own energy: Σ Jₖ Ωₖ âₖ·ω + ½ Σ Jₖ Ωₖ² (a constant-rate
            // wheel's is left out, its motor's work not being in the balance).
            let driven: Vec<_> = self
                .driven
                .iter()
                .zip(&rotor_rates)
                .map(|(r, &rate)| r.at_rate(rate))
                .collect();
            if let Some(hd) = principal_momentum(arena, &driven, &self.principal_rotation)? {
                let coupling = dot(arena, &hd, &omega);
                rotational = arena.add(rotational, coupling);
            }
            for (r, &rate) in self.driven.iter().zip(&rotor_rates) {
                let w2 = arena.mul(rate, rate);
                let own = arena.product(&[half, r.inertia, w2]);
                rotational = arena.add(rotational, own);
            }
        }
        let mut energy = arena.add(translational, rotational);
        if let Some(g) = self.gravity {
            // V = −M g·x: the work of the weight is −ΔV.
            let gx = dot(arena, &g, &x);
            let v_grav = arena.mul(self.mass, gx);
            energy = arena.sub(energy, v_grav);
        }
        let applied: [ExprId; 3] = std::array::from_fn(|k| arena.sub(force[k], conservative[k]));
        let fv = dot(arena, &applied, &v);
        let tw = dot(arena, &torque, &omega);
        let mut power = arena.add(fv, tw);
        for (r, &rate) in self.driven.iter().zip(&rotor_rates) {
            // The motor's work on its wheel: uₖ Ωₖ.
            let motor = arena.mul(r.torque, rate);
            power = arena.add(power, motor);
        }
        let linear_momentum = v.map(|c| arena.mul(self.mass, c));
        let orbital = cross(arena, &x, &linear_momentum);
        let body_momentum = match h {
            Some(h) => std::array::from_fn(|k| arena.add(i_omega[k], h[k])),
            None => i_omega,
        };
        let spin = mat_vec(arena, &rotation, &body_momentum);
        let angular_momentum: [ExprId; 3] = std::array::from_fn(|k| arena.add(orbital[k], spin[k]));
        Ok(FreeDerivation {
            state,
            rhs,
            force,
            torque,
            energy,
            power,
            linear_momentum,
            angular_momentum,
            rotor_rates,
            rotor_rhs,
            driven_inertia,
            moments: self.moments,
        })
    }

    /// A point of the body relative to the centre of mass, principal axes: Rₚ𝒹ᵀ (p − c).
    fn lever(&self, arena: &mut Arena, at: &ForcePoint) -> Option<[ExprId; 3]> {
        let ForcePoint::Body(p) = at else {
            return None;
        };
        let d: [ExprId; 3] = std::array::from_fn(|k| arena.sub(p[k], self.center[k]));
        Some(mat_vec(arena, &transpose(&self.principal_rotation), &d))
    }

    /// The total force (space axes), its conservative part (the weight) and the total torque
    /// about the centre of mass (principal axes) of the declared terms.
    fn wrench(
        &self,
        arena: &mut Arena,
        rotation: &Mat3,
        v: &[ExprId; 3],
        omega: &[ExprId; 3],
    ) -> Wrench {
        let to_principal = transpose(&self.principal_rotation);
        let to_body = transpose(rotation);
        let mut forces: Vec<[ExprId; 3]> = Vec::new();
        let mut torques: Vec<[ExprId; 3]> = Vec::new();
        let mut conservative = [arena.zero(); 3];
        if let Some(g) = self.gravity {
            // The weight acts at the centre of mass: no torque about it.
            conservative = g.map(|gk| arena.mul(self.mass, gk));
            forces.push(conservative);
        }
        for f in &self.body_forces {
            let fp = mat_vec(arena, &to_principal, &f.force);
            forces.push(mat_vec(arena, rotation, &fp));
            if let Some(r) = self.lever(arena, &f.at) {
                torques.push(cross(arena, &r, &fp));
            }
        }
        for f in &self.space_forces {
            forces.push(f.force);
            if let Some(r) = self.lever(arena, &f.at) {
                let fb = mat_vec(arena, &to_body, &f.force);
                torques.push(cross(arena, &r, &fb));
            }
        }
        if let Some(c) = self.drag {
            let mc = arena.neg(c);
            forces.push(v.map(|vk| arena.mul(mc, vk)));
        }
        if let Some(u) = self.user_force {
            forces.push(u);
        }
        if let Some(t) = self.body_torque {
            torques.push(mat_vec(arena, &to_principal, &t));
        }
        if let Some(t) = self.space_torque {
            torques.push(mat_vec(arena, &to_body, &t));
        }
        if let Some(c) = self.damping {
            let mc = arena.neg(c);
            torques.push(omega.map(|w| arena.mul(mc, w)));
        }
        if let Some(u) = self.user_torque {
            torques.push(mat_vec(arena, &to_principal, &u));
        }
        if let Some(w) = &self.user_wrench {
            // Space parts as given (force) or turned into principal axes by Rᵀ (torque);
            // description parts into principal axes, the force then into space by R.
            forces.push(w.force_space);
            let fp = mat_vec(arena, &to_principal, &w.force_description);
            forces.push(mat_vec(arena, rotation, &fp));
            torques.push(mat_vec(arena, &to_body, &w.torque_space));
            torques.push(mat_vec(arena, &to_principal, &w.torque_description));
        }
        Wrench {
            force: sum_vectors(arena, &forces),
            conservative,
            torque: sum_vectors(arena, &torques),
        }
    }

    /// Euler's equations in principal axes, ω̇ᵢ = kᵢ ωⱼ ωₖ + τᵢ/Iᵢ with kᵢ = (Iⱼ − Iₖ)/Iᵢ: a
    /// coefficient that vanishes (a symmetric body) removes its term, and constant
    /// coefficients fold to one number each.
    fn euler(
        &self,
        arena: &mut Arena,
        omega: &[ExprId; 3],
        torque: &[ExprId; 3],
    ) -> Result<[ExprId; 3], FreeError> {
        const MOMENTS: [&str; 3] = [
            "principal moment I1",
            "principal moment I2",
            "principal moment I3",
        ];
        let m = self.moments;
        let mut out = [arena.zero(); 3];
        for i in 0..3 {
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            let inverse = reciprocal(arena, m[i], MOMENTS[i])?;
            let diff = arena.sub(m[j], m[k]);
            let gyro = if arena.is_zero(diff).unwrap_or(false) {
                arena.zero()
            } else {
                let coefficient = arena.mul(diff, inverse);
                let coefficient = fold(arena, coefficient);
                arena.product(&[coefficient, omega[j], omega[k]])
            };
            let drive = arena.mul(inverse, torque[i]);
            out[i] = arena.add(gyro, drive);
        }
        Ok(out)
    }
}

impl FreeScene {
    /// The rotors' gyroscopic term added to Euler's equations: ω̇ᵢ −= (ω × h)ᵢ/Iᵢ, with
    /// (ω × h)ᵢ = ωⱼ hₖ − ωₖ hⱼ; a component of h that is zero removes its products.
    fn gyrostat(
        &self,
        arena: &mut Arena,
        omega: &[ExprId; 3],
        h: &[ExprId; 3],
        euler: [ExprId; 3],
    ) -> Result<[ExprId; 3], FreeError> {
        const MOMENTS: [&str; 3] = [
            "principal moment I1",
            "principal moment I2",
            "principal moment I3",
        ];
        let h = h.map(|c| fold(arena, c));
        let mut out = euler;
        for i in 0..3 {
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            let inverse = reciprocal(arena, self.moments[i], MOMENTS[i])?;
            // −(ωⱼ hₖ − ωₖ hⱼ)/Iᵢ = (hⱼ/Iᵢ) ωₖ − (hₖ/Iᵢ) ωⱼ, each coefficient folded.
            let cj = arena.mul(h[j], inverse);
            let cj = fold(arena, cj);
            let ck = arena.mul(h[k], inverse);
            let ck = fold(arena, ck);
            let plus = arena.mul(cj, omega[k]);
            let minus = arena.mul(ck, omega[j]);
            let term = arena.sub(plus, minus);
            out[i] = arena.add(out[i], term);
        }
        Ok(out)
    }
}

/// The declared force and torque, and the part of the force that has a potential.
struct Wrench {
    force: [ExprId; 3],
    conservative: [ExprId; 3],
    torque: [ExprId; 3],
}

/// Σ of 3-vectors (the zero vector for none).
fn sum_vectors(arena: &mut Arena, terms: &[[ExprId; 3]]) -> [ExprId; 3] {
    std::array::from_fn(|k| {
        let parts: Vec<ExprId> = terms.iter().map(|t| t[k]).collect();
        arena.sum(&parts)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::codegen::Program;

    /// A torque-free symmetric body: ω̇₃ has no term, the others one product each, and no
    /// attitude entry is read.
    #[test]
    fn symmetric_torque_free_body_emits_the_reduced_euler_equations() {
        let mut a = Arena::new();
        let (m, i1, i3) = (a.integer(2), a.integer(1), a.number("0.5").unwrap());
        let scene = FreeScene::new(&mut a, m, [i1, i1, i3]);
        let d = scene.derive(&mut a).unwrap();
        assert_eq!(d.rhs[12], a.zero());
        // ω̇₁ = ((I₂ − I₃)/I₁) ω₂ ω₃ = ½ ω₂ ω₃.
        let p = Program::lower(&a, &d.rhs[10..]);
        assert_eq!(p.op_count().divs, 0);
        let reads = p.inputs();
        let quaternion: Vec<_> = d.state[6..10]
            .iter()
            .filter_map(|&e| a.as_symbol(e))
            .collect();
        assert!(reads.iter().all(|s| !quaternion.contains(s)));
        let mut env = vec![0.0; a.symbol_count()];
        for (k, &v) in [0.0, 3.0, 4.0].iter().enumerate() {
            env[a.as_symbol(d.state[10 + k]).unwrap().index()] = v;
        }
        let out = p.eval(&env);
        assert_eq!(out, vec![0.5 * 3.0 * 4.0, -0.5 * 4.0 * 0.0, 0.0]);
    }
}
