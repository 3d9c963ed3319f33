//! A body on a table integrated by an adaptive embedded pair: the quaternion put back on the
//! unit sphere after every accepted step, the stick–slip switches and the lift-off located as
//! events on the pair's dense output.
//!
//! Every root of the event functions inside a step is looked for, not only a sign change
//! between the step's ends (where two crossings cancel: a normal force that dips below zero
//! and comes back within one step, a brief slip): the scan of the generic runs' events
//! (Chebyshev interpolants of g along the dense output, refined until their error estimate
//! rules a root out; see [`crate::ode::Event`] and docs/trajectories.md for what it
//! guarantees) brackets each root, and the first crossing of the step is located on g itself
//! by regula falsi down to adjacent doubles, handled, and the run restarted there. A step far
//! from every event costs three states of the dense output and three values of each g.

use nalgebra::Vector3;

use super::dynamics::{ContactDynamics, LawKind, Phase, attitude_of};
use super::error::ContactError;
use super::state::{STATE_LEN, layout};
use super::system::ContactSystem;
use crate::ode::{
    Adaptive, AdaptiveConfig, Direction, Dop853Pair, EmbeddedPair, OdeError, Stats, Stepper,
    check_stop, crossing, first_pass_times, locate_root, scan_step,
};

/// How a [`ContactRun::advance_to`] ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ContactOutcome {
    /// The stop time was reached with the body on the table.
    Reached {
        /// The stop time.
        t: f64,
    },
    /// The normal force fell to zero: the body leaves the table here (the run stops; the
    /// model of a body on a table ends, and a free flight would begin).
    LiftOff {
        /// The time N reached zero.
        t: f64,
        /// The state then.
        state: [f64; STATE_LEN],
    },
}

/// A change of phase during a stick–slip run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Switch {
    /// When.
    pub t: f64,
    /// The phase before.
    pub from: Phase,
    /// The phase after.
    pub to: Phase,
    /// The state at the switch, as the phase before left it (before the slip is seeded or
    /// the velocity put on the rolling constraint).
    pub state: [f64; STATE_LEN],
}

/// The slip seeded when rolling gives way to sliding, m/s: Coulomb's friction needs a slip
/// direction, and at the switch the slip is zero; it is started along the direction opposite
/// to the friction rolling needed (which the table can no longer give), this small.
pub const SEED_SLIP: f64 = 1e-10;

/// A body on a table integrated by the pair `P` (DOP853 by default).
///
/// ```
/// use approx::assert_relative_eq;
/// use nalgebra::{UnitQuaternion, Vector3};
/// use precess_core::contact::{
///     ContactDynamics, ContactLaw, ContactModel, ContactOutcome, ContactRun, ContactScene, Phase,
///     Surface,
/// };
/// use precess_core::ode::AdaptiveConfig;
/// use precess_core::sym::Arena;
///
/// // A uniform ball rolls straight at 0.5 m/s: after 2 s it is 1 m on.
/// let mut a = Arena::new();
/// let (m, rho, g, i) = (a.parameter("m"), a.parameter("rho"), a.parameter("g"), a.parameter("I"));
/// let z = a.zero();
/// let scene = ContactScene {
///     mass: m,
///     center: [z; 3],
///     inertia: [[i, z, z], [z, i, z], [z, z, i]],
///     surface: Surface::Sphere { center: [z; 3], radius: rho },
///     law: ContactLaw::Rolling { rolling_resistance: None, spin_resistance: None },
///     gravity: g,
/// };
/// let d = scene.derive(&mut a)?;
/// let ball = ContactModel::new(&mut a, &d, &[("m", 1.0), ("rho", 0.1), ("g", 9.81), ("I", 0.004)])?;
/// let y0 = ball.rolling_state([0.0, 0.0], &UnitQuaternion::identity(), &Vector3::new(0.0, 5.0, 0.0));
/// let mut run = ContactRun::new(&ball, Phase::Rolling, 0.0, y0, AdaptiveConfig::with_tol(1e-12, 1e-12))?;
/// assert_eq!(run.advance_to(2.0)?, ContactOutcome::Reached { t: 2.0 });
/// assert_relative_eq!(run.y()[0], 1.0, max_relative = 1e-12);
/// # Ok::<(), precess_core::contact::ContactError>(())
/// ```
#[derive(Debug)]
pub struct ContactRun<'a, D: ?Sized, P = Dop853Pair> {
    ode: Adaptive<ContactSystem<'a, D>, P, STATE_LEN>,
    cfg: AdaptiveConfig,
    switches: Vec<Switch>,
    lifted: Option<(f64, [f64; STATE_LEN])>,
    event_evals: u64,
    /// The scan's points of the last step, kept so that a step allocates nothing.
    points: Vec<(f64, f64)>,
}

