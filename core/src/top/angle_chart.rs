//! One angle chart of a top, as the steppers and the chart switcher see it.

use nalgebra::{Matrix3, Vector3};

use super::error::TopError;
use crate::ode::System;
use crate::rigid::AngleSequence;
use crate::rigid::rates_from_omega;

/// A top's equations in one angle chart, with state `[q, q̇]`: what [`super::ChartedTop`]
/// needs to integrate in it and to map states in and out through the attitude R and the
/// body angular velocity ω.
///
/// Implemented by the run-time [`super::TopModel`] and, for derived tops, by
/// [`super::TopChart`] over the generated code. `N` is the state's length: 6, or
/// `6 + k` for a top with k driven rotors, whose rates follow `[q, q̇]` unchanged by a chart
/// switch (they are relative to the body, which both charts share).
pub trait AngleChart<const N: usize = 6>: System<N> {
    /// The chart's angle sequence.
    fn sequence(&self) -> AngleSequence;

    /// R(q), body to space.
    fn rotation_at(&self, state: &[f64; N]) -> Matrix3<f64>;

    /// B(q), with ω = B q̇.
    fn rate_matrix_at(&self, state: &[f64; N]) -> Matrix3<f64>;

    /// The energy T + V.
    fn energy_at(&self, state: &[f64; N]) -> f64;

    /// Checks the scene before a run; [`super::ChartedTop::new`] calls it. A chart over a
    /// derived top checks everything the top's field values decide
    /// ([`super::TopDynamics::check_all`]: the body and the settings); the default, for
    /// charts whose values were checked when they were built, accepts.
    ///
    /// # Errors
    /// As [`super::TopDynamics::check_all`].
    fn check_all(&self) -> Result<(), TopError> {
        Ok(())
    }

    /// The body angular velocity ω = B(q) q̇.
    fn omega_at(&self, state: &[f64; N]) -> Vector3<f64> {
        let rate = |k: usize| state.get(k).copied().unwrap_or(f64::NAN);
        self.rate_matrix_at(state) * Vector3::new(rate(3), rate(4), rate(5))
    }

    /// The rates q̇ with B(q) q̇ = ω at the angles `q`, under the one rule of
    /// [`crate::rigid::rates_from_omega`] (the same the derived tops and [`super::ChartedTop`]
    /// use).
    ///
    /// # Errors
    /// As [`crate::rigid::rates_from_omega`]: [`TopError::Chart`] ([`crate::rigid::ChartError::SingularChart`]) at gimbal lock,
    /// [`TopError::NonFinite`] for non-finite input.
    fn rates_at(&self, q: &[f64; 3], omega: &Vector3<f64>) -> Result<[f64; 3], TopError> {
        let b = self.rate_matrix_at(&at_angles(q));
        Ok(rates_from_omega(self.sequence(), &b, q, omega)?)
    }
}

/// Borrowed charts are charts: `ChartedTop::new([&a, &b], …)` for models that are costly to
/// clone, such as the interpreted [`super::TopModel`].
impl<C: AngleChart<N> + ?Sized, const N: usize> AngleChart<N> for &C {
    fn sequence(&self) -> AngleSequence {
        (**self).sequence()
    }
    fn rotation_at(&self, state: &[f64; N]) -> Matrix3<f64> {
        (**self).rotation_at(state)
    }
    fn rate_matrix_at(&self, state: &[f64; N]) -> Matrix3<f64> {
        (**self).rate_matrix_at(state)
    }
    fn energy_at(&self, state: &[f64; N]) -> f64 {
        (**self).energy_at(state)
    }
    fn check_all(&self) -> Result<(), TopError> {
        (**self).check_all()
    }
    fn omega_at(&self, state: &[f64; N]) -> Vector3<f64> {
        (**self).omega_at(state)
    }
}

/// A state of `N` slots at the angles `q`, every rate zero: what R(q) and B(q) read.
pub(crate) fn at_angles<const N: usize>(q: &[f64; 3]) -> [f64; N] {
    std::array::from_fn(|k| q.get(k).copied().unwrap_or(0.0))
}
