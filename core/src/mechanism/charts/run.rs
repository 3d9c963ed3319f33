//! [`ChartedMechanism`]: DOP853 over a mechanism in one chart set, moving each spherical
//! joint to its partner chart between steps when its `|det B_j|` falls below the threshold:
//! the one run loop ([`crate::ode::Hybrid`]) with the chart set as its mode and the switch
//! as its step-end hook.

use nalgebra::{Matrix3, Vector3};

use super::{ChartSet, ChartedDynamics, MAX_SPHERICAL_JOINTS, SphericalJoint};
use crate::mechanism::MechanismError;
use crate::ode::{
    Action, Dop853, HookAction, Hooks, Hybrid, HybridState, OdeError, Stats, Stepper, System,
};
use crate::rigid::charts::state_in_chart;
use crate::rigid::{
    AngleSequence, ChartConfig, ChartError, check_chart, check_rotation, joint_rate_matrix,
    joint_rotation, map_to_partner,
};

/// A mechanism integrated with DOP853 in whichever chart of each spherical joint is regular.
///
/// Between steps, every switchable spherical joint j whose `|det B_j|` is below
/// [`ChartConfig::switch_below`] moves to its partner sequence when that is better
/// conditioned and the resulting chart set is available ([`super::chart_variants`]): its
/// three angles and rates are mapped exactly through the joint's attitude J_j and relative
/// angular velocity ω_j ([`map_to_partner`]), the other coordinates are untouched, and the
/// stepper restarts from the mapped state. The mechanism's physical state is the same in
/// every chart, so energy and the bodies' motion carry straight through a switch.
///
/// # Examples
///
/// A pendulum on a ball joint (unit mass a unit length down, I = 1/10 about its centre,
/// g = 1) released from a 0.8 rad swing in the y–z plane passes straight below the joint,
/// ZXZ's lock, where the driver moves it to ZYX; its energy stays −cos 0.8:
///
/// ```
/// use approx::assert_relative_eq;
/// use precess_core::mechanism::charts::{ChartSet, ChartedMechanism, MechanismCharts};
/// use precess_core::mechanism::{JointKind, MechanismScene, Parent, Route};
/// use precess_core::rigid::AngleSequence;
/// use precess_core::sym::Arena;
/// use precess_core::rigid::ChartConfig;
/// let mut a = Arena::new();
/// let (o, z) = (a.one(), a.zero());
/// let tenth = { let ten = a.integer(10); a.recip(ten).unwrap() };
/// let ball = JointKind::Spherical { sequence: AngleSequence::Zxz };
/// let mut bob = MechanismScene::body(&mut a, "bob", Parent::Ground, ball, &["phi", "theta", "psi"]);
/// bob.mass = o;
/// bob.center = [z, z, a.integer(-1)];
/// bob.inertia = [[tenth, z, z], [z, tenth, z], [z, z, tenth]];
/// let mut scene = MechanismScene::new();
/// scene.bodies.push(bob);
/// scene.gravity = Some([z, z, a.integer(-1)]);
/// let charts = MechanismCharts::new(&mut a, &scene, Route::Auto, &[])?;
/// let y0 = [0.0, 0.8, 0.0, 0.0, 0.0, 0.0]; // Rz(0) Rx(0.8) Rz(0), at rest
/// let mut swing = ChartedMechanism::new(&charts, 0.0, y0, ChartSet::DECLARED, ChartConfig::default())?;
/// swing.advance_to(2.0)?;
/// assert_eq!((swing.switches(), swing.charts()), (1, ChartSet(1)));
/// assert_relative_eq!(swing.energy(), -0.8f64.cos(), max_relative = 1e-9);
/// # Ok::<(), precess_core::mechanism::MechanismError>(())
/// ```
///
/// `docs/mechanisms.md` starts a sleeping top standing exactly upright, where its declared
/// ZXZ chart cannot even start, with [`ChartedMechanism::from_attitudes`].
pub struct ChartedMechanism<D: ChartedDynamics<S>, const S: usize> {
    run: Hybrid<Dop853<InCharts<D>, S>>,
}

