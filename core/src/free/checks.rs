//! A free body's checks, in one place: a state array's parts finite and its attitude a
//! non-zero quaternion, and the driven rotors' rule (the one of [`crate::rigid`], here with
//! the free body's error).

use nalgebra::{Quaternion, UnitQuaternion};

use super::error::FreeError;
use super::state::{STATE_LEN, layout};

impl FreeError {
    /// Checks that the body's inertia about its centre of mass `inertia` stays positive
    /// definite as each driven rotor's axial moment is taken out (see
    /// [`crate::rigid::first_singular_driven`]); `rotors` holds (declared index, axis, J).
    ///
    /// # Errors
    /// [`FreeError::DrivenInertia`] naming the first rotor that breaks it.
    pub fn check_driven_inertia(
        inertia: &nalgebra::Matrix3<f64>,
        rotors: &[(usize, [f64; 3], f64)],
    ) -> Result<(), FreeError> {
        crate::rigid::check_driven_inertia(inertia, rotors, |rotor, smallest| {
            FreeError::DrivenInertia { rotor, smallest }
        })
    }
}

/// The attitude of a state array, normalised.
///
/// # Errors
/// [`FreeError::NonFinite`] for a NaN or infinite component, [`FreeError::ZeroQuaternion`]
/// for a zero quaternion.
pub fn attitude_of(y: &[f64; STATE_LEN]) -> Result<UnitQuaternion<f64>, FreeError> {
    let at = layout::QUATERNION;
    let q = [y[at], y[at + 1], y[at + 2], y[at + 3]];
    finite("attitude quaternion", &q)?;
    // Scaled by the largest component first, so the norm of a tiny quaternion does not
    // underflow to zero.
    let scale = q.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    if scale == 0.0 {
        return Err(FreeError::ZeroQuaternion { quaternion: q });
    }
    let [w, i, j, k] = q.map(|v| v / scale);
    Ok(UnitQuaternion::new_normalize(Quaternion::new(w, i, j, k)))
}

/// Rejects a part of a state that holds NaN or ±∞.
pub(super) fn finite(quantity: &'static str, values: &[f64]) -> Result<(), FreeError> {
    if values.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(FreeError::NonFinite {
            quantity,
            values: values.to_vec(),
        })
    }
}
