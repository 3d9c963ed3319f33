//! Fixed-step methods as [`Stepper`]s: the equal-step grid they share, the one-step interface
//! a method implements ([`FixedStepMethod`]), and the clock that runs it ([`FixedStepper`]).

use super::config::FixedStepConfig;
use super::error::OdeError;
use super::stepper::Stepper;
use super::system::Stats;

/// The equal steps from a start to a limit: step i ends at `t0 + i h`, the last exactly on
/// the limit, so a long run gathers no round-off in t.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct StepGrid {
    t0: f64,
    h: f64,
    n: u64,
    done: u64,
    t_limit: f64,
}

impl StepGrid {
    /// The next step `(start, h, end)` from `t` towards `t_limit`: continues `grid` when it
    /// was planned for this limit and `t` is where it left off, else plans anew under `cfg`;
    /// `None` when `t == t_limit`. The caller advances the grid with [`StepGrid::advance`]
    /// once the step is taken.
    ///
    /// # Errors
    /// As [`FixedStepConfig::plan`]: a non-finite or earlier limit, too many steps.
    pub(crate) fn next(
        grid: &mut Option<StepGrid>,
        cfg: &FixedStepConfig,
        t: f64,
        t_limit: f64,
    ) -> Result<Option<(f64, f64)>, OdeError> {
        let reusable = matches!(grid, Some(g) if g.t_limit == t_limit && g.done < g.n
            && g.time(g.done) == t);
        if !reusable {
            *grid = cfg.plan(t, t_limit)?.map(|(n, h)| StepGrid {
                t0: t,
                h,
                n,
                done: 0,
                t_limit,
            });
        }
        Ok(grid.map(|g| (g.h, g.time(g.done + 1))))
    }

    /// Marks the step returned by [`StepGrid::next`] as taken.
    pub(crate) fn advance(grid: &mut Option<StepGrid>) {
        if let Some(g) = grid {
            g.done += 1;
        }
    }

    /// The end of step i.
    fn time(&self, i: u64) -> f64 {
        if i >= self.n {
            self.t_limit
        } else {
            self.t0 + i as f64 * self.h
        }
    }
}

/// The [`Stepper`] accessors of a fixed-step stepper whose clock is its fields `t`, `y`,
/// `t_prev` and `stats` ([`FixedStepper`] and [`Rk4`](super::Rk4)), written once; invoked
/// inside the `impl Stepper` as `fixed_step_clock!(State)`.
macro_rules! fixed_step_clock {
    ($state:ty) => {
        fn t(&self) -> f64 {
            self.t
        }

        fn state(&self) -> &$state {
            &self.y
        }

        fn stats(&self) -> $crate::ode::Stats {
            self.stats
        }

        fn step_start(&self) -> f64 {
            self.t_prev
        }
    };
}
pub(crate) use fixed_step_clock;

/// [`Switchable::switch`](super::Switchable::switch) of a stepper whose fresh start and
/// continued start are the same (the fixed-step methods, RK4, the Taylor integrator): the time and
/// `check` refuse a bad `(t, state)` before the system changes, so that a refused switch
/// leaves the stepper and its system as they were; then `change` is applied to `system`
/// and the stepper restarts at `(t, state)`, which checks the changed system. A fixed step
/// has no size to choose, and the Taylor integrator chooses each from its jet, so for them a
/// fresh start is the same as a continued one.
///
/// # Errors
/// [`OdeError::NonFiniteTime`], `check`'s refusal, then [`Stepper::restart`]'s.
pub(crate) fn switch_by_restart<T: Stepper, Sy>(
    stepper: &mut T,
    (t, state): (f64, T::State),
    check: impl FnOnce(&T, &T::State) -> Result<(), OdeError>,
    system: impl FnOnce(&mut T) -> &mut Sy,
    change: &mut dyn FnMut(&mut Sy),
) -> Result<(), OdeError> {
    if !t.is_finite() {
        return Err(OdeError::NonFiniteTime { t });
    }
    check(stepper, &state)?;
    change(system(stepper));
    stepper.restart(t, state)
}

