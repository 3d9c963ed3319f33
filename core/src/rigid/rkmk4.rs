//! The Runge–Kutta–Munthe-Kaas method of order 4 on SO(3) × ℝᵏ.
//!
//! The state is advanced as y = y₀ · exp(Θ) with Θ̇ = dexp⁻¹₋Θ(ξ(y)) solved by classical
//! RK4 in the algebra, so every stage and the result stay on the group: |q| = 1 up to one
//! rounding per step, whatever the step size.

use super::kinematics::dexpinv_right;
use super::lie::{LieState, LieSystem, Tangent};
use crate::ode::{FixedStepConfig, OdeError, Stats, check_span};

/// Runge–Kutta–Munthe-Kaas of order 4 (RK4 in the algebra with the exact dexp⁻¹ on so(3)).
///
/// ```
/// use nalgebra::{UnitQuaternion, Vector3};
/// use precess_core::ode::FixedStepConfig;
/// use precess_core::rigid::{Attitude, AttitudeModel, Rkmk4};
/// struct Sym;
/// impl AttitudeModel for Sym {
///     fn inertia(&self) -> [f64; 3] { [1.0, 1.0, 1.0] }
/// }
/// // A sphere spins uniformly: after t = π about z, q = (0, 0, 0, 1).
/// let s0 = Attitude { q: UnitQuaternion::identity(), omega: Vector3::new(0.0, 0.0, 1.0) };
/// let mut m = Rkmk4::new(Sym, 0.0, s0, FixedStepConfig::with_step(0.1))?;
/// m.advance_to(std::f64::consts::PI)?;
/// approx::assert_relative_eq!(m.state().q.k, 1.0, epsilon = 1e-14);
/// # Ok::<(), precess_core::ode::OdeError>(())
/// ```
#[derive(Debug, Clone)]
pub struct Rkmk4<S, Y> {
    sys: S,
    cfg: FixedStepConfig,
    t: f64,
    y: Y,
    stats: Stats,
}

impl<Y: LieState, S: LieSystem<Y>> Rkmk4<S, Y> {
    /// Starts at (t0, y0).
    ///
    /// # Errors
    /// [`OdeError::InvalidStep`], [`OdeError::InvalidInertia`],
    /// [`OdeError::NonFiniteTime`] or [`OdeError::NonFiniteInitialState`] for a non-finite t0
    /// or y0, [`OdeError::NotUnitQuaternion`] for an attitude that is not a rotation.
    pub fn new(sys: S, t0: f64, y0: Y, cfg: FixedStepConfig) -> Result<Self, OdeError> {
        cfg.validate()?;
        check_span(t0, t0)?;
        sys.check()?;
        y0.check()?;
        Ok(Self {
            sys,
            cfg,
            t: t0,
            y: y0,
            stats: Stats::default(),
        })
    }

    /// Current time.
    pub fn t(&self) -> f64 {
        self.t
    }

    /// Current state.
    pub fn state(&self) -> &Y {
        &self.y
    }

    /// Work done so far (`rhs_evals` counts evaluations of ξ).
    pub fn stats(&self) -> Stats {
        self.stats
    }

    /// One RKMK4 step of size h from the current state, returned rather than stored so that a
    /// non-finite result leaves the state as it was; stage times capped at `t_hi` (see
    /// [`Rk4`](crate::ode::Rk4)).
    fn step(&mut self, h: f64, t_hi: f64) -> Y {
        let (t, y0) = (self.t, self.y);
        let stage = |u: &Y::Tangent, tt: f64| {
            let mut k = self.sys.xi(tt, &y0.exp_act(u));
            k.set_rot(dexpinv_right(&u.rot(), &k.rot()));
            k
        };
        let k1 = self.sys.xi(t, &y0);
        let mut u = Y::Tangent::zero();
        u.axpy(0.5 * h, &k1);
        let k2 = stage(&u, (t + 0.5 * h).min(t_hi));
        let mut u = Y::Tangent::zero();
        u.axpy(0.5 * h, &k2);
        let k3 = stage(&u, (t + 0.5 * h).min(t_hi));
        let mut u = Y::Tangent::zero();
        u.axpy(h, &k3);
        let k4 = stage(&u, (t + h).min(t_hi));
        let mut u = Y::Tangent::zero();
        u.axpy(h / 6.0, &k1);
        u.axpy(h / 3.0, &k2);
        u.axpy(h / 3.0, &k3);
        u.axpy(h / 6.0, &k4);
        self.stats.rhs_evals += 4;
        y0.exp_act(&u)
    }

    /// Advances to exactly `t_stop` in equal steps no longer than the configured h.
    ///
    /// # Errors
    /// Before any work: [`OdeError::NonFiniteTime`] for a NaN or infinite `t_stop`,
    /// [`OdeError::StopBeforeCurrent`], [`OdeError::TooManySteps`] beyond
    /// [`FixedStepConfig::max_steps`]. While stepping: [`OdeError::NonFiniteState`] at the
    /// first step whose result is not finite, naming its start time; the integrator then
    /// stays at the last finite state.
    pub fn advance_to(&mut self, t_stop: f64) -> Result<(), OdeError> {
        let Some((n, h)) = self.cfg.plan(self.t, t_stop)? else {
            return Ok(());
        };
        let t0 = self.t;
        let t_hi = t_stop.next_down();
        for i in 1..=n {
            let y_new = self.step(h, t_hi);
            // Checked every step: a blow-up stops at once instead of running out the span.
            if y_new.check().is_err() {
                return Err(OdeError::NonFiniteState { t: self.t });
            }
            self.y = y_new;
            self.stats.steps += 1;
            self.t = t0 + i as f64 * h;
        }
        self.t = t_stop;
        Ok(())
    }
}
