//! Getting through gimbal lock: two angle charts of one top and a driver that switches
//! between them.
//!
//! Euler angles are singular where `det B(q) = 0` (sin θ = 0 for ZXZ, cos pitch = 0 for ZYX):
//! the mass matrix loses rank and q̈ blows up. The ZXZ and ZYX charts are never singular at
//! the same attitude (ZXZ fails when the body z axis is vertical, ZYX when the body x axis
//! is), so [`ChartedTop`] integrates in one chart and, between steps, moves the state to the
//! other chart whenever `|det B|` falls below [`ChartConfig::switch_below`] and the other chart
//! is better conditioned. The state is mapped exactly through the attitude R and the body
//! angular velocity ω, which both charts share. The run is the one run loop
//! ([`crate::ode::Hybrid`]): the chart is its mode and the switch its step-end hook, so a
//! charted top is a [`Stepper`] (trajectories, events, ensembles) whose state carries its
//! chart.

use nalgebra::{Matrix3, Vector3};

use super::angle_chart::{AngleChart, at_angles};
use super::error::TopError;
use crate::ode::{
    Action, Dop853, HookAction, Hooks, Hybrid, HybridState, OdeError, Stats, Stepper, System,
};
use crate::rigid::{
    AngleSequence, ChartConfig, ChartError, angles_from_rotation, check_rotation, rates_from_omega,
};

/// A top integrated in whichever of two angle charts is regular, with DOP853.
///
/// # Examples
///
/// A sleeping top stands exactly vertical, where the ZXZ chart is singular: the driver starts
/// in ZYX and follows the closed form R(t) = Rz(ω3 t). The top (I1 = 1, I3 = ½ about the
/// pivot, M g l = 1) spins at ω3 = 6, above the sleeping-top threshold
/// ω3² = 4 M g l I1 / I3² = 16, so it stays up.
///
/// ```
/// use approx::assert_relative_eq;
/// use precess::prelude::*;
///
/// #[derive(RigidBody)]
/// #[rigid(
///     body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
///     pivot = [0.0, 0.0, 0.0],
/// )]
/// #[top(gravity = 1.0)]
/// struct Heavy;
///
/// let [zxz, zyx] = TopChart::both(&Heavy);
/// let (r0, w0) = (Matrix3::identity(), Vector3::new(0.0, 0.0, 6.0));
/// let mut top = ChartedTop::new([zxz, zyx], 0.0, &r0, &w0, ChartConfig::default())?;
/// assert_eq!(top.sequence(), AngleSequence::Zyx);
/// top.advance_to(5.0)?;
/// let spun = Rotation3::from_axis_angle(&Vector3::z_axis(), 30.0);
/// assert_relative_eq!(top.rotation(), *spun.matrix(), epsilon = 1e-9);
/// assert_relative_eq!(top.omega(), w0, epsilon = 1e-9);
/// # Ok::<(), precess::top::TopError>(())
/// ```
///
/// The two charts are taken by value as `[C; 2]`, the type [`super::TopChart::both`]
/// returns; borrowed charts work too (`[&a, &b]`), as [`AngleChart`] is implemented for
/// references.
pub struct ChartedTop<C: AngleChart<N>, const N: usize = 6> {
    run: Hybrid<Dop853<Charts<C>, N>>,
}

/// The two charts as one ODE system that evaluates the active one, so that the run owns
/// them and a switch only changes `active`; its hook switches charts between steps.
pub struct Charts<C> {
    charts: [C; 2],
    active: usize,
    switch_below: f64,
}

impl<C> Charts<C> {
    fn active(&self) -> &C {
        &self.charts[self.active]
    }
}

impl<C: AngleChart<N>, const N: usize> System<N> for Charts<C> {
    fn rhs(&self, t: f64, y: &[f64; N], dydt: &mut [f64; N]) {
        self.active().rhs(t, y, dydt);
    }

    fn check_parameters(&self) -> Result<(), OdeError> {
        self.active().check_all().map_err(TopError::into_ode_error)
    }

    fn explain_non_finite(&self, t: f64, y: &[f64; N]) -> Option<OdeError> {
        self.active().explain_non_finite(t, y)
    }
}

impl<C: AngleChart<N>, const N: usize> Hooks<[f64; N]> for Charts<C> {
    type Mode = AngleSequence;
    type Halt = core::convert::Infallible;

