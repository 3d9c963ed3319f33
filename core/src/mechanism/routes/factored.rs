//! The factored route: `M = L D Lᵀ` of the symbolic mass matrix, written as unexpanded
//! expressions so that lowering gives straight-line code with every intermediate on the
//! stack, then the two triangular solves.
//!
//! For j = 0 … n−1 (with Σ over k < j):
//!
//! - D_j = M_jj − Σ L_jk² D_k
//! - L_ij = (M_ij − Σ L_ik L_jk D_k) / D_j   for i > j
//!
//! then `L y = f`, `z = y / D`, `Lᵀ q̈ = z`. M is symmetric positive definite wherever the
//! mechanism is regular, so every pivot D_j > 0 there; the run-time model checks them.
//! Structural zeros of M (decoupled coordinates) stay zero through the canonical
//! constructors, so their terms vanish from the code.

use crate::mechanism::error::MechanismError;
use crate::sym::{Arena, ExprId};

/// `q̈` and the pivots D_j of the LDLᵀ solve of `M q̈ = f`.
///
/// # Errors
/// [`MechanismError::SingularMassMatrix`] when a pivot is identically zero.
pub(crate) fn ldlt_solve(
    arena: &mut Arena,
    mass: &[Vec<ExprId>],
    forcing: &[ExprId],
) -> Result<(Vec<ExprId>, Vec<ExprId>), MechanismError> {
    let n = forcing.len();
    let zero = arena.zero();
    let mut l = vec![vec![zero; n]; n];
    let mut d = vec![zero; n];
    let mut inv_d = vec![zero; n];
    for j in 0..n {
        let mut terms = vec![mass[j][j]];
        for k in 0..j {
            if l[j][k] != zero {
                let t = arena.product(&[l[j][k], l[j][k], d[k]]);
                terms.push(arena.neg(t));
            }
        }
        d[j] = arena.sum(&terms);
        if d[j] == zero {
            return Err(MechanismError::SingularMassMatrix {
                pivot: j,
                value: 0.0,
            });
        }
        inv_d[j] = arena.recip(d[j])?;
        for i in j + 1..n {
            let mut terms = vec![mass[i][j]];
            for k in 0..j {
                if l[i][k] != zero && l[j][k] != zero {
                    let t = arena.product(&[l[i][k], l[j][k], d[k]]);
                    terms.push(arena.neg(t));
                }
            }
            let s = arena.sum(&terms);
            l[i][j] = arena.mul(s, inv_d[j]);
        }
    }
    // L y = f
    let mut y = vec![zero; n];
    for i in 0..n {
        let mut terms = vec![forcing[i]];
        for k in 0..i {
            if l[i][k] != zero {
                let t = arena.mul(l[i][k], y[k]);
                terms.push(arena.neg(t));
            }
        }
        y[i] = arena.sum(&terms);
    }
    // Lᵀ x = y / D
    let mut x = vec![zero; n];
    for i in (0..n).rev() {
        let mut terms = vec![arena.mul(y[i], inv_d[i])];
        for k in i + 1..n {
            if l[k][i] != zero {
                let t = arena.mul(l[k][i], x[k]);
                terms.push(arena.neg(t));
            }
        }
        x[i] = arena.sum(&terms);
    }
    Ok((x, d))
}