/// The dynamics and the current chart set as one ODE system, so that a switch only changes
/// `charts`; its hook moves joints near their lock to their partner charts.
pub struct InCharts<D> {
    dynamics: D,
    charts: ChartSet,
    joints: Vec<SphericalJoint>,
    switch_below: f64,
}

impl<D: ChartedDynamics<S>, const S: usize> System<S> for InCharts<D> {
    fn rhs(&self, t: f64, y: &[f64; S], dydt: &mut [f64; S]) {
        self.dynamics.rhs_in(self.charts, t, y, dydt);
    }

    fn check_parameters(&self) -> Result<(), OdeError> {
        self.dynamics
            .check_parameters()
            .map_err(MechanismError::into_ode_error)
    }
}

impl<D: ChartedDynamics<S>, const S: usize> Hooks<[f64; S]> for InCharts<D> {
    type Mode = ChartSet;
    type Halt = core::convert::Infallible;

    fn mode(&self) -> ChartSet {
        self.charts
    }

    fn set_mode(&mut self, mode: ChartSet) {
        self.charts = mode;
    }

    /// Moves each joint near its chart's lock to its partner chart when that is better
    /// conditioned and available; one fresh start if any moved.
    fn after_step(
        &self,
        _t: f64,
        s: &HybridState<ChartSet, [f64; S]>,
    ) -> Result<HookAction<Self, [f64; S]>, OdeError> {
        let n = S / 2;
        let mut y = s.x;
        let mut charts = s.mode;
        for (j, joint) in self.joints.iter().enumerate() {
            if !joint.switchable {
                continue;
            }
            let (Some(q), Some(qd)) = (triple(&y, joint.first), triple(&y, joint.first + n)) else {
                continue;
            };
            let here = charts.sequence(j, joint.declared);
            let det_here = joint_rate_matrix(here, &q).determinant().abs();
            if det_here >= self.switch_below || !self.dynamics.has_charts(charts.toggled(j)) {
                continue;
            }
            let Ok((p, pd, det_other)) = map_to_partner(here, &q, &qd) else {
                continue;
            };
            if det_other <= det_here {
                continue;
            }
            put(&mut y, joint.first, &p);
            put(&mut y, joint.first + n, &pd);
            charts = charts.toggled(j);
        }
        Ok(if charts == s.mode {
            Action::Continue
        } else {
            // A fresh start in the new chart set, its first step size from its own f.
            Action::Switch {
                mode: charts,
                state: y,
                fresh: true,
            }
        })
    }
}

/// A joint's three angles or rates from the state (`offset` 0 for q, n for q̇).
fn triple<const S: usize>(y: &[f64; S], at: usize) -> Option<[f64; 3]> {
    y.get(at..at + 3)?.try_into().ok()
}

fn put<const S: usize>(y: &mut [f64; S], at: usize, v: &[f64; 3]) {
    if let Some(slot) = y.get_mut(at..at + 3) {
        slot.copy_from_slice(v);
    }
}

impl<D: ChartedDynamics<S>, const S: usize> ChartedMechanism<D, S> {
    /// Starts from the state `y0 = [q, q̇]` given in the chart set `charts`.
    ///
    /// # Errors
    /// [`MechanismError::Chart`] ([`ChartError::InvalidSwitch`]) for a `switch_below` that is
    /// not finite and positive; [`MechanismError::OdeStateLength`] if S ≠ 2n;
    /// [`MechanismError::TooManyJoints`]; [`MechanismError::UnavailableCharts`] for
    /// a chart set the mechanism does not provide; [`MechanismError::NonFinite`] for a
    /// NaN or infinite state; [`MechanismError::Joint`] for a spherical joint at its
    /// chart's gimbal lock (start it with [`ChartedMechanism::from_attitudes`]); the
    /// stepper's errors.
    pub fn new(
        dynamics: D,
        t0: f64,
        y0: [f64; S],
        charts: ChartSet,
        config: ChartConfig,
    ) -> Result<Self, MechanismError> {
        let joints = check_setup(&dynamics, &config)?;
        if !dynamics.has_charts(charts) {
            return Err(MechanismError::UnavailableCharts { charts: charts.0 });
        }
        if !y0.iter().all(|v| v.is_finite()) {
            return Err(MechanismError::NonFinite {
                quantity: "state",
                values: y0.to_vec(),
            });
        }
        for (j, joint) in joints.iter().enumerate() {
            let q = triple(&y0, joint.first).unwrap_or_default();
            let sequence = charts.sequence(j, joint.declared);
            check_chart(sequence, &joint_rate_matrix(sequence, &q), &q).map_err(|source| {
                MechanismError::Joint {
                    joint: joint.name.clone(),
                    source,
                }
            })?;
        }
        let switch_below = config.switch_below;
        let system = InCharts {
            dynamics,
            charts,
            joints,
            switch_below,
        };
        let ode = Dop853::new(system, t0, y0, config.stepper)?;
        Ok(ChartedMechanism {
            run: Hybrid::new(ode)?.with_max_steps(config.stepper.max_steps),
        })
    }

