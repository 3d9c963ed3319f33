//! One spherical joint's angles, numerically: its rotation J(q) and rate matrix B(q) in
//! either sequence, and the exact map of (q, q̇) to the partner chart through the relative
//! attitude J and the relative angular velocity ω = B q̇ that both charts share.
//!
//! The angles from J are [`angles_from_rotation`]'s and the rates from ω are
//! [`rates_from_omega`]'s, the rules every chart switch uses.

use nalgebra::{Matrix3, Rotation3, Unit, Vector3};

use super::error::ChartError;
use super::singular::rates_from_omega;
use crate::rigid::{AngleSequence, angles_from_rotation};

fn elementary_axis(k: usize) -> Unit<Vector3<f64>> {
    match k {
        0 => Vector3::x_axis(),
        1 => Vector3::y_axis(),
        _ => Vector3::z_axis(),
    }
}

fn elementary(k: usize, angle: f64) -> Matrix3<f64> {
    *Rotation3::from_axis_angle(&elementary_axis(k), angle).matrix()
}

/// The joint rotation J(q) = E_a(q₀) E_b(q₁) E_c(q₂) of `sequence` (its elementary axes a,
/// b, c): the child's axes to the parent's axes, as [`AngleSequence::rotation`] builds it
/// symbolically.
///
/// # Examples
///
/// ```
/// use approx::assert_relative_eq;
/// use nalgebra::{Rotation3, Vector3};
/// use precess_core::rigid::joint_rotation;
/// use precess_core::rigid::AngleSequence;
/// let r = Rotation3::from_axis_angle(&Vector3::z_axis(), 0.3)
///     * Rotation3::from_axis_angle(&Vector3::y_axis(), -0.2)
///     * Rotation3::from_axis_angle(&Vector3::x_axis(), 1.1);
/// assert_relative_eq!(joint_rotation(AngleSequence::Zyx, &[0.3, -0.2, 1.1]), *r.matrix(),
///     epsilon = 1e-15);
/// ```
pub fn joint_rotation(sequence: AngleSequence, q: &[f64; 3]) -> Matrix3<f64> {
    let [a, b, c] = sequence.axes();
    elementary(a, q[0]) * elementary(b, q[1]) * elementary(c, q[2])
}

/// The rate matrix B(q) of `sequence`, with the relative angular velocity ω = B(q) q̇ in the
/// child's axes: from ω = vee(Jᵀ J̇), column k is the k-th elementary axis carried into the
/// child's axes by the rotations after it, (E₁E₂)ᵀ e_a, E₂ᵀ e_b, e_c.
///
/// # Examples
///
/// ZXZ's third row is the textbook ω₃ = φ̇ cos θ + ψ̇, and |det B| = |sin θ|:
///
/// ```
/// use approx::assert_relative_eq;
/// use precess_core::rigid::joint_rate_matrix;
/// use precess_core::rigid::AngleSequence;
/// let b = joint_rate_matrix(AngleSequence::Zxz, &[0.4, 0.7, -1.2]);
/// assert_relative_eq!(b[(2, 0)], 0.7f64.cos(), epsilon = 1e-15);
/// assert_relative_eq!(b[(2, 2)], 1.0, epsilon = 1e-15);
/// assert_relative_eq!(b.determinant().abs(), 0.7f64.sin(), epsilon = 1e-15);
/// ```
pub fn joint_rate_matrix(sequence: AngleSequence, q: &[f64; 3]) -> Matrix3<f64> {
    let [a, b, c] = sequence.axes();
    let (e1, e2) = (elementary(b, q[1]), elementary(c, q[2]));
    let col0 = (e1 * e2).transpose() * elementary_axis(a).into_inner();
    let col1 = e2.transpose() * elementary_axis(b).into_inner();
    let col2 = elementary_axis(c).into_inner();
    Matrix3::from_columns(&[col0, col1, col2])
}

/// The angles and rates of the chart `sequence` for the relative attitude `rotation` and the
/// relative angular velocity `omega` (child axes), with `|det B|` there.
///
/// # Errors
/// As [`rates_from_omega`]: [`ChartError::SingularChart`] at the chart's gimbal lock,
/// [`ChartError::NonFinite`] for non-finite input, [`ChartError::NonFiniteResult`] on overflow.
pub(crate) fn state_in_chart(
    sequence: AngleSequence,
    rotation: &Matrix3<f64>,
    omega: &Vector3<f64>,
) -> Result<([f64; 3], [f64; 3], f64), ChartError> {
    let q = angles_from_rotation(sequence, rotation);
    let b = joint_rate_matrix(sequence, &q);
    let qd = rates_from_omega(sequence, &b, &q, omega)?;
    Ok((q, qd, b.determinant().abs()))
}

/// Maps a spherical joint's angles `q` and rates `qd` in `sequence` to its partner chart
/// (`sequence.other()`) exactly, through J(q) and ω = B(q) q̇: returns the partner's angles,
/// rates and `|det B|` there.
///
/// # Errors
/// As [`rates_from_omega`] in the partner chart: [`ChartError::SingularChart`] if the
/// attitude is the partner's gimbal lock, [`ChartError::NonFinite`] for non-finite input.
///
/// # Examples
///
/// ZXZ near its lock (θ = 10⁻³) is far from ZYX's, and the map round-trips:
///
/// ```
/// use approx::assert_relative_eq;
/// use precess_core::rigid::map_to_partner;
/// use precess_core::rigid::AngleSequence;
/// let (q, qd) = ([0.3, 1e-3, -0.5], [0.2, -0.1, 4.0]);
/// let (p, pd, det) = map_to_partner(AngleSequence::Zxz, &q, &qd)?;
/// assert!(det > 0.9);
/// let (back, back_d, _) = map_to_partner(AngleSequence::Zyx, &p, &pd)?;
/// assert_relative_eq!(back.as_slice(), q.as_slice(), epsilon = 1e-12);
/// assert_relative_eq!(back_d.as_slice(), qd.as_slice(), epsilon = 1e-9);
/// # Ok::<(), precess_core::rigid::ChartError>(())
/// ```
pub fn map_to_partner(
    sequence: AngleSequence,
    q: &[f64; 3],
    qd: &[f64; 3],
) -> Result<([f64; 3], [f64; 3], f64), ChartError> {
    if !q.iter().chain(qd).all(|v| v.is_finite()) {
        return Err(ChartError::NonFinite {
            quantity: "a spherical joint's angles or rates",
            values: q.iter().chain(qd).copied().collect(),
        });
    }
    let rotation = joint_rotation(sequence, q);
    let omega = joint_rate_matrix(sequence, q) * Vector3::from(*qd);
    state_in_chart(sequence.other(), &rotation, &omega)
}
