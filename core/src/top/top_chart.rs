//! One angle chart of a derived top as an ODE system.

use nalgebra::Matrix3;

use super::angle_chart::AngleChart;
use super::top_trait::Top;
use crate::ode::System;
use crate::rigid::AngleSequence;

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
        [
            Self::declared(top),
            TopChart {
                top,
                sequence: T::SEQUENCE.other(),
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
