//! The Eulerian form of a derived top as an ODE system: attitude quaternion and body ω.

use nalgebra::{Quaternion, UnitQuaternion, Vector3};

use super::dynamics::TopDynamics;
use super::error::TopError;
use crate::ode::{OdeError, System};

/// The Eulerian form of a derived top as an ODE system with state
/// `[q_w, q_x, q_y, q_z, ω₁, ω₂, ω₃]` (unit quaternion body to space, body ω):
/// q̇ = ½ q ⊗ (0, ω), ω̇ from [`TopDynamics::eulerian_rhs`]. The quaternion is normalised before use,
/// so drift of its norm under a general-purpose stepper does not leak into ω̇. It has no
/// singular attitude.
///
/// The right-hand side is unchecked, for the steppers' inner loop: a state assembled by hand
/// with a zero quaternion gives NaN, which a stepper reports as a non-finite state. Build
/// states with [`EulerianTop::state`], or check them with [`EulerianTop::check_state`],
/// which names the cause.
///
/// # Examples
///
/// Steady precession of the symmetric heavy top (I1 = 1, I3 = ½ about the pivot,
/// M g l = 1) at θ = 60° with ω3 = 10: the figure axis turns about the vertical at the slow
/// root Ω = 0.204168476687 rad/s of I1 cos θ Ω² − I3 ω3 Ω + M g l = 0, keeping its tilt.
///
/// ```
/// use approx::assert_relative_eq;
/// use precess::ode::{AdaptiveConfig, Dop853};
/// use precess::prelude::*;
///
/// #[derive(RigidBody)]
/// #[rigid(
///     body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
///     pivot = [0.0, 0.0, 0.0],
/// )]
/// #[top(gravity = 1.0)]
/// struct Heavy;
///
/// let (theta, omega_p) = (std::f64::consts::FRAC_PI_3, 0.204168476687);
/// // ZXZ at φ = ψ = 0: R = Rx(θ), and ω = (θ̇, φ̇ sin θ, ω3).
/// let q0 = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), theta);
/// let w0 = Vector3::new(0.0, omega_p * theta.sin(), 10.0);
/// let y0 = EulerianTop::<Heavy>::state(&q0, &w0);
/// let tight = AdaptiveConfig::with_tol(1e-12, 1e-12);
/// let mut ode = Dop853::new(EulerianTop(&Heavy), 0.0, y0, tight)?;
/// ode.advance_to(2.0)?;
/// let axis = EulerianTop::<Heavy>::attitude(ode.y())? * Vector3::z();
/// let phi = omega_p * 2.0;
/// let expected = Vector3::new(theta.sin() * phi.sin(), -theta.sin() * phi.cos(), theta.cos());
/// assert_relative_eq!(axis, expected, epsilon = 1e-8);
///
/// // A hand-made state with a zero quaternion is refused by name.
/// let zero = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 10.0];
/// assert!(matches!(
///     EulerianTop::<Heavy>::check_state(&zero),
///     Err(TopError::ZeroQuaternion { .. })
/// ));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct EulerianTop<'a, T>(pub &'a T);

impl<T> EulerianTop<'_, T> {
    /// The state `[q_w, q_x, q_y, q_z, ω₁, ω₂, ω₃]` of an attitude and a body ω.
    pub fn state(attitude: &UnitQuaternion<f64>, omega: &Vector3<f64>) -> [f64; 7] {
        let q = attitude.quaternion();
        [q.w, q.i, q.j, q.k, omega.x, omega.y, omega.z]
    }

    /// The attitude of a state, normalised (a quaternion of any non-zero size, down to the
    /// smallest subnormal, names its attitude).
    ///
    /// # Errors
    /// [`TopError::NonFinite`] for a NaN or infinite component, [`TopError::ZeroQuaternion`]
    /// for a zero quaternion.
    pub fn attitude(y: &[f64; 7]) -> Result<UnitQuaternion<f64>, TopError> {
        let q = [y[0], y[1], y[2], y[3]];
        if !q.iter().all(|v| v.is_finite()) {
            return Err(TopError::NonFinite {
                quantity: "attitude quaternion",
                values: q.to_vec(),
            });
        }
        // Scaled by the largest component first, so the norm of a tiny quaternion does not
        // underflow to zero.
        let scale = q.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        if scale == 0.0 {
            return Err(TopError::ZeroQuaternion { quaternion: q });
        }
        let [w, i, j, k] = q.map(|v| v / scale);
        Ok(UnitQuaternion::new_normalize(Quaternion::new(w, i, j, k)))
    }

    /// Checks a state before integrating it: a finite, non-zero quaternion and a finite ω.
    ///
    /// # Errors
    /// As [`EulerianTop::attitude`], and [`TopError::NonFinite`] for a NaN or infinite ω.
    pub fn check_state(y: &[f64; 7]) -> Result<(), TopError> {
        Self::attitude(y)?;
        let w = [y[4], y[5], y[6]];
        if w.iter().all(|v| v.is_finite()) {
            Ok(())
        } else {
            Err(TopError::NonFinite {
                quantity: "body angular velocity ω",
                values: w.to_vec(),
            })
        }
    }
}

impl<T: TopDynamics> System<7> for EulerianTop<'_, T> {
    #[inline]
    fn rhs(&self, t: f64, y: &[f64; 7], d: &mut [f64; 7]) {
        let q = Quaternion::new(y[0], y[1], y[2], y[3]);
        let w = Vector3::new(y[4], y[5], y[6]);
        let qd = q * Quaternion::new(0.0, w.x, w.y, w.z) * 0.5;
        let wd = self
            .0
            .eulerian_rhs(t, &UnitQuaternion::new_normalize(q), &w);
        d[..4].copy_from_slice(&[qd.w, qd.i, qd.j, qd.k]);
        d[4..].copy_from_slice(wd.as_slice());
    }

    /// The top's [`TopDynamics::check_all`]: body and settings, before any step.
    fn check_parameters(&self) -> Result<(), OdeError> {
        self.0.check_all().map_err(TopError::into_ode_error)
    }
}
