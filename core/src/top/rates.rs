//! Solving `B(q) q̇ = ω`: the rates of an angle chart from the body angular velocity.

use nalgebra::{Matrix3, Vector3};

use super::error::TopError;
use crate::rigid::AngleSequence;

/// Solves `B q̇ = ω`, refusing a singular chart and non-finite values.
///
/// # Errors
/// As [`Top::rates_from_omega`].
pub fn rates_from_omega(
    sequence: AngleSequence,
    b: &Matrix3<f64>,
    q: &[f64; 3],
    omega: &Vector3<f64>,
) -> Result<[f64; 3], TopError> {
    if !q.iter().chain(omega.iter()).all(|v| v.is_finite()) {
        return Err(TopError::NonFinite {
            state: q.iter().chain(omega.iter()).copied().collect(),
        });
    }
    let det = b.determinant().abs();
    let singular = || TopError::SingularChart {
        sequence,
        q: *q,
        det,
    };
    if det < 1e-12 {
        return Err(singular());
    }
    let r = b.lu().solve(omega).ok_or_else(singular)?;
    Ok([r[0], r[1], r[2]])
}
