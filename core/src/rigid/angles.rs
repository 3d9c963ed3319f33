//! Euler-angle sequences: the rotation they parametrise and the body angular velocity,
//! derived symbolically from `Ω = Rᵀ Ṙ` rather than typed in, and the angles of a numeric
//! attitude.

use nalgebra::Matrix3;

use crate::lagrange::Coordinates;
use crate::sym::mat3::{Mat3, mat_mul, transpose};
use crate::sym::{Arena, ExprId};

/// The angle sequence of a top's generalised coordinates.
///
/// # Examples
///
/// The ZXZ body angular velocity is derived, not typed in; its third component is the
/// textbook ω₃ = φ̇ cos θ + ψ̇:
///
/// ```
/// use precess_core::rigid::AngleSequence;
/// use precess_core::sym::Arena;
/// let mut a = Arena::new();
/// let seq = AngleSequence::Zxz;
/// let c = seq.coordinates(&mut a);
/// let omega = seq.body_rates(&mut a, &c);
/// let b = seq.rate_matrix(&mut a, &c, &omega);
/// // ∂ω₃/∂ψ̇ = 1 and ∂ω₃/∂θ̇ = 0 everywhere.
/// assert_eq!((b[2][2], b[2][1]), (a.one(), a.zero()));
/// let cos = a.cos(c.q[1]);
/// let phi_dot_cos = a.mul(cos, c.rates[0]);
/// assert_eq!(omega[2], a.add(phi_dot_cos, c.rates[2]));
/// ```
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

    /// The other sequence: the chart that is regular where this one is singular.
    pub fn other(self) -> AngleSequence {
        match self {
            AngleSequence::Zxz => AngleSequence::Zyx,
            AngleSequence::Zyx => AngleSequence::Zxz,
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

/// The angles of `seq` for the attitude `r` (body to space). Each angle is in (−π, π], and
/// θ of ZXZ in [0, π].
///
/// At the sequence's singular attitudes (sin θ = 0, cos pitch = 0) only a sum or difference
/// of the outer angles is determined; the split returned there is one valid choice.
///
/// # Examples
///
/// ```
/// use approx::assert_relative_eq;
/// use nalgebra::{Rotation3, Vector3};
/// use precess_core::rigid::{AngleSequence, angles_from_rotation};
/// // R = Rz(0.3) Rx(1.1) Rz(−0.4) gives back (φ, θ, ψ) = (0.3, 1.1, −0.4).
/// let r = Rotation3::from_axis_angle(&Vector3::z_axis(), 0.3)
///     * Rotation3::from_axis_angle(&Vector3::x_axis(), 1.1)
///     * Rotation3::from_axis_angle(&Vector3::z_axis(), -0.4);
/// let q = angles_from_rotation(AngleSequence::Zxz, r.matrix());
/// assert_relative_eq!(q.as_slice(), [0.3, 1.1, -0.4].as_slice(), epsilon = 1e-15);
/// ```
pub fn angles_from_rotation(seq: AngleSequence, r: &Matrix3<f64>) -> [f64; 3] {
    match seq {
        // R = Rz(φ) Rx(θ) Rz(ψ): R₂₂ = cos θ, (R₀₂, R₁₂) = sin θ (sin φ, −cos φ),
        // (R₂₀, R₂₁) = sin θ (sin ψ, cos ψ).
        AngleSequence::Zxz => [
            r[(0, 2)].atan2(-r[(1, 2)]),
            r[(0, 2)].hypot(r[(1, 2)]).atan2(r[(2, 2)]),
            r[(2, 0)].atan2(r[(2, 1)]),
        ],
        // R = Rz(yaw) Ry(pitch) Rx(roll): R₂₀ = −sin pitch, (R₂₁, R₂₂) = cos pitch (sin roll,
        // cos roll), (R₁₀, R₀₀) = cos pitch (sin yaw, cos yaw).
        AngleSequence::Zyx => [
            r[(1, 0)].atan2(r[(0, 0)]),
            (-r[(2, 0)]).atan2(r[(0, 0)].hypot(r[(1, 0)])),
            r[(2, 1)].atan2(r[(2, 2)]),
        ],
    }
}

/// A chart as the mode of a run that switches charts (a top through gimbal lock): its CSV
/// column `chart` holds 0 for ZXZ and 1 for ZYX.
impl crate::ode::Mode for AngleSequence {
    const COLUMN: Option<&'static str> = Some("chart");

    fn number(&self) -> f64 {
        match self {
            AngleSequence::Zxz => 0.0,
            AngleSequence::Zyx => 1.0,
        }
    }
}
