//! One angle chart of a top, as the steppers and the chart switcher see it.

use nalgebra::{Matrix3, Vector3};

use crate::ode::System;
use crate::rigid::AngleSequence;

/// A top's equations in one angle chart, with state `[q, q̇]`: what [`super::ChartedTop`]
/// needs to integrate in it and to map states in and out through the attitude R and the
/// body angular velocity ω.
///
/// Implemented by the run-time [`super::TopModel`] and, for derived tops, by
/// [`super::TopChart`] over the generated code.
pub trait AngleChart: System<6> {
    /// The chart's angle sequence.
    fn sequence(&self) -> AngleSequence;

    /// R(q), body to space.
    fn rotation_at(&self, state: &[f64; 6]) -> Matrix3<f64>;

    /// B(q), with ω = B q̇.
    fn rate_matrix_at(&self, state: &[f64; 6]) -> Matrix3<f64>;

    /// The energy T + V.
    fn energy_at(&self, state: &[f64; 6]) -> f64;

    /// The body angular velocity ω = B(q) q̇.
    fn omega_at(&self, state: &[f64; 6]) -> Vector3<f64> {
        self.rate_matrix_at(state) * Vector3::new(state[3], state[4], state[5])
    }
}
