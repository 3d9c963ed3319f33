//! The trait `#[top(...)]` implements: a derived top's equations in both angle charts and in
//! Eulerian form, with the helpers built on them.

use nalgebra::{Matrix3, UnitQuaternion, Vector3};

use super::error::TopError;
use super::rates::rates_from_omega;
use crate::rigid::AngleSequence;

/// A top about a fixed pivot, its equations derived at compile time by `#[top(...)]`.
///
/// Angle-form methods take the angles `q` and rates `q̇` of [`Top::SEQUENCE`]; the `_in`
/// methods take either sequence (both are generated, so a simulation can switch charts at
/// gimbal lock, see [`super::ChartedTop`]). The Eulerian form takes the attitude and the
/// body angular velocity, in the description axes of the body.
pub trait Top {
    /// The declared angle sequence.
    const SEQUENCE: AngleSequence;

    /// q̈ in the chart `seq` at time `t` and state `[q, q̇]`.
    fn accel_in(&self, seq: AngleSequence, t: f64, state: &[f64; 6]) -> [f64; 3];

    /// R(q) in the chart `seq`, body to space.
    fn rotation_in(&self, seq: AngleSequence, q: &[f64; 3]) -> Matrix3<f64>;

    /// B(q) in the chart `seq`: ω = B q̇.
    fn rate_matrix_in(&self, seq: AngleSequence, q: &[f64; 3]) -> Matrix3<f64>;

    /// The energy T + V in the chart `seq`.
    fn energy_in(&self, seq: AngleSequence, state: &[f64; 6]) -> f64;

    /// The Jacobian of q̈ with respect to `(q, q̇)` in [`Top::SEQUENCE`]: row i holds
    /// `∂q̈_i/∂(q_0, q_1, q_2, q̇_0, q̇_1, q̇_2)`.
    fn angle_jacobian(&self, t: f64, q: &[f64; 3], q_dot: &[f64; 3]) -> [[f64; 6]; 3];

    /// The momenta `∂L/∂q̇_i` of [`Top::SEQUENCE`] that are conserved for this scene
    /// (`None` for the others).
    fn conserved_momenta(&self, q: &[f64; 3], q_dot: &[f64; 3]) -> [Option<f64>; 3];

    /// The Eulerian form: ω̇ = I⁻¹(τ − ω × I ω), with the same torques, for the attitude
    /// (body to space) and body angular velocity ω.
    fn eulerian_rhs(
        &self,
        t: f64,
        attitude: &UnitQuaternion<f64>,
        omega: &Vector3<f64>,
    ) -> Vector3<f64>;

    /// q̈ in [`Top::SEQUENCE`].
    fn angle_accel(&self, t: f64, q: &[f64; 3], q_dot: &[f64; 3]) -> [f64; 3] {
        self.accel_in(Self::SEQUENCE, t, &angle_state(q, q_dot))
    }

    /// The energy T + V in [`Top::SEQUENCE`].
    fn energy(&self, q: &[f64; 3], q_dot: &[f64; 3]) -> f64 {
        self.energy_in(Self::SEQUENCE, &angle_state(q, q_dot))
    }

    /// The body angular velocity ω = B(q) q̇ of [`Top::SEQUENCE`].
    fn omega_from_rates(&self, q: &[f64; 3], q_dot: &[f64; 3]) -> Vector3<f64> {
        self.rate_matrix_in(Self::SEQUENCE, q) * Vector3::from(*q_dot)
    }

    /// The rates q̇ = B(q)⁻¹ ω of [`Top::SEQUENCE`].
    ///
    /// # Errors
    /// [`TopError::SingularChart`] at gimbal lock (|det B| < 1e-12),
    /// [`TopError::NonFinite`] for non-finite input.
    fn rates_from_omega(&self, q: &[f64; 3], omega: &Vector3<f64>) -> Result<[f64; 3], TopError> {
        rates_from_omega(
            Self::SEQUENCE,
            &self.rate_matrix_in(Self::SEQUENCE, q),
            q,
            omega,
        )
    }
}

/// The angle-form state `[q, q̇]` that [`Top::accel_in`] and [`Top::energy_in`] take.
pub fn angle_state(q: &[f64; 3], q_dot: &[f64; 3]) -> [f64; 6] {
    [q[0], q[1], q[2], q_dot[0], q_dot[1], q_dot[2]]
}
