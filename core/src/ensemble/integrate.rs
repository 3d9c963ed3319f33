//! The common case: every run a stepper integrated to one end time.

use super::results::EnsembleResults;
use super::runner::Ensemble;
use crate::ode::{OdeError, Stepper, check_span};

impl Ensemble<'_> {
    /// Builds a stepper per run with `build(index)` (its system, parameters, initial state
    /// and tolerances), steps it to `t_end` (or until it halts by itself: a hybrid run whose
    /// scene stopped it, which `output` can read from the stepper), and keeps
    /// `output(index, &stepper)`.
    ///
    /// Any [`Stepper`]: the adaptive pairs ([`crate::ode::Dop853`], …), [`crate::ode::Rk4`],
    /// the splittings in a [`crate::ode::FixedStepper`], the Taylor integrator, and every
    /// scene's run ([`crate::ode::Hybrid`]: charted tops and mechanisms, free flights,
    /// bodies on a table).
    ///
    /// # Errors
    /// Per run, as [`EnsembleError::Run`](super::EnsembleError::Run): `build`'s error;
    /// [`OdeError::NonFiniteTime`] or [`OdeError::EndBeforeStart`] when `t_end` is not a
    /// finite time at or after the stepper's; the stepper's own failures
    /// ([`OdeError::NonFiniteState`], [`OdeError::MaxStepsExceeded`], …), converted into
    /// `E`; [`OdeError::StepSizeUnderflow`] if a step does not advance.
    /// [`EnsembleError::Panicked`](super::EnsembleError::Panicked) for a panic in either
    /// closure.
    pub fn integrate<S, T, E, B, O>(&self, t_end: f64, build: B, output: O) -> EnsembleResults<T, E>
    where
        S: Stepper,
        B: Fn(usize) -> Result<S, E> + Sync,
        O: Fn(usize, &S) -> T + Sync,
        E: From<OdeError> + Send,
        T: Send,
    {
        self.run(|index| {
            let mut stepper = build(index)?;
            check_span(stepper.t(), t_end)?;
            while stepper.t() < t_end && !stepper.halted() {
                let before = stepper.t();
                stepper.step(t_end)?;
                if stepper.t() <= before {
                    return Err(OdeError::StepSizeUnderflow { t: before, h: 0.0 }.into());
                }
            }
            Ok(output(index, &stepper))
        })
    }
}
