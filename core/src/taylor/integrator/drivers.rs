//! The Taylor integrator as the rest of precess sees a stepper: [`Stepper`] for
//! [`Run`](crate::ode::Run), and the one-call drivers in the shape of [`crate::ode::solve`].

use super::{Taylor, TaylorConfig};
use crate::ode::drivers::{check_sampling, check_sorted, sample, through_stops};
use crate::ode::{OdeError, Solution, Stats, check_span, inherent_stepper, restart_switchable};
use crate::taylor::TaylorSystem;

inherent_stepper!([S: TaylorSystem<N>, const N: usize] Taylor<S, N>, N);

// The Taylor integrator chooses every step from its jet, so a fresh start and a continued
// one are the same; `system_mut` drops the jet computed ahead with the old system.
restart_switchable!([S: TaylorSystem<N>, const N: usize] Taylor<S, N>, sys: S, |s| s.system_mut(), |_, y| {
    crate::ode::check_finite(y)
});

/// Integrates from `(t0, y0)` to `t_end` with the Taylor integrator, stopping exactly at
/// each time in `stops` (ascending; those past `t_end` are ignored), as
/// [`ode::solve`](crate::ode::solve) does for the pairs.
///
/// ```
/// use precess_core::taylor::{TaylorConfig, TaylorSystem, solve};
/// /// The harmonic oscillator x'' = −x as (x, v): c_{k+1} = (v_k, −x_k)/(k + 1).
/// struct Oscillator;
/// impl TaylorSystem<2> for Oscillator {
///     fn max_order(&self) -> usize { 40 }
///     type Workspace = ();
///     fn coefficients_into(&self, _ws: &mut (), _t: f64, y: &[f64; 2], order: usize, c: &mut [[f64; 2]]) {
///         c[0] = *y;
///         for k in 0..order {
///             let d = (k + 1) as f64;
///             c[k + 1] = [c[k][1] / d, -c[k][0] / d];
///         }
///     }
/// }
/// let cfg = TaylorConfig::with_tol(1e-15, 1e-15);
/// let s = solve(Oscillator, 0.0, [1.0, 0.0], 100.0, &[50.0], cfg)?;
/// approx::assert_relative_eq!(s.y[0], 100.0f64.cos(), epsilon = 1e-13);
/// # Ok::<(), precess_core::ode::OdeError>(())
/// ```
///
/// # Errors
/// Bad input ([`OdeError::EndBeforeStart`], an invalid configuration, non-finite values,
/// unsorted stops as [`OdeError::StopBeforeCurrent`]) before any work; then the stepping
/// errors of [`Taylor::step`].
pub fn solve<S: TaylorSystem<N>, const N: usize>(
    sys: S,
    t0: f64,
    y0: [f64; N],
    t_end: f64,
    stops: &[f64],
    cfg: TaylorConfig,
) -> Result<Solution<N>, OdeError> {
    check_span(t0, t_end)?;
    check_sorted(t0, stops)?;
    let mut ode = Taylor::new(sys, t0, y0, cfg)?;
    through_stops(&mut ode, t_end, stops)
}

/// Integrates from `(t0, y0)` and writes the state at each of `times` (ascending, ≥ t0),
/// from the step polynomials, into `out`; the steps are the integrator's own.
///
/// # Errors
/// As [`solve`], and [`OdeError::InvalidParameter`] if `out` is shorter than `times`.
pub fn solve_dense<S: TaylorSystem<N>, const N: usize>(
    sys: S,
    t0: f64,
    y0: [f64; N],
    times: &[f64],
    out: &mut [[f64; N]],
    cfg: TaylorConfig,
) -> Result<Stats, OdeError> {
    check_sampling(t0, times, out)?;
    let mut ode = Taylor::new(sys, t0, y0, cfg)?;
    sample(&mut ode, times, out)
}