/// The [`Switchable`](super::Switchable) of a stepper whose fresh start and continued start
/// are the same ([`FixedStepper`], [`Rk4`](super::Rk4), the Taylor integrator), written once:
/// the system is the stepper's field `$field`, changed through `$system_mut` (`|stepper|`,
/// which may also drop what the stepper computed from the old system), `$check`
/// (`|stepper, state|`) refuses a bad state, and the switch is [`switch_by_restart`].
/// Invoked as `restart_switchable!([generics] Type, field: System, system_mut, check)`.
macro_rules! restart_switchable {
    ([$($generics:tt)*] $ty:ty, $field:ident: $sys:ty, $system_mut:expr, $check:expr) => {
        impl<$($generics)*> $crate::ode::Switchable for $ty {
            type System = $sys;

            fn system(&self) -> &$sys {
                &self.$field
            }

            fn switch(
                &mut self,
                t: f64,
                state: <Self as $crate::ode::Stepper>::State,
                _fresh: bool,
                change: &mut dyn FnMut(&mut $sys),
            ) -> Result<(), $crate::ode::OdeError> {
                $crate::ode::switch_by_restart(self, (t, state), $check, $system_mut, change)
            }
        }
    };
}
pub(crate) use restart_switchable;

/// One step of a fixed-step method on its own state, for [`FixedStepper`].
///
/// The rigid-body splittings implement it (`FreeBodySplitting`, `PotentialSplitting` on
/// `BodyMomentum`); so can any method that maps `(t, y, h)` to the state at `t + h`.
pub trait FixedStepMethod {
    /// The state the method advances.
    type State: Clone;

    /// Checks a state before the method steps from it (default: nothing to check).
    ///
    /// # Errors
    /// The method's own refusal (a non-finite component, a quaternion that is no rotation).
    fn check_state(&self, _y: &Self::State) -> Result<(), OdeError> {
        Ok(())
    }

    /// Checks the method's parameters once, when a [`FixedStepper`] is built or restarted
    /// (default: nothing to check), as [`super::System::check_parameters`] does for the
    /// systems.
    ///
    /// # Errors
    /// [`OdeError::InvalidSystemParameter`] naming the quantity and its value.
    fn check_parameters(&self) -> Result<(), OdeError> {
        Ok(())
    }

    /// Advances `y` from `t` by `h > 0`; on error `y` is left as it was.
    ///
    /// # Errors
    /// [`OdeError::NonFiniteState`] when the step is not finite, its `t` counted from the
    /// start of the call (0: the splittings carry no clock; [`FixedStepper`] adds the step's
    /// start), or the method's own.
    fn advance(&self, t: f64, y: &mut Self::State, h: f64) -> Result<(), OdeError>;
}

impl<M: FixedStepMethod + ?Sized> FixedStepMethod for &M {
    type State = M::State;
    fn check_state(&self, y: &Self::State) -> Result<(), OdeError> {
        (**self).check_state(y)
    }
    fn check_parameters(&self) -> Result<(), OdeError> {
        (**self).check_parameters()
    }
    fn advance(&self, t: f64, y: &mut Self::State, h: f64) -> Result<(), OdeError> {
        (**self).advance(t, y, h)
    }
}

/// A [`FixedStepMethod`] with a clock: equal steps no longer than the configured `h`, the
/// solution inside the last step by a partial step from its start, and a restart.
///
/// ```
/// use precess_core::ode::{FixedStepConfig, FixedStepMethod, FixedStepper, OdeError, Stepper};
/// /// The exact flow of y' = −y, as a "method".
/// struct Decay;
/// impl FixedStepMethod for Decay {
///     type State = f64;
///     fn advance(&self, _t: f64, y: &mut f64, h: f64) -> Result<(), OdeError> {
///         *y *= (-h).exp();
///         Ok(())
///     }
/// }
/// let mut s = FixedStepper::new(Decay, 0.0, 1.0, FixedStepConfig::with_step(0.25))?;
/// s.step(1.0)?;
/// approx::assert_relative_eq!(s.t(), 0.25);
/// approx::assert_relative_eq!(s.state_at(0.1)?, (-0.1f64).exp(), max_relative = 1e-15);
/// # Ok::<(), OdeError>(())
/// ```
#[derive(Debug, Clone)]
pub struct FixedStepper<M: FixedStepMethod> {
    method: M,
    cfg: FixedStepConfig,
    t: f64,
    y: M::State,
    t_prev: f64,
    y_prev: M::State,
    grid: Option<StepGrid>,
    stats: Stats,
}

impl<M: FixedStepMethod> FixedStepper<M> {
    /// Starts `method` at `(t0, y0)` with steps no longer than `cfg.h`.
    ///
    /// # Errors
    /// [`OdeError::InvalidStep`], [`OdeError::NonFiniteTime`], or the method's
    /// [`FixedStepMethod::check_state`] and [`FixedStepMethod::check_parameters`].
    pub fn new(method: M, t0: f64, y0: M::State, cfg: FixedStepConfig) -> Result<Self, OdeError> {
        cfg.validate()?;
        if !t0.is_finite() {
            return Err(OdeError::NonFiniteTime { t: t0 });
        }
        method.check_state(&y0)?;
        method.check_parameters()?;
        Ok(Self {
            method,
            cfg,
            t: t0,
            y: y0.clone(),
            t_prev: t0,
            y_prev: y0,
            grid: None,
            stats: Stats::default(),
        })
    }

