//! A rolling mechanism in the one run loop ([`crate::ode::Hybrid`]): its lowest wheel's tilt
//! is a witness, so a wheel that falls flat stops the run with
//! [`RollingHalt::WheelFlat`] where its tilt reaches [`FLAT_WITNESS`] = 2 [`MIN_TILT`], a
//! configuration its contact can still be placed in, rather than failing later with a
//! non-finite state. The margin keeps the witness's root resolvable: a disk falling onto its
//! face at a few rad/s crosses the last microradian of tilt in 10⁻⁷ s, while the right-hand
//! side is refused at [`MIN_TILT`] itself.

use super::dynamics::{MIN_TILT, RollingDynamics, RollingSystem, split_rolling};
use crate::mechanism::error::MechanismError;
use crate::ode::{
    Action, AdaptiveConfig, Dop853, HookAction, Hooks, Hybrid, HybridState, OdeError,
};

/// The tilt at which a rolling mechanism's run halts: twice the smallest tilt its
/// configurations may have.
pub const FLAT_WITNESS: f64 = 2.0 * MIN_TILT;

/// Why a rolling mechanism's run stopped by itself.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RollingHalt {
    /// A disk's tilt |d| (the cosine of its lean from the vertical) fell to
    /// [`FLAT_WITNESS`]: lying flat, its rim's lowest point would no longer be one point.
    WheelFlat {
        /// When (the last time the tilt was at least [`FLAT_WITNESS`]).
        t: f64,
        /// The wheel, in the order of the description.
        wheel: usize,
        /// Its tilt there.
        tilt: f64,
    },
}

/// The rolling mechanism's run: DOP853 in the one run loop.
pub type RollingRun<'a, T, const N: usize, const M: usize, const K: usize, const S: usize> =
    Hybrid<Dop853<RollingSystem<'a, T, N, M, K, S>, S>>;

impl<T, const N: usize, const M: usize, const K: usize, const S: usize> Hooks<[f64; S]>
    for RollingSystem<'_, T, N, M, K, S>
where
    T: RollingDynamics<N, M, K>,
{
    type Mode = ();
    type Halt = RollingHalt;

    fn mode(&self) {}

    fn set_mode(&mut self, _mode: ()) {}

    fn witness_names(&self) -> &[&'static str] {
        &["wheel tilt"]
    }

    /// The lowest wheel's tilt above [`FLAT_WITNESS`]: the smallest of continuous
    /// functions, continuous.
    fn witness(&self, _mode: &(), _id: usize, _t: f64, y: &[f64; S]) -> f64 {
        let (q, _) = split_rolling::<N, K, S>(y);
        self.model().lowest_tilt(&q).1 - FLAT_WITNESS
    }

    fn on_witness(
        &self,
        _id: usize,
        t: f64,
        s: &HybridState<(), [f64; S]>,
        _w: f64,
    ) -> Result<HookAction<Self, [f64; S]>, OdeError> {
        let (q, _) = split_rolling::<N, K, S>(&s.x);
        let (wheel, tilt) = self.model().lowest_tilt(&q);
        Ok(Action::Halt(RollingHalt::WheelFlat { t, wheel, tilt }))
    }
}

/// Starts `model` at `(t0, y0)`, `y0 = (q, u)`, in the one run loop with DOP853: a
/// [`Stepper`](crate::ode::Stepper) for [`Run`](crate::ode::Run), trajectories and
/// ensembles, which halts with [`RollingHalt::WheelFlat`] where a wheel falls flat.
///
/// # Errors
/// As [`RollingDynamics::check_start`]; [`MechanismError::Ode`] for a bad configuration of
/// the stepper or a right-hand side that is not finite at the start.
pub fn rolling_run<T, const N: usize, const M: usize, const K: usize, const S: usize>(
    model: &T,
    t0: f64,
    y0: [f64; S],
    cfg: AdaptiveConfig,
) -> Result<RollingRun<'_, T, N, M, K, S>, MechanismError>
where
    T: RollingDynamics<N, M, K>,
{
    let (q, _) = split_rolling::<N, K, S>(&y0);
    model.check_start(&q)?;
    let ode = Dop853::new(model.rolling_system::<S>(), t0, y0, cfg)?;
    Ok(Hybrid::new(ode)?.with_max_steps(cfg.max_steps))
}