impl<'a, D: ContactDynamics + ?Sized> ContactRun<'a, D, Dop853Pair> {
    /// Starts `body` in `phase` at `y0`, time `t0`, with DOP853.
    ///
    /// # Errors
    /// As [`ContactDynamics::check_parameters`] and [`ContactDynamics::check_state`];
    /// [`ContactError::Ode`] for a bad configuration or a right-hand side not finite at the
    /// start.
    pub fn new(
        body: &'a D,
        phase: Phase,
        t0: f64,
        y0: [f64; STATE_LEN],
        cfg: AdaptiveConfig,
    ) -> Result<Self, ContactError> {
        Self::with_pair(body, phase, t0, y0, cfg)
    }
}

impl<'a, D: ContactDynamics + ?Sized, P: EmbeddedPair> ContactRun<'a, D, P> {
    /// Starts as [`ContactRun::new`] with the pair `P`
    /// (`ContactRun::<_, Dopri5Pair>::with_pair(..)`).
    ///
    /// # Errors
    /// As [`ContactRun::new`].
    pub fn with_pair(
        body: &'a D,
        phase: Phase,
        t0: f64,
        y0: [f64; STATE_LEN],
        cfg: AdaptiveConfig,
    ) -> Result<Self, ContactError> {
        body.check_parameters()?;
        body.check_state(phase, &y0)?;
        let (mut y0, mut phase, mut switches) = (y0, phase, Vec::new());
        // A stick–slip body started rolling where rolling needs more friction than μ N
        // slides from the start.
        if body.law() == LawKind::StickSlip && phase == Phase::Rolling {
            let mu = body.friction_coefficient().unwrap_or(0.0);
            let r = body.reaction(Phase::Rolling, &y0);
            if r.friction.norm() > mu * r.normal {
                switches.push(Switch {
                    t: t0,
                    from: Phase::Rolling,
                    to: Phase::Sliding,
                    state: y0,
                });
                seed_slip(body, &mut y0);
                phase = Phase::Sliding;
            }
        }
        let sys = ContactSystem { body, phase };
        Ok(ContactRun {
            ode: Adaptive::new(sys, t0, y0, cfg)?,
            cfg,
            switches,
            lifted: None,
            event_evals: 0,
            points: Vec::new(),
        })
    }

    /// Current time.
    pub fn t(&self) -> f64 {
        self.ode.t()
    }

    /// The current state array.
    pub fn y(&self) -> &[f64; STATE_LEN] {
        self.ode.y()
    }

    /// The current phase.
    pub fn phase(&self) -> Phase {
        self.ode.system().phase
    }

    /// The phase switches so far.
    pub fn switches(&self) -> &[Switch] {
        &self.switches
    }

    /// Work done so far.
    pub fn stats(&self) -> Stats {
        self.ode.stats()
    }

    /// Evaluations of the event functions so far (N, μN − |F_t|, the slip along its
    /// direction at the step's start), each on one state: the cost of looking for events.
    pub fn event_evaluations(&self) -> u64 {
        self.event_evals
    }

