//! The exact motion of a free body under uniform gravity alone: the centre of mass on its
//! parabola, the attitude on the torque-free flow (gravity makes no torque about the centre
//! of mass), both in closed form.

use nalgebra::Vector3;

use super::error::FreeError;
use super::state::FreeState;
use crate::exact::{FreeBodyAttitude, FreeBodyExact, Regime};

/// The exact motion from one state, evaluated at any time in O(1):
/// x(t) = x₀ + v₀ τ + ½ g τ², v(t) = v₀ + g τ with τ = t − t₀, and (q(t), m(t)) from
/// [`FreeBodyAttitude`] (Jacobi elliptic functions and the third-kind integral), ω = I⁻¹ m.
///
/// ```
/// use approx::assert_relative_eq;
/// use nalgebra::{UnitQuaternion, Vector3};
/// use precess_core::free::{FreeExact, FreeState};
///
/// // Thrown up at 9.81 m/s: back at its start after 2 s, spinning steadily about axis 3.
/// let s0 = FreeState {
///     velocity: Vector3::new(0.0, 0.0, 9.81),
///     omega_principal: Vector3::new(0.0, 0.0, std::f64::consts::PI),
///     ..FreeState::at_rest()
/// };
/// let motion = FreeExact::new(&Vector3::new(1.0, 2.0, 3.0), &Vector3::new(0.0, 0.0, -9.81), 0.0, &s0)?;
/// let s = motion.at(2.0)?;
/// assert_relative_eq!(s.position, Vector3::zeros(), epsilon = 1e-14);
/// // Half a turn per second: after two seconds, a full turn.
/// assert_relative_eq!(s.attitude.angle_to(&UnitQuaternion::identity()), 0.0, epsilon = 1e-12);
/// # Ok::<(), precess_core::free::FreeError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FreeExact {
    t0: f64,
    start: FreeState,
    gravity: Vector3<f64>,
    moments: Vector3<f64>,
    attitude: FreeBodyAttitude,
    /// The body angular momentum alone, in the caller's time (the attitude's own works on
    /// a rescaled clock).
    momentum: FreeBodyExact,
}

impl FreeExact {
    /// The exact motion of a body with principal moments `moments` (about the centre of
    /// mass) under uniform gravity `gravity` (space axes), from `state` at `t0`.
    ///
    /// # Errors
    /// [`FreeError::InvalidInertia`] unless the moments are finite and positive;
    /// [`FreeError::NonFiniteParameter`] for a non-finite gravity or `t0`; as
    /// [`FreeState::check`] for the state; [`FreeError::Exact`] if the attitude's closed form
    /// cannot be set up.
    pub fn new(
        moments: &Vector3<f64>,
        gravity: &Vector3<f64>,
        t0: f64,
        state: &FreeState,
    ) -> Result<FreeExact, FreeError> {
        if !moments.iter().all(|&i| i.is_finite() && i > 0.0) {
            return Err(FreeError::InvalidInertia {
                mass: 1.0,
                moments: [moments.x, moments.y, moments.z],
            });
        }
        for (name, value) in [
            ("gravity x", gravity.x),
            ("gravity y", gravity.y),
            ("gravity z", gravity.z),
            ("t0", t0),
        ] {
            if !value.is_finite() {
                return Err(FreeError::NonFiniteParameter {
                    name: name.to_owned(),
                    value,
                });
            }
        }
        state.check()?;
        let m = moments.component_mul(&state.omega_principal);
        let (i, m) = ([moments.x, moments.y, moments.z], [m.x, m.y, m.z]);
        let attitude = FreeBodyAttitude::new(i, state.attitude, m)?;
        let momentum = FreeBodyExact::new(i, m)?;
        Ok(FreeExact {
            t0,
            start: *state,
            gravity: *gravity,
            moments: *moments,
            attitude,
            momentum,
        })
    }

    /// The state at time `t` (before `t0` as well: the flow is reversible).
    ///
    /// # Errors
    /// [`FreeError::NonFinite`] for a non-finite `t`; [`FreeError::Exact`] when the
    /// attitude's elliptic argument is too large to reduce accurately.
    pub fn at(&self, t: f64) -> Result<FreeState, FreeError> {
        if !t.is_finite() {
            return Err(FreeError::NonFinite {
                quantity: "time",
                values: vec![t],
            });
        }
        let tau = t - self.t0;
        let s = &self.start;
        let (q, m) = self.attitude.at(tau)?;
        Ok(FreeState {
            position: s.position + s.velocity * tau + self.gravity * (0.5 * tau * tau),
            velocity: s.velocity + self.gravity * tau,
            attitude: q,
            omega_principal: Vector3::from(m).component_div(&self.moments),
        })
    }

    /// The regime of the attitude's motion (about the largest or smallest axis, on the
    /// separatrix, or steady).
    pub fn regime(&self) -> Regime {
        self.momentum.regime()
    }

    /// The time between two flips of a body spinning near its intermediate axis, 2K/|λ|
    /// (half the period of the angular momentum in the body); `None` when steady or on the
    /// separatrix.
    pub fn flip_interval(&self) -> Option<f64> {
        match self.momentum.regime() {
            Regime::AboutLargest | Regime::AboutSmallest => Some(0.5 * self.momentum.period()),
            Regime::Steady | Regime::Separatrix => None,
        }
    }

    /// The time the centre of mass is back at its starting height along −g (the flight
    /// time of a body thrown from the ground), 2 v₀·ĝ⊥/|g|; `None` without gravity or when
    /// thrown downward.
    pub fn return_time(&self) -> Option<f64> {
        let g = self.gravity.norm();
        if g == 0.0 {
            return None;
        }
        let up = -self.gravity / g;
        let rise = self.start.velocity.dot(&up);
        (rise > 0.0).then_some(self.t0 + 2.0 * rise / g)
    }

    /// The highest point above the start along −g, v_up²/(2|g|) (zero when thrown downward),
    /// and the time it is reached; `None` without gravity.
    pub fn apex(&self) -> Option<(f64, f64)> {
        let g = self.gravity.norm();
        if g == 0.0 {
            return None;
        }
        let up = -self.gravity / g;
        let rise = self.start.velocity.dot(&up).max(0.0);
        Some((rise * rise / (2.0 * g), self.t0 + rise / g))
    }
}
