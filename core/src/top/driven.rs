//! A top whose internal wheels are turned by motors: the derivation behind
//! `#[top(rotor(axis = [..], inertia = J, torque = path))]`.
//!
//! With I the whole body's inertia about the pivot (every wheel counted as if locked), wheel
//! k of axial moment Jₖ on the body axis âₖ turning at the relative rate Ωₖ, its motor torque
//! uₖ (on the wheel; −uₖ âₖ on the body) and τ the external torque (body axes),
//!
//! d/dt(I ω + h) + ω × (I ω + h) = τ,   Jₖ (âₖ·ω̇ + Ω̇ₖ) = uₖ,   h = Σ Jₖ Ωₖ âₖ,
//!
//! so (I − Σ J â âᵀ) ω̇ = τ − ω × (I ω + h) − Σ uₖ âₖ and Ω̇ₖ = uₖ/Jₖ − âₖ·ω̇, the free body's
//! equations ([`crate::rigid::DrivenRotor`]).
//!
//! The derivation reuses the constant-rate top: write sₖ = Ωₖ + âₖ·ω for wheel k's absolute
//! axial spin. Then I ω + h = I′ ω + Σ Jₖ sₖ âₖ with I′ = I − Σ J â âᵀ, and the body's
//! equation reads I′ ω̇ + ω × (I′ ω + h′) = τ − Σ uₖ âₖ with h′ = Σ Jₖ sₖ âₖ: the equation
//! of a gyrostat of inertia I′ whose wheels spin at constant rates sₖ, under the extra body
//! torque −Σ uₖ âₖ. The Euler–Lagrange engine derives that scene with each sₖ a symbol
//! (so it solves only the 3×3 mass matrix of the angles, not a (3 + k)-square one with the
//! wheel angles as coordinates), and sₖ = Ωₖ + âₖ·ω(q, q̇) is substituted after. Ω̇ₖ comes
//! from the same scene's Eulerian form, ω̇ over R(q) and ω(q, q̇).
//!
//! The energy is T + V with T = ½ ωᵀ I′ ω + ½ Σ Jₖ sₖ² (= ½ ωᵀ I ω + Σ Jₖ Ωₖ âₖ·ω + ½ Σ Jₖ Ωₖ²),
//! of rate Σ uₖ Ωₖ plus the external torques' power. The momentum ∂L′/∂q̇ᵢ of the scene in
//! sₖ is the true one (about the space z axis for φ or the yaw, it is ẑ·R(I ω + h)), and is
//! conserved when L′ does not depend on qᵢ and no external torque acts on it: the motors'
//! reaction is cancelled by the change of the sₖ they cause.

use super::derivation::TopDerivation;
use super::scene::TopScene;
use crate::lagrange::LagrangeError;
use crate::rigid::{DrivenRotor, Rotor};
use crate::sym::mat3::{dot, mat_vec, transpose};
use crate::sym::{Arena, ExprId, Rational, SymbolId};

/// A top with driven rotors, derived: q̈ and Ω̇ over the state `[q, q̇, Ω]` and the motor
/// torques.
#[derive(Clone, Debug, PartialEq)]
pub struct DrivenDerivation {
    /// The scene [`DrivenDerivation::effective`] derives: inertia I′, the wheels as
    /// constant-rate rotors at the spin symbols sₖ, the reaction as a body torque.
    pub scene: TopScene,
    /// The scene of inertia I′ = I − Σ J â âᵀ with the wheels at the constant absolute spins
    /// sₖ and the motors' reaction −Σ uₖ âₖ as a body torque: its q̈, energy and momenta
    /// read sₖ, which [`DrivenDerivation::accel`] and the others have substituted.
    pub effective: TopDerivation,
    /// q̈ over q, q̇, the rates Ω and the torques u.
    pub accel: [ExprId; 3],
    /// Ω̇ₖ = uₖ/Jₖ − âₖ·ω̇, one per driven rotor.
    pub rotor_accel: Vec<ExprId>,
    /// The energy T + V over q, q̇ and Ω.
    pub energy: ExprId,
    /// For each angle, its momentum ∂L/∂q̇ᵢ over q, q̇ and Ω if it is conserved.
    pub conserved_momenta: Vec<Option<ExprId>>,
}