    fn body(&self) -> &'a D {
        self.ode.system().body
    }

    /// Steps until `t == t_stop`, or until the body lifts off.
    ///
    /// # Errors
    /// [`ContactError::Ode`] as [`Adaptive::step`] (a non-finite or past `t_stop`, a step
    /// size underflow, a non-finite state, more than `max_steps` attempts in this call), and
    /// [`OdeError::NonFiniteEvent`] for an event function that is not finite inside a step
    /// (index 0 the normal force, 1 the friction cone, 2 the slip).
    pub fn advance_to(&mut self, t_stop: f64) -> Result<ContactOutcome, ContactError> {
        if let Some((t, state)) = self.lifted {
            return Ok(ContactOutcome::LiftOff { t, state });
        }
        check_stop(self.t(), t_stop)?;
        let body = self.body();
        // A state that already presses on the table with N < 0 leaves it at once.
        let y = *self.y();
        if body.reaction(self.phase(), &y).normal < 0.0 {
            self.lifted = Some((self.t(), y));
            return Ok(ContactOutcome::LiftOff {
                t: self.t(),
                state: y,
            });
        }
        let start = self.stats();
        while self.t() < t_stop {
            let total = self.stats();
            let attempts = (total.steps + total.rejections) - (start.steps + start.rejections);
            if attempts >= self.cfg.max_steps {
                return Err(OdeError::MaxStepsExceeded {
                    t: self.t(),
                    max_steps: self.cfg.max_steps,
                }
                .into());
            }
            let phase = self.phase();
            let before = *self.y();
            let reference = slip(body, &before);
            self.ode.step(t_stop)?;
            let events = Events {
                body,
                phase,
                stick_slip: body.law() == LawKind::StickSlip,
                mu: body.friction_coefficient().unwrap_or(0.0),
                reference,
            };
            let first = self.first_event(&events, &before)?;
            match first {
                None => self.project()?,
                Some((t, kind)) => {
                    let mut y = self.ode.dense_at(t)?;
                    normalise(&mut y);
                    match kind {
                        Kind::LiftOff => {
                            Stepper::restart(&mut self.ode, t, y)?;
                            self.lifted = Some((t, y));
                            return Ok(ContactOutcome::LiftOff { t, state: y });
                        }
                        Kind::Slips => {
                            let at = y;
                            seed_slip(body, &mut y);
                            self.switch_to(t, at, y, Phase::Sliding)?;
                        }
                        Kind::Sticks => {
                            // The slip has stopped: put the velocity on the rolling
                            // constraint (its residual is the slip's sideways part).
                            let at = y;
                            let u = body.contact(&y).velocity;
                            y[layout::VELOCITY] -= u.x;
                            y[layout::VELOCITY + 1] -= u.y;
                            let r = body.reaction(Phase::Rolling, &y);
                            if r.friction.norm() <= events.mu * r.normal {
                                self.switch_to(t, at, y, Phase::Rolling)?;
                            } else {
                                // Rolling would need more than μ N: the slip starts again
                                // against the friction rolling needs (Coulomb's law has no
                                // direction at zero slip, so it is seeded as at a switch).
                                seed_slip(body, &mut y);
                                Stepper::restart(&mut self.ode, t, y)?;
                            }
                        }
                    }
                }
            }
        }
        Ok(ContactOutcome::Reached { t: self.t() })
    }

    /// Switches to `to` at `t`, recording the state `at` the phase before left and going on
    /// from `y`.
    fn switch_to(
        &mut self,
        t: f64,
        at: [f64; STATE_LEN],
        y: [f64; STATE_LEN],
        to: Phase,
    ) -> Result<(), ContactError> {
        let from = self.phase();
        self.ode.modify_system(|s| s.phase = to);
        Stepper::restart(&mut self.ode, t, y)?;
        self.switches.push(Switch {
            t,
            from,
            to,
            state: at,
        });
        Ok(())
    }

    /// The first event of the last step, with its time: for each event that applies, every
    /// root of its g inside the step is bracketed by the ode module's scan (a Chebyshev
    /// interpolant of g along the dense output, refined until its error estimate says no
    /// root hides between its points), and the first falling crossing (g > 0, then g ≤ 0) is
    /// located on g itself by regula falsi down to adjacent doubles.
    ///
    /// # Errors
    /// [`OdeError::NonFiniteEvent`] for a g that is not finite (index 0 lift-off, 1 the
    /// cone, 2 the slip); what the dense output returns.
    fn first_event(
        &mut self,
        events: &Events<'_, D>,
        before: &[f64; STATE_LEN],
    ) -> Result<Option<(f64, Kind)>, ContactError> {
        let (t_a, t_b) = (self.ode.last_step_start(), self.ode.t());
        let after = *self.ode.y();
        // The first pass's three inner states, shared by every event (lift-off always
        // applies): the only dense output a step without events near costs.
        let times = first_pass_times(t_a, t_b);
        let states = [
            self.ode.dense_at(times[0])?,
            self.ode.dense_at(times[1])?,
            self.ode.dense_at(times[2])?,
        ];
        let mut first: Option<(f64, Kind)> = None;
        for kind in [Kind::LiftOff, Kind::Slips, Kind::Sticks] {
            if !events.applies(kind) {
                continue;
            }
            let ode = &mut self.ode;
            let count = &mut self.event_evals;
            let points = &mut self.points;
            let mut g = |t: f64, y: &[f64; STATE_LEN]| {
                *count += 1;
                events.checked(kind, t, y)
            };
            let g_a = g(t_a, before)?;
            let g_b = g(t_b, &after)?;
            let inner = [
                g(times[0], &states[0])?,
                g(times[1], &states[1])?,
                g(times[2], &states[2])?,
            ];
            let mut at = |t: f64| {
                let y = ode.dense_at(t)?;
                g(t, &y)
            };
            points.clear();
            points.push((t_a, g_a));
            scan_step(&mut at, (t_a, g_a), (t_b, g_b), inner, points)?;
            let bracket = points
                .windows(2)
                .find(|w| crossing(Direction::Falling, w[0].1, w[1].1).is_some());
            if let Some(w) = bracket {
                let t = locate_root(&mut at, w[0], w[1])?;
                if first.is_none_or(|(t0, _)| t < t0) {
                    first = Some((t, kind));
                }
            }
        }
        Ok(first)
    }

    /// Puts q back on the unit sphere and continues from there.
    fn project(&mut self) -> Result<(), ContactError> {
        let mut y = *self.ode.y();
        normalise(&mut y);
        if y == *self.ode.y() {
            return Ok(());
        }
        let t = self.ode.t();
        Stepper::restart(&mut self.ode, t, y)?;
        Ok(())
    }
}

