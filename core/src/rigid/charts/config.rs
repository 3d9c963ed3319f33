//! When to switch charts, and the checks of the attitude a switching run starts from: one
//! rule for `ChartedTop` and `ChartedMechanism`.

use nalgebra::Matrix3;

use super::error::ChartError;
use crate::ode::AdaptiveConfig;

/// When to switch charts, and the integrator settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChartConfig {
    /// Switch when `|det B(q)|` of the current chart falls below this (default 0.3, i.e.
    /// θ within 17° of the vertical for ZXZ).
    pub switch_below: f64,
    /// The adaptive stepper's configuration (default: DOP853 at rtol = atol = 1e-10).
    pub stepper: AdaptiveConfig,
}

impl Default for ChartConfig {
    fn default() -> Self {
        ChartConfig {
            switch_below: 0.3,
            stepper: AdaptiveConfig::with_tol(1e-10, 1e-10),
        }
    }
}

impl ChartConfig {
    /// Checks [`ChartConfig::switch_below`]: finite and positive.
    ///
    /// # Errors
    /// [`ChartError::InvalidSwitch`] otherwise.
    pub fn check(&self) -> Result<(), ChartError> {
        let value = self.switch_below;
        if value.is_finite() && value > 0.0 {
            Ok(())
        } else {
            Err(ChartError::InvalidSwitch { value })
        }
    }
}

/// How far from a rotation an attitude given to a chart switch may be: the largest entry of
/// |RᵀR − I| and |det R − 1| (a matrix from angles or a quaternion in f64 is within 1e-15;
/// one that drifted through a long integration should be re-orthonormalised first).
pub const ROTATION_TOLERANCE: f64 = 1e-9;

/// Checks that `r` is a finite rotation matrix within [`ROTATION_TOLERANCE`].
///
/// # Errors
/// [`ChartError::NotARotation`] otherwise (NaN fails too).
///
/// # Examples
///
/// ```
/// use nalgebra::Matrix3;
/// use precess_core::rigid::{ChartError, check_rotation};
/// assert_eq!(check_rotation(&Matrix3::identity()), Ok(()));
/// let mirror = Matrix3::from_diagonal(&[1.0, 1.0, -1.0].into());
/// assert!(matches!(check_rotation(&mirror), Err(ChartError::NotARotation { .. })));
/// ```
pub fn check_rotation(r: &Matrix3<f64>) -> Result<(), ChartError> {
    let orthogonality = (r.transpose() * r - Matrix3::identity()).abs().max();
    let det = r.determinant();
    // Written so that NaN fails both tests.
    let orthogonal = orthogonality <= ROTATION_TOLERANCE;
    let proper = (det - 1.0).abs() <= ROTATION_TOLERANCE;
    if orthogonal && proper {
        Ok(())
    } else {
        Err(ChartError::NotARotation {
            matrix: Box::new([0, 1, 2].map(|i| [r[(i, 0)], r[(i, 1)], r[(i, 2)]])),
            orthogonality,
            det,
        })
    }
}
