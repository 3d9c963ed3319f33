//! A loop mechanism in the one run loop ([`crate::ode::Hybrid`]): after every accepted step
//! the projection puts the state back on the loop ([`LoopDynamics::close_loop`]: positions
//! by Newton, dependent rates from the free ones), and a state the projection could not
//! close, or a configuration where no choice of dependent coordinates is regular (the loop
//! folded flat), halts the run with a [`LoopHalt`] instead of stepping on.

use super::dynamics::{LoopDynamics, LoopSystem, halves};
use crate::lagrange::START_RESIDUAL;
use crate::mechanism::error::MechanismError;
use crate::ode::{Action, Dop853, HookAction, Hooks, Hybrid, HybridState, OdeError};

/// Why a loop mechanism's run stopped by itself.
#[derive(Clone, Debug, PartialEq)]
pub enum LoopHalt {
    /// After a step the loop could not be closed again: its residual max |φ| stayed above
    /// [`START_RESIDUAL`].
    Open {
        /// When.
        t: f64,
        /// The residual left.
        residual: f64,
    },
    /// The closure's Jacobian A lost rank: every block of dependent coordinates is singular
    /// (a four-bar folded flat, at a change point), where the motion is not determined.
    Singular {
        /// When.
        t: f64,
        /// The projection's complaint ([`LagrangeError::SingularAtState`](crate::lagrange::LagrangeError::SingularAtState)).
        error: MechanismError,
    },
}

/// The loop mechanism's run: DOP853 in the one run loop.
pub type LoopRun<'a, T, const N: usize, const M: usize, const K: usize, const S: usize> =
    Hybrid<Dop853<LoopSystem<'a, T, N, M, K>, S>>;

impl<T, const N: usize, const M: usize, const K: usize, const S: usize> Hooks<[f64; S]>
    for LoopSystem<'_, T, N, M, K>
where
    T: LoopDynamics<N, M, K>,
{
    /// Closes the loop; a failure leaves the state, for [`Hooks::after_step`] to halt on.
    fn project(&self, y: &mut [f64; S]) -> bool {
        let (mut q, mut qdot) = halves::<N, S>(y);
        match self.model.close_loop(&mut q, &mut qdot) {
            Ok(_) => {
                y[..N].copy_from_slice(&q);
                y[N..].copy_from_slice(&qdot);
                true
            }
            Err(_) => false,
        }
    }

    fn after_step(
        &self,
        t: f64,
        s: &HybridState<(), [f64; S]>,
    ) -> Result<HookAction<Self, [f64; S]>, OdeError> {
        let (q, _) = halves::<N, S>(&s.x);
        if let Err(error) = self.model.partition(&q) {
            return Ok(Action::Halt(LoopHalt::Singular { t, error }));
        }
        let residual = self.model.residual(&q);
        if residual.is_nan() || residual > START_RESIDUAL {
            return Ok(Action::Halt(LoopHalt::Open { t, residual }));
        }
        Ok(Action::Continue)
    }

    type Mode = ();
    type Halt = LoopHalt;

    fn mode(&self) {}

    fn set_mode(&mut self, _mode: ()) {}
}
