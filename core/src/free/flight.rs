//! A free body integrated by an adaptive embedded pair, with the attitude quaternion put back
//! on the unit sphere after every accepted step.

use super::error::FreeError;
use super::state::{FreeState, STATE_LEN, attitude_of, layout};
use crate::ode::{
    Adaptive, AdaptiveConfig, Dop853Pair, EmbeddedPair, OdeError, Stats, Stepper, System,
    check_stop,
};

/// How a [`FreeFlight`] keeps the quaternion on the unit sphere.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Projection {
    /// Normalise q after every accepted step, and restart the pair from the projected state
    /// (one evaluation per step more; the step size carries over).
    #[default]
    EveryStep,
    /// Leave q as the pair computes it: the right-hand side reads q/|q|, so the motion is
    /// right whatever |q|, and |q| drifts by the local errors only.
    Never,
}

/// A free body integrated by the adaptive pair `P` (DOP853 by default) on any
/// [`System`] of its state array ([`super::FreeSystem`] of a derived body, or a
/// [`super::FreeModel`]).
///
/// ```
/// use approx::assert_relative_eq;
/// use precess::free::{FreeFlight, FreeState, FreeSystem};
/// use precess::ode::AdaptiveConfig;
/// use precess::prelude::*;
///
/// #[derive(RigidBody)]
/// #[rigid(cuboid(mass = 1.0, size = [0.1, 0.2, 0.3]))]
/// #[free(gravity = 9.81)]
/// struct Brick;
///
/// let s0 = FreeState {
///     velocity: Vector3::new(0.0, 0.0, 9.81),
///     omega_principal: Vector3::new(0.05, 6.0, 0.05),
///     ..FreeState::at_rest()
/// };
/// let tight = AdaptiveConfig::with_tol(1e-12, 1e-12);
/// let mut flight = FreeFlight::new(FreeSystem(&Brick), 0.0, &s0, tight)?;
/// flight.advance_to(2.0)?;
/// let s = flight.state()?;
/// assert_relative_eq!(s.position.z, 0.0, epsilon = 1e-9);
/// assert_relative_eq!(s.attitude.quaternion().norm(), 1.0, epsilon = 1e-15);
/// # Ok::<(), precess::free::FreeError>(())
/// ```
#[derive(Debug, Clone)]
pub struct FreeFlight<S, P = Dop853Pair> {
    ode: Adaptive<S, P, STATE_LEN>,
    cfg: AdaptiveConfig,
    projection: Projection,
}

impl<S: System<STATE_LEN>> FreeFlight<S, Dop853Pair> {
    /// Starts at `state` at time `t0` with DOP853, projecting after every step.
    ///
    /// # Errors
    /// As [`FreeState::check`] for the state; [`FreeError::Ode`] for a bad configuration,
    /// a non-finite `t0` or a right-hand side that is not finite at the start (a NaN
    /// parameter).
    pub fn new(sys: S, t0: f64, state: &FreeState, cfg: AdaptiveConfig) -> Result<Self, FreeError> {
        Self::with_projection(sys, t0, state, cfg, Projection::default())
    }
}

impl<S: System<STATE_LEN>, P: EmbeddedPair> FreeFlight<S, P> {
    /// Starts at `state` at time `t0` with the pair `P` (name it:
    /// `FreeFlight::<_, Dopri5Pair>::with_projection(..)`), keeping the quaternion on the
    /// sphere as `projection` says.
    ///
    /// # Errors
    /// As [`FreeFlight::new`].
    pub fn with_projection(
        sys: S,
        t0: f64,
        state: &FreeState,
        cfg: AdaptiveConfig,
        projection: Projection,
    ) -> Result<Self, FreeError> {
        state.check()?;
        Ok(FreeFlight {
            ode: Adaptive::new(sys, t0, state.to_array(), cfg)?,
            cfg,
            projection,
        })
    }

    /// Current time.
    pub fn t(&self) -> f64 {
        self.ode.t()
    }

    /// The current state array.
    pub fn y(&self) -> &[f64; STATE_LEN] {
        self.ode.y()
    }

    /// The current state.
    ///
    /// # Errors
    /// As [`FreeState::from_array`] (a state the stepper produced is finite, so only a
    /// quaternion that collapsed to zero can fail).
    pub fn state(&self) -> Result<FreeState, FreeError> {
        FreeState::from_array(self.ode.y())
    }

    /// Work done so far.
    pub fn stats(&self) -> Stats {
        self.ode.stats()
    }

    /// Steps until `t == t_stop` exactly; no step crosses it.
    ///
    /// # Errors
    /// [`FreeError::Ode`] as [`Adaptive::step`] (a non-finite or past `t_stop`, a step size
    /// underflow, a non-finite state, more than `max_steps` attempts in this call: the budget
    /// is per run, as for [`Run`](crate::ode::Run), so a flight advanced in many short legs
    /// never exhausts it).
    pub fn advance_to(&mut self, t_stop: f64) -> Result<(), FreeError> {
        check_stop(self.t(), t_stop)?;
        let start = self.stats();
        while self.t() < t_stop {
            let total = self.stats();
            let attempts = (total.steps + total.rejections) - (start.steps + start.rejections);
            if attempts >= self.cfg.max_steps {
                return Err(OdeError::MaxStepsExceeded {
                    t: self.t(),
                    max_steps: self.cfg.max_steps,
                }
                .into());
            }
            self.ode.step(t_stop)?;
            if self.projection == Projection::EveryStep {
                self.project()?;
            }
        }
        Ok(())
    }

    /// Puts q back on the unit sphere and continues the pair from there: its stages belong
    /// to the unprojected state, so f is evaluated afresh; the step size and the
    /// controller's memory are kept ([`Stepper::restart`]).
    fn project(&mut self) -> Result<(), FreeError> {
        let mut y = *self.ode.y();
        let q = attitude_of(&y)?;
        let at = layout::QUATERNION;
        let unit = [q.w, q.i, q.j, q.k];
        if y[at..at + 4] == unit {
            return Ok(());
        }
        y[at..at + 4].copy_from_slice(&unit);
        let t = self.ode.t();
        Stepper::restart(&mut self.ode, t, y)?;
        Ok(())
    }
}
