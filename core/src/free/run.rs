//! A free body integrated by an adaptive embedded pair in the one run loop
//! ([`crate::ode::Hybrid`]), whose hook puts the attitude quaternion back on the unit sphere
//! after every accepted step.

use super::error::FreeError;
use super::state::{FreeState, STATE_LEN, layout};
use crate::ode::{
    Adaptive, AdaptiveConfig, Dop853Pair, EmbeddedPair, Hooks, Hybrid, HybridState, OdeError,
    Stats, Stepper, System,
};
use crate::rigid::normalise_quaternion;

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
pub struct FreeFlight<S, P = Dop853Pair>
where
    S: System<STATE_LEN>,
    P: EmbeddedPair,
{
    run: Hybrid<Adaptive<Flight<S>, P, STATE_LEN>>,
}

/// A free body's system with the hook of its flight: the quaternion projected after every
/// step (or never), one mode, no witnesses.
#[derive(Debug, Clone)]
pub struct Flight<S> {
    sys: S,
    projection: Projection,
}

impl<S: System<STATE_LEN>> System<STATE_LEN> for Flight<S> {
    #[inline]
    fn rhs(&self, t: f64, y: &[f64; STATE_LEN], dydt: &mut [f64; STATE_LEN]) {
        self.sys.rhs(t, y, dydt)
    }

    fn check_parameters(&self) -> Result<(), OdeError> {
        self.sys.check_parameters()
    }

    fn explain_non_finite(&self, t: f64, y: &[f64; STATE_LEN]) -> Option<OdeError> {
        self.sys.explain_non_finite(t, y)
    }
}

impl<S> Hooks<[f64; STATE_LEN]> for Flight<S> {
    type Mode = ();
    type Halt = core::convert::Infallible;

    fn mode(&self) {}

    fn set_mode(&mut self, _mode: ()) {}

    fn project(&self, x: &mut [f64; STATE_LEN]) -> bool {
        self.projection == Projection::EveryStep && normalise_quaternion(x, layout::QUATERNION)
    }
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
        let flight = Flight { sys, projection };
        let ode = Adaptive::new(flight, t0, state.to_array(), cfg)?;
        Ok(FreeFlight {
            run: Hybrid::new(ode)?.with_max_steps(cfg.max_steps),
        })
    }

    /// Current time.
    pub fn t(&self) -> f64 {
        self.run.t()
    }

    /// The current state array.
    pub fn y(&self) -> &[f64; STATE_LEN] {
        &self.run.state().x
    }

    /// The current state.
    ///
    /// # Errors
    /// As [`FreeState::from_array`] (a state the stepper produced is finite, so only a
    /// quaternion that collapsed to zero can fail).
    pub fn state(&self) -> Result<FreeState, FreeError> {
        FreeState::from_array(self.y())
    }

    /// Work done so far.
    pub fn stats(&self) -> Stats {
        self.run.stats()
    }

    /// The run loop itself, for what the flight does not wrap.
    pub fn run(&self) -> &Hybrid<Adaptive<Flight<S>, P, STATE_LEN>> {
        &self.run
    }

    /// Steps until `t == t_stop` exactly; no step crosses it.
    ///
    /// # Errors
    /// [`FreeError::Ode`] as [`Adaptive::step`] (a non-finite or past `t_stop`, a step size
    /// underflow, a non-finite state, more than `max_steps` attempts towards `t_stop`: the
    /// budget is per stop time, as for [`Run`](crate::ode::Run), so a flight advanced in
    /// many short legs never exhausts it).
    pub fn advance_to(&mut self, t_stop: f64) -> Result<(), FreeError> {
        Ok(self.run.advance_to(t_stop)?)
    }
}

crate::ode::delegate_stepper!(
    [S: System<STATE_LEN>, P: EmbeddedPair] FreeFlight<S, P>,
    run,
    HybridState<(), [f64; STATE_LEN]>
);
