//! When an angle chart is singular, and solving `B(q) q̇ = ω` there: one rule for every
//! path (the derived and interpreted tops, `ChartedTop` when it picks or
//! switches a chart, and a mechanism's spherical joints).
//!
//! The body angular velocity is `ω = B(q) q̇`. For ZXZ `|det B| = |sin θ|`, for ZYX
//! `|det B| = |cos pitch|`, so `|det B|` ∈ [0, 1] measures the distance to gimbal lock on the
//! same scale in both charts, and q̇ and q̈ grow like `1/|det B|` and worse towards it. A chart
//! is singular at q when `|det B(q)| < SINGULAR_DET`: within about 1e-12 rad of the lock the
//! rates would exceed 10¹² |ω| and carry no correct digits worth having.

use nalgebra::{Matrix3, Vector3};

use super::error::ChartError;
use crate::rigid::AngleSequence;

/// `|det B(q)|` below which an angle chart counts as singular (about 1e-12 rad from gimbal
/// lock: sin θ for ZXZ, cos pitch for ZYX).
pub const SINGULAR_DET: f64 = 1e-12;

/// `|det B(q)|` of the chart `sequence` at the angles `q`, under the one rule.
///
/// # Errors
/// [`ChartError::NonFinite`] for non-finite angles; [`ChartError::SingularChart`] when
/// `|det B| < SINGULAR_DET` (or B itself is not finite).
///
/// # Examples
///
/// ZXZ is singular with the body axis vertical (θ = 0, |det B| = |sin θ|):
///
/// ```
/// use nalgebra::Matrix3;
/// use precess_core::rigid::AngleSequence;
/// use precess_core::rigid::{ChartError, check_chart};
/// let zxz_b = |theta: f64, psi: f64| {
///     let (st, ct, sp, cp) = (theta.sin(), theta.cos(), psi.sin(), psi.cos());
///     Matrix3::new(st * sp, cp, 0.0, st * cp, -sp, 0.0, ct, 0.0, 1.0)
/// };
/// let q = [0.0, 0.5, 0.2];
/// assert_eq!(check_chart(AngleSequence::Zxz, &zxz_b(0.5, 0.2), &q), Ok(0.5f64.sin()));
/// let vertical = [0.0, 0.0, 0.2];
/// assert!(matches!(
///     check_chart(AngleSequence::Zxz, &zxz_b(0.0, 0.2), &vertical),
///     Err(ChartError::SingularChart { det: 0.0, .. })
/// ));
/// ```
pub fn check_chart(
    sequence: AngleSequence,
    b: &Matrix3<f64>,
    q: &[f64; 3],
) -> Result<f64, ChartError> {
    if !q.iter().all(|v| v.is_finite()) {
        return Err(ChartError::NonFinite {
            quantity: "angles q",
            values: q.to_vec(),
        });
    }
    let det = b.determinant().abs();
    // Written so that a NaN determinant counts as singular too.
    if det >= SINGULAR_DET {
        Ok(det)
    } else {
        Err(ChartError::SingularChart {
            sequence,
            q: *q,
            det,
        })
    }
}

/// Solves `B q̇ = ω` for the rates of the chart `sequence` at the angles `q`, refusing a
/// singular chart ([`check_chart`]) and non-finite values.
///
/// # Errors
/// [`ChartError::NonFinite`] for non-finite angles or ω; [`ChartError::SingularChart`] at
/// gimbal lock; [`ChartError::NonFiniteResult`] if the rates overflow.
///
/// # Examples
///
/// At θ = 0.5, ψ = 0 the ZXZ rates of ω = (ω₁, ω₂, ω₃) are θ̇ = ω₁, φ̇ = ω₂ / sin θ,
/// ψ̇ = ω₃ − φ̇ cos θ:
///
/// ```
/// use approx::assert_relative_eq;
/// use nalgebra::{Matrix3, Vector3};
/// use precess_core::rigid::AngleSequence;
/// use precess_core::rigid::rates_from_omega;
/// let (st, ct) = 0.5f64.sin_cos();
/// let b = Matrix3::new(0.0, 1.0, 0.0, st, 0.0, 0.0, ct, 0.0, 1.0);
/// let w = Vector3::new(0.1, 0.2, 3.0);
/// let qd = rates_from_omega(AngleSequence::Zxz, &b, &[0.0, 0.5, 0.0], &w).unwrap();
/// let phi_dot = 0.2 / st;
/// assert_relative_eq!(qd.as_slice(), [phi_dot, 0.1, 3.0 - phi_dot * ct].as_slice(), epsilon = 1e-15);
/// ```
pub fn rates_from_omega(
    sequence: AngleSequence,
    b: &Matrix3<f64>,
    q: &[f64; 3],
    omega: &Vector3<f64>,
) -> Result<[f64; 3], ChartError> {
    if !omega.iter().all(|v| v.is_finite()) {
        return Err(ChartError::NonFinite {
            quantity: "body angular velocity ω",
            values: omega.iter().copied().collect(),
        });
    }
    let det = check_chart(sequence, b, q)?;
    let singular = || ChartError::SingularChart {
        sequence,
        q: *q,
        det,
    };
    let r = b.lu().solve(omega).ok_or_else(singular)?;
    let rates = [r[0], r[1], r[2]];
    if rates.iter().all(|v| v.is_finite()) {
        Ok(rates)
    } else {
        Err(ChartError::NonFiniteResult {
            quantity: "the rates q̇",
            values: rates.to_vec(),
        })
    }
}
