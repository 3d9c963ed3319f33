//! The one interface the trajectory and event machinery drives: a stepper that takes accepted
//! steps, can give its own solution anywhere inside the last one, and can be put back on a
//! state (a terminal event's).

use super::adaptive::Adaptive;
use super::error::OdeError;
use super::hybrid::Switchable;
use super::pairs::EmbeddedPair;
use super::system::{Stats, System};

/// A time stepper as [`Run`](super::Run) sees it: accepted steps, the solution inside the last
/// step, and a restart.
///
/// Implemented by the adaptive driver ([`Adaptive`]: [`Dopri5`](super::Dopri5),
/// [`Dop853`](super::Dop853), [`Vern9`](super::Vern9)), by [`Rk4`](super::Rk4), and by
/// [`FixedStepper`](super::FixedStepper) for any [`FixedStepMethod`](super::FixedStepMethod)
/// (the rigid-body splittings). A new integrator gets trajectories, observers and events by
/// implementing these seven methods.
///
/// Inside the last step, [`Stepper::state_at`] is the adaptive pairs' dense output; the
/// fixed-step methods have no high-order interpolant, so they re-step from the step's start
/// with a partial step, which is the method's own solution at that time, as accurate as its
/// steps.
///
/// ```
/// use precess_core::ode::{AdaptiveConfig, Dop853, FnSystem, Stepper};
/// let sys = FnSystem(|_t: f64, y: &[f64; 1], d: &mut [f64; 1]| d[0] = -y[0]);
/// let mut ode = Dop853::new(sys, 0.0, [1.0], AdaptiveConfig::with_tol(1e-12, 1e-14))?;
/// Stepper::step(&mut ode, 10.0)?;
/// let (t0, t1) = (ode.step_start(), Stepper::t(&ode));
/// let mid = ode.state_at(0.5 * (t0 + t1))?;
/// approx::assert_relative_eq!(mid[0], (-0.5 * (t0 + t1)).exp(), max_relative = 1e-12);
/// # Ok::<(), precess_core::ode::OdeError>(())
/// ```
pub trait Stepper {
    /// The state the stepper advances (an array for [`System`]s, `BodyMomentum` for the
    /// splittings).
    type State: Clone;

    /// Current time.
    fn t(&self) -> f64;

    /// Current state.
    fn state(&self) -> &Self::State;

    /// Work done so far.
    fn stats(&self) -> Stats;

    /// Takes one accepted step that does not pass `t_limit`, landing on it exactly at the end.
    ///
    /// # Errors
    /// [`OdeError::NonFiniteTime`], [`OdeError::StopBeforeCurrent`], and the stepper's own
    /// failures ([`OdeError::NonFiniteState`], …); the state is left as it was.
    fn step(&mut self, t_limit: f64) -> Result<(), OdeError>;

    /// Start of the last step (equal to [`Stepper::t`] before any step and after a restart).
    fn step_start(&self) -> f64;

    /// The stepper's solution at `t` inside the last step `[step_start, t]`.
    ///
    /// # Errors
    /// [`OdeError::NonFiniteTime`], [`OdeError::OutsideLastStep`], or the method's failure on
    /// the partial step.
    fn state_at(&mut self, t: f64) -> Result<Self::State, OdeError>;

    /// Puts the stepper at `(t, state)`, as if it had started there (the step size an
    /// adaptive driver had found is kept).
    ///
    /// # Errors
    /// [`OdeError::NonFiniteTime`], [`OdeError::NonFiniteInitialState`], or what the method
    /// checks of a state.
    fn restart(&mut self, t: f64, state: Self::State) -> Result<(), OdeError>;

    /// Whether the stepper has ended its run by itself (a [`Hybrid`](super::Hybrid) run
    /// whose scene halted it: a lift-off, a disk fallen flat); a halted stepper takes no
    /// more steps until it is restarted. The loops over steppers ([`Run`](super::Run),
    /// ensembles) stop there. The default never halts.
    fn halted(&self) -> bool {
        false
    }
}

/// The inherent accessors `t`, `y` and `stats` of a stepper over `[f64; N]` that keeps them
/// in fields of those names (the pairs' [`Adaptive`], [`Rk4`](super::Rk4), the Taylor
/// integrator), written once; the attributes given (a doc line) are added to `stats`.
/// Invoked inside the stepper's inherent `impl` as `state_accessors!(N)`.
macro_rules! state_accessors {
    ($n:ident $(, $(#[$stats:meta])+)?) => {
        /// Current time.
        pub fn t(&self) -> f64 {
            self.t
        }

        /// Current state.
        pub fn y(&self) -> &[f64; $n] {
            &self.y
        }

        /// Work done so far.
        $($(#[$stats])+)?
        pub fn stats(&self) -> $crate::ode::Stats {
            self.stats
        }
    };
}
pub(crate) use state_accessors;

/// The [`Stepper`] of an adaptive driver over `[f64; N]` whose inherent methods carry the
/// trait's meaning (`t`, `y`, `stats`, `step`, `last_step_start`, `dense_at`,
/// `reset_state`): the pairs' [`Adaptive`] and the Taylor integrator, written once.
/// Invoked as `inherent_stepper!([generics] Type, N)`.
macro_rules! inherent_stepper {
    ([$($generics:tt)*] $ty:ty, $n:ident) => {
        impl<$($generics)*> $crate::ode::Stepper for $ty {
            type State = [f64; $n];

            fn t(&self) -> f64 {
                <$ty>::t(self)
            }

            fn state(&self) -> &[f64; $n] {
                self.y()
            }

            fn stats(&self) -> $crate::ode::Stats {
                <$ty>::stats(self)
            }

            fn step(&mut self, t_limit: f64) -> Result<(), $crate::ode::OdeError> {
                <$ty>::step(self, t_limit)
            }

            fn step_start(&self) -> f64 {
                self.last_step_start()
            }

            fn state_at(&mut self, t: f64) -> Result<[f64; $n], $crate::ode::OdeError> {
                self.dense_at(t)
            }

            fn restart(&mut self, t: f64, state: [f64; $n]) -> Result<(), $crate::ode::OdeError> {
                if !t.is_finite() {
                    return Err($crate::ode::OdeError::NonFiniteTime { t });
                }
                $crate::ode::check_finite(&state)?;
                self.check_system()?;
                self.reset_state(t, state);
                Ok(())
            }
        }
    };
}
pub(crate) use inherent_stepper;

inherent_stepper!([S: System<N>, P: EmbeddedPair, const N: usize] Adaptive<S, P, N>, N);

impl<S: System<N>, P: EmbeddedPair, const N: usize> Switchable for Adaptive<S, P, N> {
    type System = S;

    fn system(&self) -> &S {
        Adaptive::system(self)
    }

    fn switch(
        &mut self,
        t: f64,
        state: [f64; N],
        fresh: bool,
        change: &mut dyn FnMut(&mut S),
    ) -> Result<(), OdeError> {
        if !t.is_finite() {
            return Err(OdeError::NonFiniteTime { t });
        }
        super::check_finite(&state)?;
        self.modify_system(|s| change(s));
        if fresh {
            self.reinitialise(t, state)
        } else {
            Stepper::restart(self, t, state)
        }
    }
}
