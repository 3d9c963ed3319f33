//! A free body's rotors ([`Rotor`], shared with tops in `rigid`): their total relative
//! momentum in principal axes, for the Volterra–Zhukovsky equations I ω̇ = τ − ω × (I ω + h),
//! and the equations with driven rotors ([`crate::rigid::DrivenRotor`]), whose rates are
//! state variables; with the two expression helpers these and `derivation.rs` use (a
//! constant folded to one number, a checked reciprocal). `derivation.rs` takes names from
//! here and this file none from it, so the two form no import circle.

use super::error::FreeError;
use super::scene::FreeScene;
use crate::rigid::{Rotor, total_momentum};
use crate::sym::mat3::{Mat3, cofactor, cross, determinant, dot, mat_vec, transpose};
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

/// ω̇, the driven rotors' Ω̇ and their inertias, as [`FreeScene::driven_dynamics`] returns them.
pub(super) type Driven = ([ExprId; 3], Vec<ExprId>, Vec<Mat3>);

impl FreeScene {
    /// The equations with driven rotors (principal axes, âₖ each rotor's unit axis, h the
    /// total relative momentum of every wheel):
    /// (I − Σ Jₖ âₖ âₖᵀ) ω̇ = τ − ω × (I ω + h) − Σ uₖ âₖ, solved by the adjugate, and
    /// Ω̇ₖ = uₖ/Jₖ − âₖ·ω̇. Constant entries of the inverse fold to one number each.
    pub(super) fn driven_dynamics(
        &self,
        arena: &mut Arena,
        omega: &[ExprId; 3],
        torque: &[ExprId; 3],
        h: &[ExprId; 3],
        rates: &[ExprId],
    ) -> Result<Driven, FreeError> {
        let to_principal = transpose(&self.principal_rotation);
        let z = arena.zero();
        let mut a: Mat3 = [[z; 3]; 3];
        for (k, m) in self.moments.iter().enumerate() {
            a[k][k] = *m;
        }
        let mut steps = Vec::with_capacity(self.driven.len());
        let mut axes = Vec::with_capacity(self.driven.len());
        for (k, r) in self.driven.iter().enumerate() {
            let unit = r.unit_axis(arena).map_err(|_| FreeError::ZeroRotorAxis {
                rotor: self.rotors.len() + k,
            })?;
            let up = mat_vec(arena, &to_principal, &unit);
            for i in 0..3 {
                for j in 0..3 {
                    let jaa = arena.product(&[r.inertia, up[i], up[j]]);
                    let jaa = fold(arena, jaa);
                    a[i][j] = arena.sub(a[i][j], jaa);
                    a[i][j] = fold(arena, a[i][j]);
                }
            }
            steps.push(a);
            axes.push(up);
        }
        // b = τ − ω × (I ω + h) − Σ uₖ âₖ.
        let l: [ExprId; 3] = std::array::from_fn(|k| {
            let iw = arena.mul(self.moments[k], omega[k]);
            arena.add(iw, h[k])
        });
        let gyro = cross(arena, omega, &l);
        let b: [ExprId; 3] = std::array::from_fn(|i| {
            let mut terms = vec![torque[i]];
            terms.push(arena.neg(gyro[i]));
            for (r, up) in self.driven.iter().zip(&axes) {
                let push = arena.mul(r.torque, up[i]);
                terms.push(arena.neg(push));
            }
            arena.sum(&terms)
        });
        let rows: Vec<Vec<ExprId>> = a.iter().map(|row| row.to_vec()).collect();
        let det = determinant(arena, &rows);
        let quantity = "determinant of I − Σ J â âᵀ (the body without its driven wheels)";
        let inv_det = reciprocal(arena, det, quantity)?;
        let mut omega_dot = [z; 3];
        for (i, out) in omega_dot.iter_mut().enumerate() {
            let mut terms = Vec::with_capacity(3);
            for (j, bj) in b.iter().enumerate() {
                // (A⁻¹)ᵢⱼ = Cⱼᵢ / det A.
                let c = cofactor(arena, &rows, j, i);
                let entry = arena.mul(c, inv_det);
                let entry = fold(arena, entry);
                if arena.is_zero(entry).unwrap_or(false) {
                    continue;
                }
                terms.push(arena.mul(entry, *bj));
            }
            *out = arena.sum(&terms);
        }
        let mut rotor_rhs = Vec::with_capacity(self.driven.len());
        for ((r, up), _) in self.driven.iter().zip(&axes).zip(rates) {
            let inv_j = reciprocal(arena, r.inertia, "rotor inertia")?;
            let drive = arena.mul(r.torque, inv_j);
            let along = dot(arena, up, &omega_dot);
            rotor_rhs.push(arena.sub(drive, along));
        }
        Ok((omega_dot, rotor_rhs, steps))
    }
}

/// A constant expression as one constant, so no arithmetic on constants is left for run
/// time (exact when it folded to a rational, else its value rounded once).
pub(super) fn fold(arena: &mut Arena, e: ExprId) -> ExprId {
    if arena.as_rational(e).is_some() || !arena.free_symbols(e).is_empty() {
        return e;
    }
    let value = arena.eval(e, &[]);
    arena.float(value).unwrap_or(e)
}

/// 1/e, folded when constant.
///
/// # Errors
/// [`FreeError::ZeroInertia`] naming `quantity` when e is identically zero.
pub(super) fn reciprocal(
    arena: &mut Arena,
    e: ExprId,
    quantity: &'static str,
) -> Result<ExprId, FreeError> {
    if arena.is_zero(e).unwrap_or(false) {
        return Err(FreeError::ZeroInertia { quantity });
    }
    let r = arena
        .recip(e)
        .map_err(|_| FreeError::ZeroInertia { quantity })?;
    Ok(fold(arena, r))
}
