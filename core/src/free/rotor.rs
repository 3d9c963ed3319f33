//! A free body's rotors ([`Rotor`], shared with tops in `rigid`): their total relative
//! momentum in principal axes, for the Volterra–Zhukovsky equations I ω̇ = τ − ω × (I ω + h).

use super::error::FreeError;
use crate::rigid::{Rotor, total_momentum};
use crate::sym::mat3::{Mat3, mat_vec, transpose};
use crate::sym::{Arena, ExprId};

/// The rotors' total relative momentum in principal axes, Rₚ𝒹ᵀ Σ hₖ, or `None` without
/// rotors (so a body without one derives exactly the expressions it did before).
///
/// # Errors
/// [`FreeError::ZeroRotorAxis`] for a rotor whose axis is identically zero.
pub(super) fn principal_momentum(
    arena: &mut Arena,
    rotors: &[Rotor],
    principal_rotation: &Mat3,
) -> Result<Option<[ExprId; 3]>, FreeError> {
    let Some(total) =
        total_momentum(arena, rotors).map_err(|(rotor, _)| FreeError::ZeroRotorAxis { rotor })?
    else {
        return Ok(None);
    };
    Ok(Some(mat_vec(arena, &transpose(principal_rotation), &total)))
}
