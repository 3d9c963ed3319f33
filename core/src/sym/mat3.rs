//! Small symbolic matrices: 3×3 products, dot and cross products, and determinants and
//! cofactors of square matrices, the algebra every scene's kinematics is written in.
//!
//! Products are left unexpanded (call [`Arena::expand`] where cancellation matters), so a
//! caller chooses when to pay for expansion.
//!
//! ```
//! use precess_core::sym::{Arena, mat3};
//! let mut a = Arena::new();
//! let (x, y) = (a.parameter("x"), a.parameter("y"));
//! let (o, z) = (a.one(), a.zero());
//! // e₁ × e₂ = e₃, and (x, y, 0)·(0, 0, 1) = 0.
//! assert_eq!(mat3::cross(&mut a, &[o, z, z], &[z, o, z]), [z, z, o]);
//! assert_eq!(mat3::dot(&mut a, &[x, y, z], &[z, z, o]), z);
//! // det [[x, y], [y, x]] = x² − y².
//! let d = mat3::determinant(&mut a, &[vec![x, y], vec![y, x]]);
//! let (x2, y2) = (a.mul(x, x), a.mul(y, y));
//! assert_eq!(a.expand(d), a.sub(x2, y2));
//! ```

use super::{Arena, ExprId};

/// A 3×3 matrix of expressions, row-major.
pub type Mat3 = [[ExprId; 3]; 3];

/// `a b`, entries left unexpanded.
pub fn mat_mul(arena: &mut Arena, a: &Mat3, b: &Mat3) -> Mat3 {
    let mut out = [[arena.zero(); 3]; 3];
    for (i, row) in out.iter_mut().enumerate() {
        for (j, entry) in row.iter_mut().enumerate() {
            let terms: Vec<ExprId> = (0..3).map(|k| arena.mul(a[i][k], b[k][j])).collect();
            *entry = arena.sum(&terms);
        }
    }
    out
}

/// `m v`.
pub fn mat_vec(arena: &mut Arena, m: &Mat3, v: &[ExprId; 3]) -> [ExprId; 3] {
    let mut out = [arena.zero(); 3];
    for (i, o) in out.iter_mut().enumerate() {
        let terms: Vec<ExprId> = (0..3).map(|k| arena.mul(m[i][k], v[k])).collect();
        *o = arena.sum(&terms);
    }
    out
}

/// `mᵀ`.
pub fn transpose(m: &Mat3) -> Mat3 {
    let mut t = *m;
    for (i, row) in t.iter_mut().enumerate() {
        for (j, e) in row.iter_mut().enumerate() {
            *e = m[j][i];
        }
    }
    t
}

/// `a · b`.
pub fn dot(arena: &mut Arena, a: &[ExprId; 3], b: &[ExprId; 3]) -> ExprId {
    let terms: Vec<ExprId> = (0..3).map(|k| arena.mul(a[k], b[k])).collect();
    arena.sum(&terms)
}

/// `a × b`.
pub fn cross(arena: &mut Arena, a: &[ExprId; 3], b: &[ExprId; 3]) -> [ExprId; 3] {
    let mut out = [arena.zero(); 3];
    for (i, o) in out.iter_mut().enumerate() {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        let p = arena.mul(a[j], b[k]);
        let m = arena.mul(a[k], b[j]);
        *o = arena.sub(p, m);
    }
    out
}

/// `det m` of a square matrix (rows of equal length, any size), by cofactor expansion along
/// the first row, skipping zero entries. The cost grows as n!: meant for the small blocks of
/// a mass matrix and for inertia tensors.
pub fn determinant(arena: &mut Arena, m: &[Vec<ExprId>]) -> ExprId {
    match m.len() {
        0 => arena.one(),
        1 => m[0][0],
        _ => {
            let mut terms = Vec::new();
            for (j, &entry) in m[0].iter().enumerate() {
                if entry == arena.zero() {
                    continue;
                }
                let c = cofactor(arena, m, 0, j);
                terms.push(arena.mul(entry, c));
            }
            arena.sum(&terms)
        }
    }
}

/// The (i, j) cofactor of a square matrix: `(−1)^(i+j)` times the minor without row i and
/// column j.
pub fn cofactor(arena: &mut Arena, m: &[Vec<ExprId>], i: usize, j: usize) -> ExprId {
    let minor: Vec<Vec<ExprId>> = m
        .iter()
        .enumerate()
        .filter(|&(r, _)| r != i)
        .map(|(_, row)| {
            row.iter()
                .enumerate()
                .filter(|&(c, _)| c != j)
                .map(|(_, &e)| e)
                .collect()
        })
        .collect();
    let d = determinant(arena, &minor);
    if (i + j) % 2 == 1 { arena.neg(d) } else { d }
}

/// `adj(m) b`, the numerators of `m⁻¹ b = adj(m) b / det m` for a square `m`: row r is
/// Σ_c C_cr b_c over the cofactors C, each expanded (so one that cancels to zero drops its
/// term) and the sums left unexpanded. The division by det m is the caller's, which decides
/// how a zero determinant is refused.
///
/// ```
/// use precess_core::sym::{Arena, mat3};
/// let mut a = Arena::new();
/// let (x, y) = (a.parameter("x"), a.parameter("y"));
/// let (o, z) = (a.one(), a.zero());
/// // adj [[x, 0], [0, y]] = [[y, 0], [0, x]]: adj · (1, 1) = (y, x).
/// let n = mat3::adjugate_times(&mut a, &[vec![x, z], vec![z, y]], &[o, o]);
/// assert_eq!(n, vec![y, x]);
/// ```
pub fn adjugate_times(arena: &mut Arena, m: &[Vec<ExprId>], b: &[ExprId]) -> Vec<ExprId> {
    (0..m.len())
        .map(|r| {
            let mut terms = Vec::with_capacity(b.len());
            for (c, &bc) in b.iter().enumerate() {
                let cof = cofactor(arena, m, c, r);
                let cof = arena.expand(cof);
                if cof != arena.zero() {
                    terms.push(arena.mul(cof, bc));
                }
            }
            arena.sum(&terms)
        })
        .collect()
}
