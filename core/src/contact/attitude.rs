//! The attitude in expressions: the rotation of a stored quaternion of any non-zero size and
//! the quaternion's rate, as the contact derivation writes them.
//!
//! The free body's derivation writes the same two; the layering rule keeps a scene from
//! reaching into another, and they are too small to earn a shared layer of their own.

use crate::sym::mat3::Mat3;
use crate::sym::{Arena, ExprId, Rational, SymError};

/// R of a quaternion q = (w, x, y, z) of any non-zero size, body to space: the homogeneous
/// form divided by |q|², so a quaternion drifting off the unit sphere still gives a rotation.
///
/// # Errors
/// [`SymError`] if |q|² is refused as a divisor (never for the state's symbols).
pub(crate) fn rotation_of_quaternion(arena: &mut Arena, q: [ExprId; 4]) -> Result<Mat3, SymError> {
    let [w, x, y, z] = q;
    let sq = q.map(|c| arena.mul(c, c));
    let norm2 = arena.sum(&sq);
    let inv = arena.recip(norm2)?;
    let two = arena.integer(2);
    // Diagonal: w² + a² − b² − c² for the axis a and the other two b, c.
    let diagonal = |arena: &mut Arena, a: usize| {
        let mut terms = vec![sq[0], sq[a]];
        for k in (1..4).filter(|&k| k != a) {
            terms.push(arena.neg(sq[k]));
        }
        let s = arena.sum(&terms);
        arena.mul(s, inv)
    };
    // Off-diagonal: 2 (a b ± w c) / |q|².
    let off = |arena: &mut Arena, a: ExprId, b: ExprId, c: ExprId, plus: bool| {
        let ab = arena.mul(a, b);
        let wc = arena.mul(w, c);
        let s = if plus {
            arena.add(ab, wc)
        } else {
            arena.sub(ab, wc)
        };
        arena.product(&[two, s, inv])
    };
    Ok([
        [
            diagonal(arena, 1),
            off(arena, x, y, z, false),
            off(arena, x, z, y, true),
        ],
        [
            off(arena, x, y, z, true),
            diagonal(arena, 2),
            off(arena, y, z, x, false),
        ],
        [
            off(arena, x, z, y, false),
            off(arena, y, z, x, true),
            diagonal(arena, 3),
        ],
    ])
}

/// q̇ = ½ q ⊗ (0, ω) for the body angular velocity ω.
pub(crate) fn quaternion_rate(
    arena: &mut Arena,
    q: [ExprId; 4],
    omega: [ExprId; 3],
) -> [ExprId; 4] {
    let [w, x, y, z] = q;
    let [p, r, s] = omega;
    let half = arena.constant(Rational::new(1, 2).unwrap_or(Rational::ONE));
    let mut combine = |terms: &[(ExprId, ExprId, bool)]| {
        let parts: Vec<ExprId> = terms
            .iter()
            .map(|&(a, b, positive)| {
                let t = arena.mul(a, b);
                if positive { t } else { arena.neg(t) }
            })
            .collect();
        let sum = arena.sum(&parts);
        arena.mul(half, sum)
    };
    [
        combine(&[(x, p, false), (y, r, false), (z, s, false)]),
        combine(&[(w, p, true), (y, s, true), (z, r, false)]),
        combine(&[(w, r, true), (z, p, true), (x, s, false)]),
        combine(&[(w, s, true), (x, r, true), (y, p, false)]),
    ]
}
