//! The torque-free symmetric body: ω cones about the symmetry axis in the body, and the axis
//! cones about the fixed angular momentum in space.

use nalgebra::Vector3;

use super::error::{TheoryError, finite};

/// A symmetric rigid body (I1 = I2, axial I3) under no torque, from its body angular
/// velocity ω in principal axes (axis 3 the symmetry axis).
///
/// Euler's equations I1 ω̇1 = (I1 − I3) ω2 ω3, I1 ω̇2 = (I3 − I1) ω3 ω1, I3 ω̇3 = 0 keep ω3
/// and turn (ω1, ω2) at the body-cone rate Ω_b = (I3 − I1) ω3 / I1:
/// ω1 + i ω2 = (ω1 + i ω2)(0) e^{i Ω_b t}. In space the symmetry axis precesses about the
/// fixed L at the space-cone rate |L|/I1, at the constant angle arccos(I3 ω3/|L|).
///
/// # Examples
///
/// A coin-like body (I3 = 2 I1) spinning at ω3 = 3 with a small wobble: ω turns about the axis
/// at +3 rad/s in the body, the axis about L at about |L|/I1 ≈ 6 rad/s in space.
///
/// ```
/// use approx::assert_relative_eq;
/// use precess_core::top::TorqueFreeSymmetric;
///
/// let coin = TorqueFreeSymmetric::new(1.0, 2.0, [0.1, 0.0, 3.0])?;
/// assert_relative_eq!(coin.body_cone_rate(), 3.0);
/// assert_relative_eq!(coin.space_cone_rate(), (0.01f64 + 36.0).sqrt());
/// let w = coin.omega_at(std::f64::consts::PI / 6.0)?; // a quarter turn at 3 rad/s
/// assert_relative_eq!(w[1], 0.1, epsilon = 1e-15);
/// # Ok::<(), precess_core::top::TheoryError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TorqueFreeSymmetric {
    i1: f64,
    i3: f64,
    omega: Vector3<f64>,
}

impl TorqueFreeSymmetric {
    /// The body with transverse moment `i1` = I1 = I2, axial moment `i3` and body angular
    /// velocity `omega` at t = 0 (principal axes, axis 3 the symmetry axis).
    ///
    /// # Errors
    /// [`TheoryError::NonFinite`]; [`TheoryError::NonPositiveMoment`].
    pub fn new(i1: f64, i3: f64, omega: impl Into<Vector3<f64>>) -> Result<Self, TheoryError> {
        let omega = omega.into();
        for (moment, value) in [("I1", i1), ("I3", i3)] {
            finite(moment, value)?;
            if value <= 0.0 {
                return Err(TheoryError::NonPositiveMoment { moment, value });
            }
        }
        for &w in omega.iter() {
            finite("ω", w)?;
        }
        Ok(TorqueFreeSymmetric { i1, i3, omega })
    }

    /// Ω_b = (I3 − I1) ω3 / I1: the rate at which ω (and L) turn about the symmetry axis,
    /// seen from the body (positive: counter-clockwise about +axis 3).
    pub fn body_cone_rate(&self) -> f64 {
        (self.i3 - self.i1) * self.omega[2] / self.i1
    }

    /// |L| = √(I1² (ω1² + ω2²) + I3² ω3²).
    pub fn angular_momentum(&self) -> f64 {
        let (w1, w2, w3) = (self.omega.x, self.omega.y, self.omega.z);
        (self.i1 * w1.hypot(w2)).hypot(self.i3 * w3)
    }

    /// |L|/I1: the rate at which the symmetry axis (and ω) turn about L, seen in space.
    pub fn space_cone_rate(&self) -> f64 {
        self.angular_momentum() / self.i1
    }

    /// The constant angle between the symmetry axis and L, atan2(I1 |ω⊥|, I3 ω3).
    pub fn axis_angle(&self) -> f64 {
        let (w1, w2, w3) = (self.omega.x, self.omega.y, self.omega.z);
        (self.i1 * w1.hypot(w2)).atan2(self.i3 * w3)
    }

    /// The body angular velocity at time t: ω3 fixed, (ω1, ω2) turned by Ω_b t.
    ///
    /// # Errors
    /// [`TheoryError::NonFinite`] for a non-finite t.
    pub fn omega_at(&self, t: f64) -> Result<Vector3<f64>, TheoryError> {
        finite("t", t)?;
        let (s, c) = (self.body_cone_rate() * t).sin_cos();
        let (w1, w2, w3) = (self.omega.x, self.omega.y, self.omega.z);
        Ok(Vector3::new(c * w1 - s * w2, s * w1 + c * w2, w3))
    }
}
