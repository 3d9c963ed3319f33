//! Internal rotors: symmetric wheels spinning at a constant rate relative to the body about a
//! body-fixed axis, which make the body a gyrostat (free bodies and tops alike).
//!
//! A wheel symmetric about its axis a and spun at the relative rate Ω carries the relative
//! angular momentum h = J Ω â (J its axial moment, â = a/|a|), constant in the body. The
//! body's own inertia I includes the wheel as if it were locked (its transverse and axial
//! moments about the centre of mass are part of the body's parts), so the total angular
//! momentum is I ω + h and Euler's equations become the Volterra–Zhukovsky equations of the
//! gyrostat,
//!
//! I ω̇ = τ − ω × (I ω + h).
//!
//! The motor that holds Ω constant does work on the wheel, so the wheel's own kinetic energy
//! is not the conserved one; ½ ωᵀ I ω is (its rate is ω·τ, the term ω·(ω × h) vanishing).

use crate::sym::mat3::dot;
use crate::sym::{Arena, ExprId, SymError};

/// A symmetric wheel spinning at a constant rate relative to the body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rotor {
    /// Its spin axis, fixed in the body, description axes (any non-zero length: it is
    /// normalised).
    pub axis: [ExprId; 3],
    /// Its moment of inertia J about its own axis.
    pub inertia: ExprId,
    /// Its spin rate Ω relative to the body (rad/s, signed about `axis`).
    pub rate: ExprId,
}

impl Rotor {
    /// Its relative angular momentum h = J Ω a/|a|, description axes.
    ///
    /// # Errors
    /// [`SymError`] (a division by zero) if the axis is identically zero.
    pub fn momentum(&self, arena: &mut Arena) -> Result<[ExprId; 3], SymError> {
        let a2 = dot(arena, &self.axis, &self.axis);
        let norm = arena.sqrt(a2)?;
        let scale = arena.mul(self.inertia, self.rate);
        let scale = arena.div(scale, norm)?;
        Ok(self.axis.map(|c| arena.mul(scale, c)))
    }
}

/// The rotors' total relative angular momentum Σₖ hₖ in description axes, or `None` without
/// rotors (so a body without one derives exactly the expressions it did before).
///
/// # Errors
/// The index of the first rotor whose axis is identically zero, with its [`SymError`].
pub fn total_momentum(
    arena: &mut Arena,
    rotors: &[Rotor],
) -> Result<Option<[ExprId; 3]>, (usize, SymError)> {
    if rotors.is_empty() {
        return Ok(None);
    }
    let mut parts: Vec<[ExprId; 3]> = Vec::with_capacity(rotors.len());
    for (k, r) in rotors.iter().enumerate() {
        parts.push(r.momentum(arena).map_err(|e| (k, e))?);
    }
    Ok(Some(std::array::from_fn(|i| {
        let terms: Vec<ExprId> = parts.iter().map(|p| p[i]).collect();
        arena.sum(&terms)
    })))
}