    /// Starts with each spherical joint j at the relative attitude `attitudes[j].0` (child
    /// axes to parent axes) turning at the relative angular velocity `attitudes[j].1` (child
    /// axes), in the better conditioned of its charts; the other coordinates and rates are
    /// taken from `y0` (whose spherical joints' slots are ignored).
    ///
    /// # Errors
    /// As [`ChartedMechanism::new`]; [`MechanismError::AttitudeCount`] unless there is
    /// one attitude per spherical joint; [`MechanismError::Attitude`] for a matrix that
    /// is not a rotation within [`crate::rigid::ROTATION_TOLERANCE`] or a non-finite ω.
    pub fn from_attitudes(
        dynamics: D,
        t0: f64,
        y0: [f64; S],
        attitudes: &[(Matrix3<f64>, Vector3<f64>)],
        config: ChartConfig,
    ) -> Result<Self, MechanismError> {
        let joints = check_setup(&dynamics, &config)?;
        if attitudes.len() != joints.len() {
            return Err(MechanismError::AttitudeCount {
                expected: joints.len(),
                got: attitudes.len(),
            });
        }
        let n = S / 2;
        // Each joint's state and |det B| in its declared and its partner chart.
        let mut placed = Vec::with_capacity(joints.len());
        for (joint, (r, w)) in joints.iter().zip(attitudes) {
            let attitude = |source| MechanismError::Attitude {
                joint: joint.name.clone(),
                source,
            };
            check_rotation(r).map_err(attitude)?;
            if !w.iter().all(|v| v.is_finite()) {
                return Err(attitude(ChartError::NonFiniteOmega {
                    omega: [w.x, w.y, w.z],
                }));
            }
            let declared = state_in_chart(joint.declared, r, w);
            let partner = state_in_chart(joint.declared.other(), r, w);
            placed.push((declared, partner));
        }
        let det = |s: &Result<([f64; 3], [f64; 3], f64), _>| s.as_ref().map_or(0.0, |s| s.2);
        // The worst-conditioned joints choose first, so that under the k + 1 rule the
        // one switch available goes where it is needed most.
        let mut by_need: Vec<usize> = (0..joints.len()).collect();
        by_need.sort_by(|&a, &b| det(&placed[a].0).total_cmp(&det(&placed[b].0)));
        let mut charts = ChartSet::DECLARED;
        for &j in &by_need {
            let (declared, partner) = &placed[j];
            let better = det(partner) > det(declared);
            if joints[j].switchable && better && dynamics.has_charts(charts.toggled(j)) {
                charts = charts.toggled(j);
            }
        }
        let mut y = y0;
        for (j, joint) in joints.iter().enumerate() {
            let (declared, partner) = &placed[j];
            let chosen = if charts.is_switched(j) {
                partner
            } else {
                declared
            };
            let (q, qd, _) = chosen.clone().map_err(|source| MechanismError::Joint {
                joint: joint.name.clone(),
                source,
            })?;
            put(&mut y, joint.first, &q);
            put(&mut y, joint.first + n, &qd);
        }
        Self::new(dynamics, t0, y, charts, config)
    }

