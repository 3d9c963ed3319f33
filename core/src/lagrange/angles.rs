//! Euler-angle sequences: the rotation they parametrise and the body angular velocity,
//! derived symbolically from `Ω = Rᵀ Ṙ` rather than typed in.

use super::equations::Coordinates;
use crate::sym::{Arena, ExprId};

/// A 3×3 matrix of expressions, row-major.
pub type Mat3 = [[ExprId; 3]; 3];

/// The angle sequence of a top's generalised coordinates.
#[derive(Clone, Copy, PartialEq, Eq, Debug, Default)]
pub enum AngleSequence {
    /// Proper Euler angles (φ, θ, ψ), `R = Rz(φ) Rx(θ) Rz(ψ)`; singular at sin θ = 0.
    #[default]
    Zxz,
    /// Tait–Bryan yaw, pitch, roll, `R = Rz(yaw) Ry(pitch) Rx(roll)`; singular at
    /// cos(pitch) = 0.
    Zyx,
}

impl AngleSequence {
    /// The coordinate names, in order.
    pub fn names(self) -> [&'static str; 3] {
        match self {
            AngleSequence::Zxz => ["phi", "theta", "psi"],
            AngleSequence::Zyx => ["yaw", "pitch", "roll"],
        }
    }

    /// The elementary rotation axes (0 = x, 1 = y, 2 = z), outermost first.
    pub fn axes(self) -> [usize; 3] {
        match self {
            AngleSequence::Zxz => [2, 0, 2],
            AngleSequence::Zyx => [2, 1, 0],
        }
    }

    /// The coordinates of this sequence in `arena`.
    pub fn coordinates(self, arena: &mut Arena) -> Coordinates {
        Coordinates::new(arena, &self.names())
    }

    /// `R(q)`, mapping body axes to space axes.
    pub fn rotation(self, arena: &mut Arena, q: &[ExprId]) -> Mat3 {
        let [a0, a1, a2] = self.axes();
        let r0 = elementary(arena, a0, q[0]);
        let r1 = elementary(arena, a1, q[1]);
        let r2 = elementary(arena, a2, q[2]);
        let r01 = mat_mul(arena, &r0, &r1);
        let r = mat_mul(arena, &r01, &r2);
        r.map(|row| row.map(|e| arena.expand(e)))
    }

    /// The body angular velocity `ω = vee(Rᵀ Ṙ)`, linear in the rates: `ω = B(q) q̇`.
    pub fn body_rates(self, arena: &mut Arena, coords: &Coordinates) -> [ExprId; 3] {
        let r = self.rotation(arena, &coords.q);
        let rdot = r.map(|row| row.map(|e| arena.dt(e)));
        let rt = transpose(&r);
        let omega_hat = mat_mul(arena, &rt, &rdot);
        [omega_hat[2][1], omega_hat[0][2], omega_hat[1][0]].map(|e| arena.expand(e))
    }

    /// `B(q)` with `B_ij = ∂ω_i/∂q̇_j`.
    pub fn rate_matrix(self, arena: &mut Arena, coords: &Coordinates, omega: &[ExprId; 3]) -> Mat3 {
        let mut b = [[arena.zero(); 3]; 3];
        for (i, row) in b.iter_mut().enumerate() {
            for (j, entry) in row.iter_mut().enumerate() {
                let Some(s) = arena.as_symbol(coords.rates[j]) else {
                    continue;
                };
                let d = arena.diff(omega[i], s);
                *entry = arena.expand(d);
            }
        }
        b
    }
}

/// The rotation by `angle` about axis `axis` (0 = x, 1 = y, 2 = z).
pub fn elementary(arena: &mut Arena, axis: usize, angle: ExprId) -> Mat3 {
    let (c, s) = (arena.cos(angle), arena.sin(angle));
    let ms = arena.neg(s);
    let (o, z) = (arena.one(), arena.zero());
    match axis {
        0 => [[o, z, z], [z, c, ms], [z, s, c]],
        1 => [[c, z, s], [z, o, z], [ms, z, c]],
        _ => [[c, ms, z], [s, c, z], [z, z, o]],
    }
}

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
