//! A derived free body as the systems the steppers take: an ODE on the state array for the
//! adaptive pairs and RK4, and a rigid-body model for the Lie-group RKMK4.

use nalgebra::Vector3;

use super::dynamics::FreeDynamics;
use super::state::FreeState;
use crate::ode::{OdeError, System};
use crate::rigid::{RigidBodyModel, RigidState};

/// A derived free body as an ODE system on the state array of [`super::layout`] (and its
/// driven rotors' rates, if any), for the adaptive pairs, RK4 and [`super::FreeFlight`] (which
/// takes the 13-slot state only).
///
/// ```
/// use approx::assert_relative_eq;
/// use precess::free::{FreeState, FreeSystem};
/// use precess::ode::{AdaptiveConfig, Dop853};
/// use precess::prelude::*;
///
/// #[derive(RigidBody)]
/// #[rigid(sphere(mass = 1.0, radius = 0.1))]
/// #[free(gravity = 9.81)]
/// struct Ball;
///
/// let s0 = FreeState { velocity: Vector3::new(3.0, 0.0, 9.81), ..FreeState::at_rest() };
/// let mut ode = Dop853::new(FreeSystem(&Ball), 0.0, s0.to_array(), AdaptiveConfig::default())?;
/// ode.advance_to(2.0)?;
/// // Back on the ground after 2 s, 6 m downrange.
/// assert_relative_eq!(ode.y()[0], 6.0, epsilon = 1e-9);
/// assert_relative_eq!(ode.y()[2], 0.0, epsilon = 1e-9);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct FreeSystem<'a, T>(pub &'a T);

impl<T> Clone for FreeSystem<'_, T> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<T> Copy for FreeSystem<'_, T> {}

impl<const N: usize, T: FreeDynamics<N>> System<N> for FreeSystem<'_, T> {
    #[inline]
    fn rhs(&self, t: f64, y: &[f64; N], dydt: &mut [f64; N]) {
        self.0.free_rhs(t, y, dydt);
    }

    /// The body's [`FreeDynamics::check_parameters`], before any step.
    fn check_parameters(&self) -> Result<(), OdeError> {
        self.0
            .check_parameters()
            .map_err(super::error::FreeError::into_ode_error)
    }

    /// A driven rotor's motor that is not finite at `(t, y)` ([`FreeDynamics::check_motors`]):
    /// [`OdeError::NonFiniteInput`] naming it.
    fn explain_non_finite(&self, t: f64, y: &[f64; N]) -> Option<OdeError> {
        self.0
            .check_motors(t, y)
            .err()
            .map(super::error::FreeError::into_ode_error)
    }
}

/// A derived free body as the rigid-body model of the Lie-group stepper
/// [`crate::rigid::Rkmk4`], whose steps keep the attitude on SO(3) by construction (a body
/// without driven rotors: the model's state has no slot for their rates).
///
/// ```
/// use approx::assert_relative_eq;
/// use precess::free::{FreeLie, FreeState};
/// use precess::ode::FixedStepConfig;
/// use precess::rigid::{Rkmk4, RigidState};
/// use precess::prelude::*;
///
/// #[derive(RigidBody)]
/// #[rigid(cuboid(mass = 1.0, size = [0.1, 0.2, 0.3]))]
/// #[free(gravity = 9.81)]
/// struct Brick;
///
/// let s0 = FreeState { omega_principal: Vector3::new(0.1, 5.0, 0.1), ..FreeState::at_rest() };
/// let mut m = Rkmk4::new(FreeLie(&Brick), 0.0, RigidState::from(s0), FixedStepConfig::with_step(1e-3))?;
/// m.advance_to(1.0)?;
/// assert_relative_eq!(m.state().q.quaternion().norm(), 1.0, epsilon = 1e-15);
/// assert_relative_eq!(m.state().x.z, -0.5 * 9.81, max_relative = 1e-12);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct FreeLie<'a, T>(pub &'a T);

impl<T: FreeDynamics> RigidBodyModel for FreeLie<'_, T> {
    fn mass(&self) -> f64 {
        self.0.mass()
    }

    fn inertia(&self) -> [f64; 3] {
        let m = self.0.principal_cm().moments;
        [m.x, m.y, m.z]
    }

    fn force(&self, t: f64, s: &RigidState) -> Vector3<f64> {
        self.0
            .wrench(t, &FreeState::from(*s).to_array())
            .force_space
    }

    fn torque(&self, t: f64, s: &RigidState) -> Vector3<f64> {
        self.0
            .wrench(t, &FreeState::from(*s).to_array())
            .torque_principal
    }
}