    /// The method.
    pub fn method(&self) -> &M {
        &self.method
    }

    /// One step of the method from `(t, y)`, its error's time counted from the start of the
    /// run rather than of the call.
    fn advance_from(&self, t: f64, y: &mut M::State, h: f64) -> Result<(), OdeError> {
        self.method.advance(t, y, h).map_err(|e| match e {
            OdeError::NonFiniteState { t: since } => OdeError::NonFiniteState { t: t + since },
            other => other,
        })
    }
}

/// Its stats count the steps taken; the splittings evaluate no right-hand side, so
/// `rhs_evals` stays 0.
impl<M: FixedStepMethod> Stepper for FixedStepper<M> {
    type State = M::State;

    fixed_step_clock!(M::State);

    fn step(&mut self, t_limit: f64) -> Result<(), OdeError> {
        let Some((h, t_new)) = StepGrid::next(&mut self.grid, &self.cfg, self.t, t_limit)? else {
            return Ok(());
        };
        let mut y = self.y.clone();
        self.advance_from(self.t, &mut y, h)?;
        StepGrid::advance(&mut self.grid);
        self.t_prev = self.t;
        self.y_prev = core::mem::replace(&mut self.y, y);
        self.t = t_new;
        self.stats.steps += 1;
        Ok(())
    }

    fn state_at(&mut self, t: f64) -> Result<M::State, OdeError> {
        check_inside(t, self.t_prev, self.t)?;
        if t == self.t {
            return Ok(self.y.clone());
        }
        let mut y = self.y_prev.clone();
        if t > self.t_prev {
            self.advance_from(self.t_prev, &mut y, t - self.t_prev)?;
        }
        Ok(y)
    }

    fn restart(&mut self, t: f64, state: M::State) -> Result<(), OdeError> {
        if !t.is_finite() {
            return Err(OdeError::NonFiniteTime { t });
        }
        self.method.check_state(&state)?;
        self.method.check_parameters()?;
        self.t = t;
        self.t_prev = t;
        self.y_prev = state.clone();
        self.y = state;
        self.grid = None;
        Ok(())
    }
}

// The state checked by the method, then the method changed.
restart_switchable!([M: FixedStepMethod] FixedStepper<M>, method: M, |s| &mut s.method, |s, y| {
    s.method.check_state(y)
});

/// Knuth's TwoSum: `(s, e)` with s = fl(a + b) and a + b = s + e exactly, whatever the
/// magnitudes; the compensated updates keep `e` beside the state and add it back next step.
#[inline]
pub(crate) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// Checks that `t` is finite and inside the last step `[t_prev, t_now]`.
///
/// # Errors
/// [`OdeError::NonFiniteTime`], [`OdeError::OutsideLastStep`].
pub(crate) fn check_inside(t: f64, t_prev: f64, t_now: f64) -> Result<(), OdeError> {
    if !t.is_finite() {
        return Err(OdeError::NonFiniteTime { t });
    }
    if t >= t_prev && t <= t_now {
        Ok(())
    } else {
        Err(OdeError::OutsideLastStep { t, t_prev, t_now })
    }
}

#[cfg(test)]
mod tests {
    use super::super::Switchable;
    use super::*;

    /// y' = −k y, advanced exactly.
    struct Decay {
        k: f64,
    }

    impl FixedStepMethod for Decay {
        type State = f64;
        fn advance(&self, _t: f64, y: &mut f64, h: f64) -> Result<(), OdeError> {
            *y *= (-self.k * h).exp();
            Ok(())
        }
    }

    /// A switch refused for its time leaves the method as it was: the time is checked
    /// before the change is applied, not after (which changed the method and then refused).
    #[test]
    fn a_switch_refused_for_its_time_changes_nothing() {
        let cfg = FixedStepConfig::with_step(0.25);
        let mut s = FixedStepper::new(Decay { k: 1.0 }, 0.0, 1.0, cfg).expect("a valid start");
        let e = s.switch(f64::NAN, 1.0, false, &mut |m: &mut Decay| m.k = 2.0);
        assert!(
            matches!(e, Err(OdeError::NonFiniteTime { t }) if t.is_nan()),
            "{e:?}"
        );
        assert_eq!(s.system().k, 1.0);
        // A good switch changes it and restarts there.
        s.switch(0.5, 2.0, false, &mut |m: &mut Decay| m.k = 2.0)
            .expect("a finite switch");
        assert_eq!((s.system().k, s.t(), *s.state()), (2.0, 0.5, 2.0));
    }
}
