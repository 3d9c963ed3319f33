//! The Eulerian form of a derived top as an ODE system: attitude quaternion and body ω.

use nalgebra::{UnitQuaternion, Vector3};

use super::top_trait::Top;
use crate::ode::System;

/// The Eulerian form of a derived top as an ODE system with state
/// `[q_w, q_x, q_y, q_z, ω₁, ω₂, ω₃]` (unit quaternion body to space, body ω):
/// q̇ = ½ q ⊗ (0, ω), ω̇ from [`Top::eulerian_rhs`]. The quaternion is normalised before use,
/// so drift of its norm under a general-purpose stepper does not leak into ω̇.
#[derive(Debug)]
pub struct EulerianTop<'a, T>(pub &'a T);

impl<T> EulerianTop<'_, T> {
    /// The state `[q_w, q_x, q_y, q_z, ω₁, ω₂, ω₃]` of an attitude and a body ω.
    pub fn state(attitude: &UnitQuaternion<f64>, omega: &Vector3<f64>) -> [f64; 7] {
        let q = attitude.quaternion();
        [q.w, q.i, q.j, q.k, omega.x, omega.y, omega.z]
    }

    /// The attitude of a state, normalised.
    pub fn attitude(y: &[f64; 7]) -> UnitQuaternion<f64> {
        UnitQuaternion::new_normalize(nalgebra::Quaternion::new(y[0], y[1], y[2], y[3]))
    }
}

impl<T: Top> System<7> for EulerianTop<'_, T> {
    #[inline]
    fn rhs(&self, t: f64, y: &[f64; 7], d: &mut [f64; 7]) {
        let q = nalgebra::Quaternion::new(y[0], y[1], y[2], y[3]);
        let w = Vector3::new(y[4], y[5], y[6]);
        let qd = q * nalgebra::Quaternion::new(0.0, w.x, w.y, w.z) * 0.5;
        let wd = self
            .0
            .eulerian_rhs(t, &UnitQuaternion::new_normalize(q), &w);
        d[..4].copy_from_slice(&[qd.w, qd.i, qd.j, qd.k]);
        d[4..].copy_from_slice(wd.as_slice());
    }
}