    fn mode(&self) -> AngleSequence {
        self.active().sequence()
    }

    fn set_mode(&mut self, mode: AngleSequence) {
        if let Some(k) = self.charts.iter().position(|c| c.sequence() == mode) {
            self.active = k;
        }
    }

    /// Moves to the other chart when the active one nears its singularity and the other is
    /// better conditioned; stays put otherwise (the active chart is then still regular).
    fn after_step(
        &self,
        _t: f64,
        s: &HybridState<AngleSequence, [f64; N]>,
    ) -> Result<HookAction<Self, [f64; N]>, OdeError> {
        let y = &s.x;
        let here = self.active();
        // |det B(q)| is zero exactly at the chart's singularity.
        let det_here = here.rate_matrix_at(y).determinant().abs();
        if det_here >= self.switch_below {
            return Ok(Action::Continue);
        }
        let other = &self.charts[1 - self.active];
        let r = here.rotation_at(y);
        let w = here.omega_at(y);
        // The wheels' rates are relative to the body: the same in either chart.
        let rotors = y.get(6..).unwrap_or(&[]);
        match state_in(other, &r, &w, rotors) {
            // A fresh start in the other chart, its first step size from its own f.
            Ok((state, det_other)) if det_other > det_here => Ok(Action::Switch {
                mode: other.sequence(),
                state,
                fresh: true,
            }),
            _ => Ok(Action::Continue),
        }
    }
}

impl<C: AngleChart<N>, const N: usize> ChartedTop<C, N> {
    /// Starts from an attitude `r` (body to space) and a body angular velocity `omega`, in
    /// the better-conditioned of the two charts.
    ///
    /// # Errors
    /// In [`TopError::Chart`]: [`ChartError::SameSequence`] if both models use one sequence;
    /// [`ChartError::InvalidSwitch`] for a `switch_below` that is not finite and positive
    /// ([`ChartConfig::check`]); [`ChartError::NotARotation`] if `r` is not a rotation
    /// matrix within [`crate::rigid::ROTATION_TOLERANCE`]; [`ChartError::NonFiniteOmega`]
    /// for a NaN or infinite ω; [`ChartError::Singular`] if neither chart can represent the
    /// state. The errors of [`AngleChart::check_all`] for a top that fails it (over a
    /// derived top: a body that breaks a rule of its description, a negative gravity or
    /// damping, a NaN field: [`super::TopDynamics::check_all`]); [`TopError::Ode`] for bad
    /// stepper settings or time.
    pub fn new(
        charts: [C; 2],
        t0: f64,
        r: &Matrix3<f64>,
        omega: &Vector3<f64>,
        config: ChartConfig,
    ) -> Result<Self, TopError> {
        Self::with_rotor_rates(charts, t0, r, omega, &[], config)
    }

    /// As [`ChartedTop::new`], for a top with driven rotors: `rotor_rates` are the wheels'
    /// rates Ω relative to the body (rad/s), one per driven rotor in the order of the
    /// state's slots 6, 7, …, carried through every chart switch unchanged.
    ///
    /// # Errors
    /// [`TopError::RotorRates`] unless `rotor_rates` holds `N − 6` values, all finite; then
    /// as [`ChartedTop::new`].
    pub fn with_rotor_rates(
        charts: [C; 2],
        t0: f64,
        r: &Matrix3<f64>,
        omega: &Vector3<f64>,
        rotor_rates: &[f64],
        config: ChartConfig,
    ) -> Result<Self, TopError> {
        if rotor_rates.len() + 6 != N || !rotor_rates.iter().all(|v| v.is_finite()) {
            return Err(TopError::RotorRates {
                expected: N.saturating_sub(6),
                given: rotor_rates.to_vec(),
            });
        }
        if charts[0].sequence() == charts[1].sequence() {
            return Err(ChartError::SameSequence(charts[0].sequence()).into());
        }
        config.check()?;
        for chart in &charts {
            chart.check_all()?;
        }
        check_rotation(r)?;
        if !omega.iter().all(|v| v.is_finite()) {
            return Err(ChartError::NonFiniteOmega {
                omega: [omega.x, omega.y, omega.z],
            }
            .into());
        }
        let states = [0, 1].map(|k| state_in(&charts[k], r, omega, rotor_rates));
        let det = |s: &Result<([f64; N], f64), ChartError>| match s {
            Ok((_, det)) | Err(ChartError::SingularChart { det, .. }) => *det,
            Err(_) => f64::NAN,
        };
        let dets = [det(&states[0]), det(&states[1])];
        let (active, state) = match states {
            [Ok((a, da)), Ok((_, db))] if da >= db => (0, a),
            [_, Ok((b, _))] => (1, b),
            [Ok((a, _)), Err(_)] => (0, a),
            [Err(_), Err(_)] => {
                return Err(ChartError::Singular {
                    primary: dets[0],
                    secondary: dets[1],
                }
                .into());
            }
        };
        let switch_below = config.switch_below;
        let charts = Charts {
            charts,
            active,
            switch_below,
        };
        let ode = Dop853::new(charts, t0, state, config.stepper)?;
        Ok(ChartedTop {
            run: Hybrid::new(ode)?.with_max_steps(config.stepper.max_steps),
        })
    }

