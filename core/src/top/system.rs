//! One angle chart of a derived top as an ODE system.

use nalgebra::Matrix3;

use super::angle_chart::AngleChart;
use super::checks::checked_motors;
use super::dynamics::TopDynamics;
use super::error::TopError;
use crate::ode::{OdeError, System};
use crate::rigid::AngleSequence;

/// One chart of a derived top as an ODE system with state `[q, q̇]` (`[q, q̇, Ω]` for a
/// top with driven rotors, [`TopDynamics::rhs_in`]): use it with any stepper of
/// [`crate::ode`], or two of them with [`super::ChartedTop`].
///
/// The right-hand side is the generated q̈, unchecked: NaN at the chart's gimbal lock. Near
/// the vertical, integrate [`TopChart::both`] with [`super::ChartedTop`].
///
/// # Examples
///
/// The fast heavy top (I1 = 1, I3 = ½ about the pivot, M g l = 1) released at rest from
/// θ0 = 60° spinning at ω3 = 20 nods down by 1.7580e-2 rad and back in 0.634549 s (the
/// exact nutation through the cubic in cos θ), so half a period in, θ is at its lowest:
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
/// let theta0 = std::f64::consts::FRAC_PI_3;
/// let chart = TopChart::declared(&Heavy);
/// let tight = AdaptiveConfig::with_tol(1e-12, 1e-12);
/// let mut ode = Dop853::new(&chart, 0.0, [0.0, theta0, 0.0, 0.0, 0.0, 20.0], tight)?;
/// ode.advance_to(0.634549 / 2.0)?;
/// assert_relative_eq!(ode.y()[1] - theta0, 1.7580e-2, epsilon = 1e-6);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct TopChart<'a, T> {
    /// The top.
    pub top: &'a T,
    /// The chart.
    pub sequence: AngleSequence,
}

impl<'a, T> TopChart<'a, T> {
    /// The chart of the declared sequence.
    pub fn declared<const N: usize>(top: &'a T) -> Self
    where
        T: TopDynamics<N>,
    {
        TopChart {
            top,
            sequence: T::SEQUENCE,
        }
    }

    /// Both charts, the declared one first, for [`super::ChartedTop`].
    pub fn both<const N: usize>(top: &'a T) -> [Self; 2]
    where
        T: TopDynamics<N>,
    {
        [
            Self::declared(top),
            TopChart {
                top,
                sequence: T::SEQUENCE.other(),
            },
        ]
    }
}

impl<T: TopDynamics<N>, const N: usize> System<N> for TopChart<'_, T> {
    #[inline]
    fn rhs(&self, t: f64, y: &[f64; N], dydt: &mut [f64; N]) {
        self.top.rhs_in(self.sequence, t, y, dydt);
    }

    /// The top's [`TopDynamics::check_all`]: body and settings, before any step.
    fn check_parameters(&self) -> Result<(), OdeError> {
        self.top.check_all().map_err(TopError::into_ode_error)
    }

    /// A driven rotor's motor that is not finite at `(t, y)`:
    /// [`OdeError::NonFiniteInput`] naming it ([`TopError::NonFiniteMotor`]).
    fn explain_non_finite(&self, t: f64, y: &[f64; N]) -> Option<OdeError> {
        checked_motors(self.top, t, y)
            .err()
            .map(TopError::into_ode_error)
    }
}

impl<T: TopDynamics<N>, const N: usize> AngleChart<N> for TopChart<'_, T> {
    fn sequence(&self) -> AngleSequence {
        self.sequence
    }
    fn rotation_at(&self, state: &[f64; N]) -> Matrix3<f64> {
        self.top.rotation_in(self.sequence, &angles(state))
    }
    fn rate_matrix_at(&self, state: &[f64; N]) -> Matrix3<f64> {
        self.top.rate_matrix_in(self.sequence, &angles(state))
    }
    fn energy_at(&self, state: &[f64; N]) -> f64 {
        self.top.energy_in(self.sequence, state)
    }
    fn check_all(&self) -> Result<(), TopError> {
        self.top.check_all()
    }
}

/// The angles q of a state.
fn angles(state: &[f64]) -> [f64; 3] {
    std::array::from_fn(|k| state.get(k).copied().unwrap_or(f64::NAN))
}