/// The events of a run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    /// N falls to zero (index 0 in [`OdeError::NonFiniteEvent`]).
    LiftOff = 0,
    /// Rolling needs more friction than μ N (index 1).
    Slips = 1,
    /// The slip velocity turns against its direction at the step's start (index 2).
    Sticks = 2,
}

struct Events<'b, D: ?Sized> {
    body: &'b D,
    phase: Phase,
    stick_slip: bool,
    mu: f64,
    reference: Vector3<f64>,
}

impl<D: ContactDynamics + ?Sized> Events<'_, D> {
    fn applies(&self, kind: Kind) -> bool {
        match kind {
            Kind::LiftOff => true,
            Kind::Slips => self.stick_slip && self.phase == Phase::Rolling,
            Kind::Sticks => self.stick_slip && self.phase == Phase::Sliding,
        }
    }

    /// The event function at time `t`, refused when not finite.
    fn checked(&self, kind: Kind, t: f64, y: &[f64; STATE_LEN]) -> Result<f64, OdeError> {
        let value = self.g(kind, y);
        if value.is_finite() {
            Ok(value)
        } else {
            Err(OdeError::NonFiniteEvent {
                index: kind as usize,
                t,
                value,
            })
        }
    }

    /// The event function, positive while nothing happens.
    fn g(&self, kind: Kind, y: &[f64; STATE_LEN]) -> f64 {
        match kind {
            Kind::LiftOff => self.body.reaction(self.phase, y).normal,
            Kind::Slips => {
                let r = self.body.reaction(Phase::Rolling, y);
                self.mu * r.normal - r.friction.norm()
            }
            Kind::Sticks => slip(self.body, y).dot(&self.reference),
        }
    }
}

/// The slip velocity of the contact point at `y`.
fn slip<D: ContactDynamics + ?Sized>(body: &D, y: &[f64; STATE_LEN]) -> Vector3<f64> {
    body.contact(y).velocity
}

/// Starts a slip of [`SEED_SLIP`] against the friction rolling needs at `y`.
fn seed_slip<D: ContactDynamics + ?Sized>(body: &D, y: &mut [f64; STATE_LEN]) {
    let f = body.reaction(Phase::Rolling, y).friction;
    let dir = -f / f.norm().max(f64::MIN_POSITIVE);
    y[layout::VELOCITY] += SEED_SLIP * dir.x;
    y[layout::VELOCITY + 1] += SEED_SLIP * dir.y;
}

/// The state's quaternion put on the unit sphere.
fn normalise(y: &mut [f64; STATE_LEN]) {
    let q = attitude_of(y);
    let at = layout::QUATERNION;
    y[at..at + 4].copy_from_slice(&[q.w, q.i, q.j, q.k]);
}