    /// Integrates to `t_end`, switching charts between steps as needed. A stop at the
    /// current time does nothing.
    ///
    /// # Errors
    /// [`OdeError::NonFiniteTime`](crate::ode::OdeError::NonFiniteTime) for a NaN or infinite `t_end`,
    /// [`OdeError::StopBeforeCurrent`](crate::ode::OdeError::StopBeforeCurrent) for one before the current time, and the stepper's
    /// errors (a joint that reaches gimbal lock with no chart to switch to makes the
    /// step fail).
    pub fn advance_to(&mut self, t_end: f64) -> Result<(), MechanismError> {
        Ok(self.run.advance_to(t_end)?)
    }

    fn system(&self) -> &InCharts<D> {
        self.run.system()
    }

    fn y(&self) -> &[f64; S] {
        &self.run.state().x
    }

    /// The run loop itself: its transitions are the chart switches, with the states on
    /// both sides.
    pub fn run(&self) -> &Hybrid<Dop853<InCharts<D>, S>> {
        &self.run
    }

    /// Current time.
    pub fn t(&self) -> f64 {
        self.run.t()
    }

    /// The state `[q, q̇]` in the current chart set.
    pub fn state(&self) -> &[f64; S] {
        self.y()
    }

    /// The current chart set (the loop's mode: the system's own follows at the next step).
    pub fn charts(&self) -> ChartSet {
        *self.run.mode()
    }

    /// The spherical joints, in the order of the chart set's bits.
    pub fn joints(&self) -> &[SphericalJoint] {
        &self.system().joints
    }

    /// The sequence spherical joint `j` is integrated in now (`None` past the last joint).
    pub fn sequence(&self, j: usize) -> Option<AngleSequence> {
        let joint = self.joints().get(j)?;
        Some(self.charts().sequence(j, joint.declared))
    }

    /// The relative attitude J_j of spherical joint `j` (its child's axes to its parent's).
    pub fn joint_rotation(&self, j: usize) -> Option<Matrix3<f64>> {
        let q = triple(self.y(), self.joints().get(j)?.first)?;
        Some(joint_rotation(self.sequence(j)?, &q))
    }

    /// The relative angular velocity ω_j of spherical joint `j`, in its child's axes.
    pub fn joint_omega(&self, j: usize) -> Option<Vector3<f64>> {
        let first = self.joints().get(j)?.first;
        let q = triple(self.y(), first)?;
        let qd = triple(self.y(), first + S / 2)?;
        Some(joint_rate_matrix(self.sequence(j)?, &q) * Vector3::from(qd))
    }

    /// The energy T + V.
    pub fn energy(&self) -> f64 {
        self.dynamics().energy_in(self.charts(), self.t(), self.y())
    }

    /// The dynamics being integrated.
    pub fn dynamics(&self) -> &D {
        &self.system().dynamics
    }

    /// The work done so far, over every chart set.
    pub fn stats(&self) -> Stats {
        self.run.stats()
    }

    /// How many joint switches the driver made (a switch of two joints at one step counts
    /// two).
    pub fn switches(&self) -> usize {
        let toggled = |tr: &crate::ode::Transition<ChartSet, [f64; S]>| {
            (tr.before.mode.0 ^ tr.after.mode.0).count_ones() as usize
        };
        self.run.transitions().iter().map(toggled).sum()
    }
}

crate::ode::delegate_stepper!(
    [D: ChartedDynamics<S>, const S: usize] ChartedMechanism<D, S>,
    run,
    HybridState<ChartSet, [f64; S]>
);

/// Checks the configuration and the dynamics' shape; returns the spherical joints.
fn check_setup<D: ChartedDynamics<S>, const S: usize>(
    dynamics: &D,
    config: &ChartConfig,
) -> Result<Vec<SphericalJoint>, MechanismError> {
    config.check()?;
    let expected = 2 * dynamics.dof();
    if S != expected {
        return Err(MechanismError::OdeStateLength { expected, got: S });
    }
    let joints = dynamics.spherical_joints();
    if joints.len() > MAX_SPHERICAL_JOINTS {
        return Err(MechanismError::TooManyJoints {
            count: joints.len(),
            max: MAX_SPHERICAL_JOINTS,
        });
    }
    Ok(joints)
}
