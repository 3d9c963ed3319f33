//! The drivers: [`Adaptive`] named for each pair, and one-call functions that integrate to an
//! end time through stop times or sample the dense output at given times.

use super::adaptive::Adaptive;
use super::config::AdaptiveConfig;
use super::error::{OdeError, check_span};
use super::pairs::{Dop853Pair, Dopri5Pair, EmbeddedPair, Vern9Pair};
use super::stepper::Stepper;
use super::system::{Stats, System};

/// The Dormand–Prince 5(4) driver: [`Adaptive`] with [`Dopri5Pair`].
pub type Dopri5<S, const N: usize> = Adaptive<S, Dopri5Pair, N>;

/// The DOP853 driver: [`Adaptive`] with [`Dop853Pair`].
pub type Dop853<S, const N: usize> = Adaptive<S, Dop853Pair, N>;

/// The Verner 9(8) driver: [`Adaptive`] with [`Vern9Pair`].
pub type Vern9<S, const N: usize> = Adaptive<S, Vern9Pair, N>;

/// End state of an integration and the work it took.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Solution<const N: usize> {
    /// Final time (equal to the requested end time).
    pub t: f64,
    /// Final state.
    pub y: [f64; N],
    /// Steps, rejections and evaluations.
    pub stats: Stats,
}

/// Integrates from `(t0, y0)` to `t_end` with pair `P`, stopping exactly at each time in
/// `stops` (sorted ascending; those past `t_end` are ignored) so that no step straddles a
/// discontinuity of the right-hand side.
///
/// A step that ends on a stop evaluates its last stages just before it, and the next step
/// starts with a fresh f at the stop (one extra evaluation per stop), so a switch written as
/// a function of t should take its new value at the switching time (`t < t_s` on one side,
/// `t ≥ t_s` on the other). Alternatively stop with [`Adaptive::advance_to`] and flip a
/// flag with [`Adaptive::modify_system`].
///
/// ```
/// use precess_core::ode::{AdaptiveConfig, Dop853Pair, FnSystem, solve};
/// // y' = 1 on [0, 1], 0 afterwards: exact y(2) = 1.
/// let sys = FnSystem(|t: f64, _y: &[f64; 1], d: &mut [f64; 1]| d[0] = if t < 1.0 { 1.0 } else { 0.0 });
/// let s = solve::<Dop853Pair, _, 1>(sys, 0.0, [0.0], 2.0, &[1.0], AdaptiveConfig::default())?;
/// approx::assert_relative_eq!(s.y[0], 1.0, epsilon = 1e-14);
/// # Ok::<(), precess_core::ode::OdeError>(())
/// ```
///
/// # Errors
/// Bad input ([`OdeError::EndBeforeStart`], [`OdeError::InvalidTolerance`], non-finite
/// values, unsorted stops as [`OdeError::StopBeforeCurrent`]) before any work; then the
/// stepping errors of [`Adaptive::step`].
pub fn solve<P: EmbeddedPair, S: System<N>, const N: usize>(
    sys: S,
    t0: f64,
    y0: [f64; N],
    t_end: f64,
    stops: &[f64],
    cfg: AdaptiveConfig,
) -> Result<Solution<N>, OdeError> {
    check_span(t0, t_end)?;
    check_sorted(t0, stops)?;
    let mut ode = Adaptive::<S, P, N>::new(sys, t0, y0, cfg)?;
    through_stops(&mut ode, t_end, stops)
}

/// Integrates from `(t0, y0)` and writes the dense-output state at each of `times`
/// (ascending, ≥ t0) into `out`; the steps are chosen by the controller alone.
///
/// # Errors
/// As [`solve`], and [`OdeError::InvalidParameter`] if `out` is shorter than `times`.
pub fn solve_dense<P: EmbeddedPair, S: System<N>, const N: usize>(
    sys: S,
    t0: f64,
    y0: [f64; N],
    times: &[f64],
    out: &mut [[f64; N]],
    cfg: AdaptiveConfig,
) -> Result<Stats, OdeError> {
    check_sampling(t0, times, out)?;
    let mut ode = Adaptive::<S, P, N>::new(sys, t0, y0, cfg)?;
    sample(&mut ode, times, out)
}

/// The body of every `solve`: steps `ode` to each stop before `t_end`, landing on it, then
/// to `t_end`. The stops are checked ([`check_sorted`]) by the caller.
pub(crate) fn through_stops<St, const N: usize>(
    ode: &mut St,
    t_end: f64,
    stops: &[f64],
) -> Result<Solution<N>, OdeError>
where
    St: Stepper<State = [f64; N]>,
{
    for &stop in stops.iter().filter(|&&s| s < t_end).chain([&t_end]) {
        while ode.t() < stop {
            if ode.halted() {
                return Err(OdeError::Halted { t: ode.t() });
            }
            ode.step(stop)?;
        }
    }
    Ok(Solution {
        t: ode.t(),
        y: *ode.state(),
        stats: ode.stats(),
    })
}

/// Checks the sample times and the room for them, before any work.
pub(crate) fn check_sampling<const N: usize>(
    t0: f64,
    times: &[f64],
    out: &[[f64; N]],
) -> Result<(), OdeError> {
    check_sorted(t0, times)?;
    if out.len() < times.len() {
        return Err(OdeError::InvalidParameter {
            name: "out.len()",
            value: out.len() as f64,
        });
    }
    Ok(())
}

/// The body of every `solve_dense`: the stepper's own steps up to the last time, each
/// sample from its solution inside the step that holds it (the start state at `t0`).
pub(crate) fn sample<St, const N: usize>(
    ode: &mut St,
    times: &[f64],
    out: &mut [[f64; N]],
) -> Result<Stats, OdeError>
where
    St: Stepper<State = [f64; N]>,
{
    let t0 = ode.t();
    let t_end = times.last().copied().unwrap_or(t0);
    for (&ti, o) in times.iter().zip(out.iter_mut()) {
        if ti == t0 {
            *o = *ode.state();
            continue;
        }
        while ode.t() < ti {
            if ode.halted() {
                return Err(OdeError::Halted { t: ode.t() });
            }
            ode.step(t_end)?;
        }
        *o = ode.state_at(ti)?;
    }
    Ok(ode.stats())
}

/// Checks that `times` are finite, ascending and not before `t0`.
pub(crate) fn check_sorted(t0: f64, times: &[f64]) -> Result<(), OdeError> {
    let mut last = t0;
    for &s in times {
        if !s.is_finite() {
            return Err(OdeError::NonFiniteTime { t: s });
        }
        if s < last {
            return Err(OdeError::StopBeforeCurrent { stop: s, t: last });
        }
        last = s;
    }
    Ok(())
}