    /// Integrates to `t_end`, switching charts between steps as needed. A stop at the
    /// current time does nothing.
    ///
    /// # Errors
    /// [`OdeError::NonFiniteTime`](crate::ode::OdeError::NonFiniteTime) for a NaN or infinite `t_end`,
    /// [`OdeError::StopBeforeCurrent`](crate::ode::OdeError::StopBeforeCurrent) for one before the current time, and the stepper's
    /// errors (in [`TopError::Ode`]).
    pub fn advance_to(&mut self, t_end: f64) -> Result<(), TopError> {
        Ok(self.run.advance_to(t_end)?)
    }

    /// The chart of the loop's current mode (the system's own mode follows at the next
    /// step, when a switch made at a step's end reaches the stepper).
    fn chart(&self) -> &C {
        let charts = &self.run.system().charts;
        let mode = *self.run.mode();
        charts
            .iter()
            .find(|c| c.sequence() == mode)
            .unwrap_or(&charts[0])
    }

    /// The run loop itself: its transitions are the chart switches, with the states on
    /// both sides.
    pub fn run(&self) -> &Hybrid<Dop853<Charts<C>, N>> {
        &self.run
    }

    /// Current time.
    pub fn t(&self) -> f64 {
        self.run.t()
    }

    /// The state `[q, q̇]` in the active chart (`[q, q̇, Ω]` for a driven top).
    pub fn state(&self) -> &[f64; N] {
        &self.run.state().x
    }

    /// The active chart's angle sequence.
    pub fn sequence(&self) -> AngleSequence {
        self.chart().sequence()
    }

    /// The attitude R, body to space.
    pub fn rotation(&self) -> Matrix3<f64> {
        self.chart().rotation_at(self.state())
    }

    /// The body angular velocity ω.
    pub fn omega(&self) -> Vector3<f64> {
        self.chart().omega_at(self.state())
    }

    /// The energy T + V.
    pub fn energy(&self) -> f64 {
        self.chart().energy_at(self.state())
    }

    /// The work done so far, over every chart.
    pub fn stats(&self) -> Stats {
        self.run.stats()
    }

    /// How many times the driver changed chart.
    pub fn switches(&self) -> usize {
        self.run.transitions().len()
    }
}

crate::ode::delegate_stepper!(
    [C: AngleChart<N>, const N: usize] ChartedTop<C, N>,
    run,
    HybridState<AngleSequence, [f64; N]>
);

/// The state of attitude `r` and body rate `omega` in `model`'s chart, with `|det B|` there:
/// the angles from R, the rates from B(q) q̇ = ω under the one rule of
/// [`crate::rigid::rates_from_omega`].
fn state_in<C: AngleChart<N>, const N: usize>(
    model: &C,
    r: &Matrix3<f64>,
    omega: &Vector3<f64>,
    rotor_rates: &[f64],
) -> Result<([f64; N], f64), ChartError> {
    let q = angles_from_rotation(model.sequence(), r);
    let b = model.rate_matrix_at(&at_angles(&q));
    let qd = rates_from_omega(model.sequence(), &b, &q, omega)?;
    let det = b.determinant().abs();
    let state = std::array::from_fn(|k| match k {
        0..=2 => q[k],
        3..=5 => qd[k - 3],
        _ => rotor_rates.get(k - 6).copied().unwrap_or(f64::NAN),
    });
    Ok((state, det))
}
