//! The torques on a body on a table beyond its law's friction, as the derivation adds them
//! to Euler's equation: the linear resistances and a user couple as a function of the state,
//! and pivoting friction as a torque per newton of the normal force, which each phase solves
//! for with N (`derivation.rs`).

use super::error::ContactError;
use super::scene::{ContactLaw, ContactScene, ContactTorques};
use crate::sym::mat3::dot;
use crate::sym::{Arena, ExprId, Rational};

/// The torques a phase adds to Euler's equation: `fixed` a function of the state, and
/// N `per_normal` proportional to the normal force.
pub(super) struct Applied {
    pub(super) fixed: [ExprId; 3],
    pub(super) per_normal: Option<[ExprId; 3]>,
}

/// The spin ω·γ below which sign(ω·γ) is written as ω·γ/√((ω·γ)² + ε²), ε = 10⁻¹⁵⁰ rad/s:
/// exact to 10⁻²⁰ wherever a run can be (a spin this small has stopped, which a witness
/// sees long before), and 0 rather than 0/0 at a spin of exactly zero.
const SIGN_FLOOR_EXPONENT: i64 = 300;

/// `torques` acting on the body: the resistance −c_r ω_∥ − c_s ω_⊥ (ω_⊥ = (ω·γ) γ) and the
/// user couple as `fixed`, the pivoting friction −ℓ_p sign(ω·γ) γ per unit normal force.
///
/// # Errors
/// [`ContactError::Sym`] if the engine refuses the sign's root or division (it cannot: the
/// radicand holds a positive constant).
pub(super) fn applied(
    arena: &mut Arena,
    omega: &[ExprId; 3],
    gamma: &[ExprId; 3],
    torques: &ContactTorques,
) -> Result<Applied, ContactError> {
    let w_g = dot(arena, omega, gamma);
    let perp = gamma.map(|g| arena.mul(w_g, g));
    let fixed = std::array::from_fn(|j| {
        let mut terms = Vec::new();
        if let Some(c) = torques.rolling_resistance {
            let par = arena.sub(omega[j], perp[j]);
            let t = arena.mul(c, par);
            terms.push(arena.neg(t));
        }
        if let Some(c) = torques.spin_resistance {
            let t = arena.mul(c, perp[j]);
            terms.push(arena.neg(t));
        }
        if let Some(u) = torques.user {
            terms.push(u[j]);
        }
        arena.sum(&terms)
    });
    let per_normal = match torques.pivoting {
        None => None,
        Some(l) => {
            let floor = Rational::new(1, 10)
                .and_then(|r| r.checked_pow(SIGN_FLOOR_EXPONENT))
                .unwrap_or(Rational::ZERO);
            let floor = arena.constant(floor);
            let w2 = arena.mul(w_g, w_g);
            let w2 = arena.add(w2, floor);
            let size = arena.sqrt(w2)?;
            let sign = arena.div(w_g, size)?;
            let nl = arena.neg(l);
            let scale = arena.mul(nl, sign);
            Some(gamma.map(|g| arena.mul(scale, g)))
        }
    };
    Ok(Applied { fixed, per_normal })
}

impl ContactScene {
    /// `torques` with a rolling law's own resistances joined in.
    ///
    /// # Errors
    /// [`ContactError::DeclaredTwice`] for a resistance both declare.
    pub(super) fn merged(&self, torques: &ContactTorques) -> Result<ContactTorques, ContactError> {
        let mut out = *torques;
        if let ContactLaw::Rolling {
            rolling_resistance,
            spin_resistance,
        } = self.law
        {
            for (name, law, extra) in [
                (
                    "rolling_resistance",
                    rolling_resistance,
                    &mut out.rolling_resistance,
                ),
                ("spin_resistance", spin_resistance, &mut out.spin_resistance),
            ] {
                match (law, &*extra) {
                    (Some(_), Some(_)) => return Err(ContactError::DeclaredTwice { name }),
                    (Some(c), None) => *extra = Some(c),
                    _ => {}
                }
            }
        }
        Ok(out)
    }
}