impl TopScene {
    /// Derives the top with the driven rotors `driven` besides its own (constant-rate)
    /// rotors, in the chart [`TopScene::sequence`]: `rates[k]` is the symbol of wheel k's
    /// relative rate Ωₖ (a state variable; the caller reads it from the state), each
    /// rotor's `torque` the symbol or value of its motor torque uₖ.
    ///
    /// # Errors
    /// As [`TopScene::derive`] and [`TopScene::eulerian_rhs`] (a singular I′ gives
    /// [`LagrangeError::SingularMassMatrix`]); [`LagrangeError::Sym`] for a driven rotor
    /// whose axis is identically zero, or a substitution that divides by zero.
    pub fn derive_driven(
        &self,
        arena: &mut Arena,
        driven: &[DrivenRotor],
        rates: &[ExprId],
    ) -> Result<DrivenDerivation, LagrangeError> {
        let mut effective = self.clone();
        let mut spins: Vec<ExprId> = Vec::with_capacity(driven.len());
        let mut axes: Vec<[ExprId; 3]> = Vec::with_capacity(driven.len());
        let mut reaction: Vec<[ExprId; 3]> = effective.body_torque.into_iter().collect();
        for (k, d) in driven.iter().enumerate() {
            let a = d.unit_axis(arena)?;
            // J a aᵀ/|a|²: rational for a literal axis, where â âᵀ would carry square roots.
            let a2 = dot(arena, &d.axis, &d.axis);
            for i in 0..3 {
                for j in 0..3 {
                    let jaa = arena.product(&[d.inertia, d.axis[i], d.axis[j]]);
                    let jaa = arena.div(jaa, a2)?;
                    let e = arena.sub(effective.inertia[i][j], jaa);
                    effective.inertia[i][j] = arena.expand(e);
                }
            }
            let s = arena.input(&format!("s_rotor_{k}"));
            effective.rotors.push(Rotor {
                axis: d.axis,
                inertia: d.inertia,
                rate: s,
            });
            let mu = arena.neg(d.torque);
            reaction.push(a.map(|c| arena.mul(mu, c)));
            spins.push(s);
            axes.push(a);
        }
        if !driven.is_empty() {
            effective.body_torque = Some(std::array::from_fn(|i| {
                let parts: Vec<ExprId> = reaction.iter().map(|v| v[i]).collect();
                arena.sum(&parts)
            }));
        }
        let top = effective.derive(arena)?;
        let omega_dot = effective.eulerian_rhs(arena, &top.rotation, &top.omega)?;
        // sₖ = Ωₖ + âₖ·ω(q, q̇).
        let mut map: Vec<(SymbolId, ExprId)> = Vec::with_capacity(driven.len());
        for ((&s, a), &rate) in spins.iter().zip(&axes).zip(rates) {
            let along = dot(arena, a, &top.omega);
            if let Some(sym) = arena.as_symbol(s) {
                map.push((sym, arena.add(rate, along)));
            }
        }
        let subs = |arena: &mut Arena, e: ExprId| arena.subs(e, &map);
        let mut accel = [arena.zero(); 3];
        for (out, &a) in accel.iter_mut().zip(&top.accelerations.accel) {
            *out = subs(arena, a)?;
        }
        let mut rotor_accel = Vec::with_capacity(driven.len());
        for (d, a) in driven.iter().zip(&axes) {
            let spin_up = arena.div(d.torque, d.inertia)?;
            let along = dot(arena, a, &omega_dot);
            let e = arena.sub(spin_up, along);
            rotor_accel.push(subs(arena, e)?);
        }
        let half = arena.constant(Rational::new(1, 2).unwrap_or(Rational::ONE));
        let mut kinetic = vec![top.kinetic, top.potential];
        for (d, &s) in driven.iter().zip(&spins) {
            let s2 = arena.mul(s, s);
            kinetic.push(arena.product(&[half, d.inertia, s2]));
        }
        let energy = arena.sum(&kinetic);
        let energy = subs(arena, energy)?;
        // Conserved: L′ free of qᵢ and no external torque on it (the motors' reaction is
        // internal; see the module's docs).
        let lagrangian = top.lagrangian(arena);
        let external = self.applied_torque(arena, &top.rotation, &top.omega);
        let forces = mat_vec(arena, &transpose(&top.rate_matrix), &external);
        let mut conserved_momenta = Vec::with_capacity(3);
        let coords = top.coords().q.clone();
        for ((&qi, &force), &momentum) in coords.iter().zip(&forces).zip(&top.equations.momenta) {
            let free_of = match arena.as_symbol(qi) {
                Some(q) => {
                    let d = arena.diff(lagrangian, q);
                    let d = arena.expand(d);
                    let f = arena.expand(force);
                    d == arena.zero() && f == arena.zero()
                }
                None => false,
            };
            conserved_momenta.push(if free_of {
                Some(subs(arena, momentum)?)
            } else {
                None
            });
        }
        Ok(DrivenDerivation {
            scene: effective,
            effective: top,
            accel,
            rotor_accel,
            energy,
            conserved_momenta,
        })
    }
}
