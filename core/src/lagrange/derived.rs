//! The trait `#[top(...)]` implements, and its adapters to the steppers.

use nalgebra::{Matrix3, UnitQuaternion, Vector3};
use thiserror::Error;

use super::angles::AngleSequence;
use super::chart_trait::AngleChart;
use crate::ode::System;

/// A state an angle chart cannot represent.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TopError {
    /// B(q) is singular: the angles are at the chart's gimbal lock.
    #[error(
        "the {sequence:?} angles {q:?} are at gimbal lock (|det B| = {det:e}); use the other chart or the Eulerian form"
    )]
    SingularChart {
        /// The sequence.
        sequence: AngleSequence,
        /// The angles.
        q: [f64; 3],
        /// |det B(q)|.
        det: f64,
    },
    /// A non-finite angle, rate or angular velocity.
    #[error("non-finite state {state:?}")]
    NonFinite {
        /// The offending values.
        state: Vec<f64>,
    },
}

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
        self.accel_in(Self::SEQUENCE, t, &join(q, q_dot))
    }

    /// The energy T + V in [`Top::SEQUENCE`].
    fn energy(&self, q: &[f64; 3], q_dot: &[f64; 3]) -> f64 {
        self.energy_in(Self::SEQUENCE, &join(q, q_dot))
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

/// `[q, q̇]`.
pub fn join(q: &[f64; 3], q_dot: &[f64; 3]) -> [f64; 6] {
    [q[0], q[1], q[2], q_dot[0], q_dot[1], q_dot[2]]
}

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

/// One chart of a derived top as an ODE system with state `[q, q̇]`: use it with any
/// stepper of [`crate::ode`], or two of them with [`super::ChartedTop`].
#[derive(Debug)]
pub struct TopChart<'a, T> {
    /// The top.
    pub top: &'a T,
    /// The chart.
    pub sequence: AngleSequence,
}

impl<'a, T: Top> TopChart<'a, T> {
    /// The chart of the declared sequence.
    pub fn declared(top: &'a T) -> Self {
        TopChart {
            top,
            sequence: T::SEQUENCE,
        }
    }

    /// Both charts, the declared one first, for [`super::ChartedTop`].
    pub fn both(top: &'a T) -> [Self; 2] {
        let other = match T::SEQUENCE {
            AngleSequence::Zxz => AngleSequence::Zyx,
            AngleSequence::Zyx => AngleSequence::Zxz,
        };
        [
            Self::declared(top),
            TopChart {
                top,
                sequence: other,
            },
        ]
    }
}

impl<T: Top> System<6> for TopChart<'_, T> {
    #[inline]
    fn rhs(&self, t: f64, y: &[f64; 6], dydt: &mut [f64; 6]) {
        let a = self.top.accel_in(self.sequence, t, y);
        dydt[..3].copy_from_slice(&y[3..]);
        dydt[3..].copy_from_slice(&a);
    }
}

impl<T: Top> AngleChart for TopChart<'_, T> {
    fn sequence(&self) -> AngleSequence {
        self.sequence
    }
    fn rotation_at(&self, state: &[f64; 6]) -> Matrix3<f64> {
        self.top
            .rotation_in(self.sequence, &[state[0], state[1], state[2]])
    }
    fn rate_matrix_at(&self, state: &[f64; 6]) -> Matrix3<f64> {
        self.top
            .rate_matrix_in(self.sequence, &[state[0], state[1], state[2]])
    }
    fn energy_at(&self, state: &[f64; 6]) -> f64 {
        self.top.energy_in(self.sequence, state)
    }
}

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
