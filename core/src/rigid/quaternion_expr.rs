//! The attitude in expressions, as the scenes with a quaternion state (the free body, the
//! body on a table) write it: the rotation of a stored quaternion of any non-zero size and
//! the quaternion's rate.

use crate::sym::mat3::Mat3;
use crate::sym::{Arena, ExprId, Rational, SymError};

/// R of a quaternion q = (w, x, y, z) of any non-zero size, body to space: the homogeneous
/// form divided by |q|², so a quaternion drifting off the unit sphere still gives a rotation.
/// The scenes read their stored quaternion through it, so the steppers need not keep it unit.
///
/// # Errors
/// [`SymError`] if |q|² is refused as a divisor (never for the state's symbols).
pub fn rotation_of_quaternion(arena: &mut Arena, q: [ExprId; 4]) -> Result<Mat3, SymError> {
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
pub fn quaternion_rate(arena: &mut Arena, q: [ExprId; 4], omega: [ExprId; 3]) -> [ExprId; 4] {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::codegen::Program;

    /// The symbolic rotation agrees with nalgebra's for a quaternion off the unit sphere.
    #[test]
    fn rotation_matches_nalgebra_for_any_norm() {
        let mut a = Arena::new();
        let q: [ExprId; 4] = std::array::from_fn(|k| a.input(&format!("q{k}")));
        let r = rotation_of_quaternion(&mut a, q).expect("|q|² is a divisor");
        let p = Program::lower(&a, r.as_flattened());
        let raw = [0.3, -1.2, 0.7, 2.1];
        let out = p.eval(&raw);
        let unit = nalgebra::UnitQuaternion::new_normalize(nalgebra::Quaternion::new(
            raw[0], raw[1], raw[2], raw[3],
        ));
        let m = unit.to_rotation_matrix();
        for i in 0..3 {
            for j in 0..3 {
                assert!((out[3 * i + j] - m[(i, j)]).abs() < 1e-15, "{i}{j}");
            }
        }
    }
}
