//! The one run loop of every scene: a [`Hybrid`] stepper wraps any [`Switchable`] stepper and,
//! after each accepted step and at each located witness root, lets the scene's [`Hooks`]
//! project the state, switch its mode (a chart, a contact's phase) or halt the run with a
//! typed outcome.
//!
//! The model is Drake's `Simulator` with witness functions. A scene declares
//! - **witnesses**: continuous functions w(t, x) of the state, positive while the mode holds,
//!   whose fall through zero is an event (a normal force reaching zero, the friction rolling
//!   needs leaving the cone, a slip stopping, a disk lying down). They are scanned on the
//!   wrapped stepper's own solution inside each step, projected as the scene projects its
//!   states (the state it acts on at a root), with the scan of every run's events
//!   (every root inside the step, not only a change of sign between its ends), and the first
//!   root is located to adjacent doubles; the step is cut there;
//! - **guards** ([`Hooks::after_step`]): what can jump (a normal force when the slip
//!   reverses) is checked at the step's end, never bisected;
//! - a **projection** ([`Hooks::project`]): the state put back on its manifold (a unit
//!   quaternion) after every accepted step.
//!
//! The loop is itself a [`Stepper`] over [`HybridState`] (the mode beside the continuous
//! state), so [`Run`](super::Run), trajectories, sampling, observers, user events,
//! ensembles and plots reach every scene.
//!
//! What is guaranteed: the state the loop returns (after a step, at a switch, at a halt) is
//! one where every witness of its mode is ≥ 0 — a witness's root is reported at the left end
//! of its final bracket, the last double at which the mode still held. A mode is entered only
//! after its witnesses are checked at the entry state: one below 0 there fires at once, and
//! one at exactly 0 fires at the start of the next step if it falls from there, so a mode
//! never runs outside its domain (a body set rolling exactly at the friction limit, with the
//! needed friction rising, slips at once; a ball bounced off the floor at height 0 flies on).
//! More than [`MAX_SWITCHES_AT_ONCE`] switches at one instant is an [`OdeError::Zeno`] error.

mod hooks;

pub use hooks::{Action, Cause, HookAction, Hooks, HybridState, Mode, Switchable, Transition};

use super::error::{OdeError, check_stop};
use super::events::locate_bracket;
use super::scan::{first_pass_times, scan_step};
use super::stepper::Stepper;
use super::system::Stats;

/// The most switches the loop takes at one instant before it calls the run Zeno.
pub const MAX_SWITCHES_AT_ONCE: usize = 16;

/// Whether a witness falls between two of its values in time order: from ≥ 0 to below 0,
/// or from above 0 to 0. A witness at exactly 0 where a step starts (a ball bounced off the
/// floor, a body set exactly at its friction limit) fires there if it goes on below 0, and
/// not if it rises.
fn falls(before: f64, after: f64) -> bool {
    (before >= 0.0 && after < 0.0) || (before > 0.0 && after <= 0.0)
}

/// The state type of the loop over the stepper `S`.
type StateOf<S> = HybridState<ModeOf<S>, <S as Stepper>::State>;
/// The mode type of the scene integrated by `S`.
type ModeOf<S> = <<S as Switchable>::System as Hooks<<S as Stepper>::State>>::Mode;
/// The halt type of the scene integrated by `S`.
type HaltOf<S> = <<S as Switchable>::System as Hooks<<S as Stepper>::State>>::Halt;

/// The one run loop: the stepper `S`, whose system is a scene's [`Hooks`], driven step by
/// step: witnesses located on its solution, a projection, switches and typed halts (the
/// loop is described in docs/trajectories.md, "Scenes in the run loop").
///
/// # Examples
///
/// A ball bouncing on a floor with restitution ½: the witness is its height; at each root
/// the hook reverses and halves the velocity, and halts once the bounce is below 1 mm/s.
/// The k-th flight lasts 2⁻ᵏ of the first, so the bounces come at t₁(1 + 1 + ½ + …).
///
/// ```
/// use approx::assert_relative_eq;
/// use precess_core::ode::{
///     Action, AdaptiveConfig, Dop853, Hooks, Hybrid, HybridState, OdeError, Run, StopReason,
///     System,
/// };
/// struct Ball;
/// impl System<2> for Ball {
///     fn rhs(&self, _t: f64, y: &[f64; 2], d: &mut [f64; 2]) {
///         *d = [y[1], -9.81]
///     }
/// }
/// impl Hooks<[f64; 2]> for Ball {
///     type Mode = ();
///     type Halt = f64;
///     fn mode(&self) {}
///     fn set_mode(&mut self, _: ()) {}
///     fn witness_names(&self) -> &[&'static str] {
///         &["height"]
///     }
///     fn witness(&self, _: &(), _: usize, _t: f64, y: &[f64; 2]) -> f64 {
///         y[0]
///     }
///     fn on_witness(
///         &self,
///         _: usize,
///         t: f64,
///         s: &HybridState<(), [f64; 2]>,
///         _w: f64,
///     ) -> Result<Action<(), [f64; 2], f64>, OdeError> {
///         let up = -0.5 * s.x[1];
///         Ok(if up < 1e-3 {
///             Action::Halt(t)
///         } else {
///             Action::Switch { mode: (), state: [0.0, up], fresh: false }
///         })
///     }
/// }
/// let ode = Dop853::new(Ball, 0.0, [1.0, 0.0], AdaptiveConfig::with_tol(1e-12, 1e-12))?;
/// let mut ball = Hybrid::new(ode)?;
/// let out = Run::new(&mut ball, 10.0).sample_none().integrate()?;
/// assert_eq!(out.stop, StopReason::Halted);
/// let t1 = (2.0 / 9.81f64).sqrt();
/// let bounces: Vec<f64> = ball.transitions().iter().map(|s| s.t).collect();
/// assert_relative_eq!(bounces[0], t1, max_relative = 1e-12);
/// assert_relative_eq!(bounces[1], 2.0 * t1, max_relative = 1e-12);
/// assert_relative_eq!(bounces[2], 2.5 * t1, max_relative = 1e-12);
/// // Never below the floor: every state the loop returned has a height ≥ 0.
/// assert!(ball.transitions().iter().all(|s| s.before.x[0] >= 0.0));
/// # Ok::<(), OdeError>(())
/// ```
#[derive(Debug, Clone)]
pub struct Hybrid<S>
where
    S: Switchable,
    S::System: Hooks<S::State>,
{
    inner: S,
    /// The loop's own step, which a witness's root may cut short of the inner one.
    t_start: f64,
    t: f64,
    state: StateOf<S>,
    /// The inner stepper must be put at `(t, state)` before its next step (`Some(fresh)`):
    /// the loop's step ended before the inner one's, or the state was projected or switched.
    resync: Option<bool>,
    transitions: Vec<Transition<ModeOf<S>, S::State>>,
    halt: Option<HaltOf<S>>,
    budget: Budget,
    witness_evals: u64,
    /// Witnesses not watched until they have been ≤ 0 at a step's end: one whose root the
    /// scene went on past ([`Action::Continue`]), so that it does not fire again at once.
    disarmed: Vec<bool>,
    /// The scan's points of the last step, kept so that a step allocates nothing.
    points: Vec<(f64, f64)>,
    /// Witness roots in a row at the start of their step (no time passing).
    instant_roots: usize,
}

/// The step budget: attempts (accepted and rejected steps, over every restart of the wrapped
/// stepper) towards one stop time.
#[derive(Debug, Clone, Copy)]
struct Budget {
    max_steps: u64,
    target: f64,
    start: u64,
}

impl<S> Hybrid<S>
where
    S: Switchable,
    S::System: Hooks<S::State>,
{
    /// The default budget of step attempts towards one stop time: the adaptive pairs'.
    pub const DEFAULT_MAX_STEPS: u64 = 100_000;

    /// Wraps `inner`, positioned at its start, whose system gives the hooks: the state is
    /// projected, the start hook runs (it may switch the mode or halt at once), and the
    /// entry witnesses of the mode are checked. At most [`Hybrid::DEFAULT_MAX_STEPS`] step
    /// attempts towards one stop time ([`Hybrid::with_max_steps`]).
    ///
    /// # Errors
    /// What the hooks return; [`OdeError::NonFiniteWitness`]; the stepper's refusal of a
    /// switched state; [`OdeError::Zeno`].
    pub fn new(inner: S) -> Result<Self, OdeError> {
        let t = inner.t();
        let sys = inner.system();
        let state = HybridState {
            mode: sys.mode(),
            x: inner.state().clone(),
        };
        let disarmed = vec![false; sys.witness_names().len()];
        let mut me = Hybrid {
            inner,
            t_start: t,
            t,
            state,
            resync: None,
            transitions: Vec::new(),
            halt: None,
            budget: Budget {
                max_steps: Self::DEFAULT_MAX_STEPS,
                target: f64::NAN,
                start: 0,
            },
            witness_evals: 0,
            disarmed,
            points: Vec::new(),
            instant_roots: 0,
        };
        if me.inner.system().project(&mut me.state.x) {
            me.resync = Some(false);
        }
        let action = me.inner.system().start(t, &me.state)?;
        if matches!(action, Action::Continue) {
            me.enter(t)?;
        } else {
            me.act(action, t, Cause::Start)?;
        }
        me.sync()?;
        Ok(me)
    }

    /// Sets the budget of step attempts (accepted and rejected, over every restart of the
    /// wrapped stepper) towards one stop time; past it a step fails with
    /// [`OdeError::MaxStepsExceeded`].
    pub fn with_max_steps(mut self, max_steps: u64) -> Self {
        self.budget.max_steps = max_steps;
        self
    }

    /// The wrapped stepper.
    pub fn inner(&self) -> &S {
        &self.inner
    }

    /// The scene's system. Its own mode is the mode of the last step: a switch made at a
    /// step's end reaches it with the next step, so read the current mode from
    /// [`Hybrid::mode`] (the state carries it).
    pub fn system(&self) -> &S::System {
        self.inner.system()
    }

    /// The current mode.
    pub fn mode(&self) -> &ModeOf<S> {
        &self.state.mode
    }

    /// The switches taken so far, in time order.
    pub fn transitions(&self) -> &[Transition<ModeOf<S>, S::State>] {
        &self.transitions
    }

    /// The scene's outcome, once a hook has halted the run.
    pub fn halt(&self) -> Option<&HaltOf<S>> {
        self.halt.as_ref()
    }

    /// Evaluations of the witnesses so far (each on one state): the cost of watching.
    pub fn witness_evaluations(&self) -> u64 {
        self.witness_evals
    }

    /// Steps to `t_stop` (exactly, unless the run halts before): the loop of
    /// [`Stepper::step`].
    ///
    /// # Errors
    /// As [`Stepper::step`].
    pub fn advance_to(&mut self, t_stop: f64) -> Result<(), OdeError> {
        check_stop(self.t, t_stop)?;
        while self.t < t_stop && self.halt.is_none() {
            Stepper::step(self, t_stop)?;
        }
        Ok(())
    }

    /// Puts the inner stepper at the loop's state if it is not there.
    fn sync(&mut self) -> Result<(), OdeError> {
        if let Some(fresh) = self.resync {
            let mode = self.state.mode.clone();
            self.inner
                .switch(self.t, self.state.x.clone(), fresh, &mut |sys| {
                    if sys.mode() != mode {
                        sys.set_mode(mode.clone())
                    }
                })?;
            self.resync = None;
        }
        Ok(())
    }

    /// The inner stepper's step from `t_a` towards `t_limit`. A step whose stages meet a
    /// state where the right-hand side is not finite (a wheel past lying flat, a contact
    /// past its support map) is taken again towards half the distance, from the loop's
    /// state, as long as a witness is watched: the witness placed before the singularity
    /// is then reached by steps that stay short of it. Bounded by the halvings of the
    /// doubles between `t_a` and `t_limit`.
    fn step_inner(&mut self, t_a: f64, t_limit: f64) -> Result<(), OdeError> {
        let watching =
            (0..self.disarmed.len()).any(|id| self.inner.system().watches(&self.state.mode, id));
        let mut limit = t_limit;
        loop {
            match self.inner.step(limit) {
                Err(OdeError::NonFiniteState { .. }) if watching => {
                    let shorter = t_a + 0.5 * (limit - t_a);
                    if !(shorter > t_a && shorter < limit) {
                        return self.inner.step(limit);
                    }
                    limit = shorter;
                    // The failed attempt may have left stages of the non-finite state
                    // behind: start again from the loop's state, the step size kept.
                    self.inner.restart(t_a, self.state.x.clone())?;
                }
                other => return other,
            }
        }
    }

    /// Watches again each disarmed witness that is ≤ 0 at the step's end `t` (it has
    /// crossed) or no longer watched: its next fall through zero is an event again.
    fn rearm(&mut self, t: f64) -> Result<(), OdeError> {
        for id in 0..self.disarmed.len() {
            if self.disarmed[id]
                && (!self.inner.system().watches(&self.state.mode, id)
                    || self.eval(id, t, &self.state.x.clone())? <= 0.0)
            {
                self.disarmed[id] = false;
            }
        }
        Ok(())
    }

    /// Checks the entry witnesses of the current mode at the current state, and acts on the
    /// first that is already below 0.
    fn enter(&mut self, t: f64) -> Result<(), OdeError> {
        match self.entry_witness(t)? {
            None => Ok(()),
            Some((id, w)) => {
                let action = self.inner.system().on_witness(id, t, &self.state, w)?;
                self.act(action, t, Cause::Witness(self.name(id)))
            }
        }
    }

    /// The name of witness `id`.
    fn name(&self, id: usize) -> &'static str {
        let names = self.inner.system().witness_names();
        names.get(id).copied().unwrap_or("unnamed witness")
    }

    /// Carries out a hook's action at `t` (the loop's state is already there), then checks
    /// the entry witnesses of the mode it leads to, acting on the first already below 0.
    fn act(
        &mut self,
        first: HookAction<S::System, S::State>,
        t: f64,
        cause: Cause,
    ) -> Result<(), OdeError> {
        let (mut action, mut cause) = (first, cause);
        for _ in 0..MAX_SWITCHES_AT_ONCE {
            match action {
                Action::Continue => return Ok(()),
                Action::Halt(h) => {
                    self.halt = Some(h);
                    return Ok(());
                }
                Action::Switch { mode, state, fresh } => {
                    let after = HybridState { mode, x: state };
                    let before = core::mem::replace(&mut self.state, after);
                    self.inner.system().project(&mut self.state.x);
                    self.transitions.push(Transition {
                        t,
                        cause,
                        before,
                        after: self.state.clone(),
                    });
                    // A fresh start wins over a continued one asked before at this instant.
                    self.resync = Some(fresh || self.resync.unwrap_or(false));
                    self.disarmed.iter_mut().for_each(|d| *d = false);
                }
            }
            let Some((id, w)) = self.entry_witness(t)? else {
                return Ok(());
            };
            cause = Cause::Witness(self.name(id));
            action = self.inner.system().on_witness(id, t, &self.state, w)?;
        }
        Err(OdeError::Zeno {
            t,
            switches: MAX_SWITCHES_AT_ONCE,
        })
    }

    /// The first witness of the current mode that is below 0 at the current state, with its
    /// value (one at exactly 0 is taken up by the next step: it fires there if it falls).
    fn entry_witness(&mut self, t: f64) -> Result<Option<(usize, f64)>, OdeError> {
        for id in 0..self.disarmed.len() {
            if !self.inner.system().watches(&self.state.mode, id) {
                continue;
            }
            let w = self.eval(id, t, &self.state.x.clone())?;
            if w < 0.0 {
                return Ok(Some((id, w)));
            }
        }
        Ok(None)
    }

    /// Witness `id` at `(t, x)` in the current mode, refused when not finite.
    fn eval(&mut self, id: usize, t: f64, x: &S::State) -> Result<f64, OdeError> {
        self.witness_evals += 1;
        let value = self.inner.system().witness(&self.state.mode, id, t, x);
        if value.is_finite() {
            Ok(value)
        } else {
            Err(OdeError::NonFiniteWitness {
                witness: self.name(id),
                t,
                value,
            })
        }
    }

    /// The inner stepper's solution at `t` of its last step, projected as the scene projects
    /// a state (a quaternion normalised): the state the scene acts on at a root. The
    /// witnesses are scanned and their roots located on it, not on the raw interpolant,
    /// whose drift off the scene's manifold inside a long step moved a rolling sphere's
    /// normal force by 10⁻⁴ of its weight and its lift-off by 2e-3 rad.
    fn projected_at(&mut self, t: f64) -> Result<S::State, OdeError> {
        let mut x = self.inner.state_at(t)?;
        self.inner.system().project(&mut x);
        Ok(x)
    }

    /// The first root of a watched witness inside the inner stepper's last step
    /// `[t_a, t_b]` (falling: see [`falls`]), every root inside the step looked for: its id
    /// and the left end of its final bracket.
    fn first_root(&mut self, t_a: f64, t_b: f64) -> Result<Option<(usize, f64)>, OdeError> {
        let watched: Vec<usize> = (0..self.disarmed.len())
            .filter(|&id| !self.disarmed[id] && self.inner.system().watches(&self.state.mode, id))
            .collect();
        if watched.is_empty() {
            return Ok(None);
        }
        let times = first_pass_times(t_a, t_b);
        let x_a = self.state.x.clone();
        let x_b = self.projected_at(t_b)?;
        let inner_states = [
            self.projected_at(times[0])?,
            self.projected_at(times[1])?,
            self.projected_at(times[2])?,
        ];
        let mut first: Option<(usize, f64)> = None;
        let mut points = core::mem::take(&mut self.points);
        for id in watched {
            let g_a = self.eval(id, t_a, &x_a)?;
            let g_b = self.eval(id, t_b, &x_b)?;
            let inner = [
                self.eval(id, times[0], &inner_states[0])?,
                self.eval(id, times[1], &inner_states[1])?,
                self.eval(id, times[2], &inner_states[2])?,
            ];
            points.clear();
            points.push((t_a, g_a));
            let mut at = |t: f64| -> Result<f64, OdeError> {
                let x = self.projected_at(t)?;
                self.eval(id, t, &x)
            };
            scan_step(&mut at, (t_a, g_a), (t_b, g_b), inner, &mut points)?;
            let bracket = points.windows(2).find(|w| falls(w[0].1, w[1].1));
            let Some(&[left, right]) = bracket else {
                continue;
            };
            // Only a root before the first one found so far can come first.
            if first.is_some_and(|(_, t)| t <= left.0) {
                continue;
            }
            // The left end, the last time the mode held; but where the location met the
            // witness at exactly 0 (the right end), that zero is the root and the mode still
            // holds there (a witness of 0 is not below it). The left end is then only the
            // last point evaluated before it, which was 1.3e-6 s and 7e-7 N early on a
            // rolling sphere's lift-off.
            let ((t_left, _), (t_right, g_right)) = locate_bracket(&mut at, left, right)?;
            let t = if g_right == 0.0 { t_right } else { t_left };
            if first.is_none_or(|(_, t0)| t < t0) {
                first = Some((id, t));
            }
        }
        self.points = points;
        Ok(first)
    }
}

impl<S> Stepper for Hybrid<S>
where
    S: Switchable,
    S::System: Hooks<S::State>,
{
    type State = StateOf<S>;

    fn t(&self) -> f64 {
        self.t
    }

    fn state(&self) -> &Self::State {
        &self.state
    }

    fn stats(&self) -> Stats {
        self.inner.stats()
    }

    fn halted(&self) -> bool {
        self.halt.is_some()
    }

    /// One step of the loop: the inner stepper's step, cut at the first root of a watched
    /// witness (where the scene acts), or projected and guarded at its end.
    fn step(&mut self, t_limit: f64) -> Result<(), OdeError> {
        if self.halt.is_some() {
            return Err(OdeError::Halted { t: self.t });
        }
        check_stop(self.t, t_limit)?;
        if t_limit == self.t {
            return Ok(());
        }
        self.sync()?;
        let attempts = |s: Stats| s.steps + s.rejections;
        if t_limit != self.budget.target {
            self.budget.target = t_limit;
            self.budget.start = attempts(self.inner.stats());
        }
        if attempts(self.inner.stats()) - self.budget.start >= self.budget.max_steps {
            return Err(OdeError::MaxStepsExceeded {
                t: self.t,
                max_steps: self.budget.max_steps,
            });
        }
        let t_a = self.t;
        self.step_inner(t_a, t_limit)?;
        let t_b = self.inner.t();
        self.t_start = t_a;
        match self.first_root(t_a, t_b)? {
            Some((id, t)) => {
                // A witness that starts a step at exactly 0 and falls fires at the step's
                // start: the loop's step is empty, and a run of them is a Zeno point.
                self.instant_roots = if t == t_a { self.instant_roots + 1 } else { 0 };
                if self.instant_roots > MAX_SWITCHES_AT_ONCE {
                    return Err(OdeError::Zeno {
                        t,
                        switches: self.instant_roots,
                    });
                }
                self.t = t;
                self.state.x = self.inner.state_at(t)?;
                self.inner.system().project(&mut self.state.x);
                self.resync = Some(false);
                // The witness at the root's projected state, as the scene sees it there.
                let w = self.eval(id, t, &self.state.x.clone())?;
                let action = self.inner.system().on_witness(id, t, &self.state, w)?;
                if matches!(action, Action::Continue) {
                    self.disarmed[id] = true;
                }
                self.act(action, t, Cause::Witness(self.name(id)))?;
            }
            None => {
                self.t = t_b;
                self.state.x = self.inner.state().clone();
                if self.inner.system().project(&mut self.state.x) {
                    self.resync = Some(false);
                }
                self.rearm(t_b)?;
                let action = self.inner.system().after_step(t_b, &self.state)?;
                self.act(action, t_b, Cause::StepEnd)?;
            }
        }
        Ok(())
    }

    fn step_start(&self) -> f64 {
        self.t_start
    }

    /// The inner stepper's solution inside the loop's last step, in the mode of that step;
    /// at the step's end, the loop's state (after the scene acted there).
    fn state_at(&mut self, t: f64) -> Result<Self::State, OdeError> {
        if !t.is_finite() {
            return Err(OdeError::NonFiniteTime { t });
        }
        if t == self.t {
            return Ok(self.state.clone());
        }
        if !(t >= self.t_start && t < self.t) {
            return Err(OdeError::OutsideLastStep {
                t,
                t_prev: self.t_start,
                t_now: self.t,
            });
        }
        // The mode of the step: the one before the first switch at its end, if any.
        let mode = self
            .transitions
            .iter()
            .rev()
            .take_while(|tr| tr.t == self.t)
            .last()
            .map_or_else(|| self.state.mode.clone(), |tr| tr.before.mode.clone());
        Ok(HybridState {
            mode,
            x: self.inner.state_at(t)?,
        })
    }

    /// Puts the loop at `(t, state)` in the state's mode, as a continued run: a terminal
    /// event of a [`Run`](super::Run) inside the last step, or a new start. A halted run
    /// goes on from there.
    fn restart(&mut self, t: f64, state: Self::State) -> Result<(), OdeError> {
        if !t.is_finite() {
            return Err(OdeError::NonFiniteTime { t });
        }
        let mode = state.mode.clone();
        self.inner.switch(t, state.x.clone(), false, &mut |sys| {
            if sys.mode() != mode {
                sys.set_mode(mode.clone())
            }
        })?;
        (self.t, self.t_start, self.state, self.resync) = (t, t, state, None);
        self.halt = None;
        self.disarmed.iter_mut().for_each(|d| *d = false);
        Ok(())
    }
}

/// The [`Stepper`] of a scene's run that wraps a [`Hybrid`] in a field: every method
/// forwarded, so `Run`, trajectories and ensembles take the scene's run itself. Invoked as
/// `delegate_stepper!([generics] Type, field, State)`.
macro_rules! delegate_stepper {
    ([$($generics:tt)*] $ty:ty, $field:ident, $state:ty) => {
        impl<$($generics)*> $crate::ode::Stepper for $ty {
            type State = $state;

            fn t(&self) -> f64 {
                $crate::ode::Stepper::t(&self.$field)
            }

            fn state(&self) -> &$state {
                $crate::ode::Stepper::state(&self.$field)
            }

            fn stats(&self) -> $crate::ode::Stats {
                $crate::ode::Stepper::stats(&self.$field)
            }

            fn step(&mut self, t_limit: f64) -> Result<(), $crate::ode::OdeError> {
                $crate::ode::Stepper::step(&mut self.$field, t_limit)
            }

            fn step_start(&self) -> f64 {
                $crate::ode::Stepper::step_start(&self.$field)
            }

            fn state_at(&mut self, t: f64) -> Result<$state, $crate::ode::OdeError> {
                $crate::ode::Stepper::state_at(&mut self.$field, t)
            }

            fn restart(&mut self, t: f64, state: $state) -> Result<(), $crate::ode::OdeError> {
                $crate::ode::Stepper::restart(&mut self.$field, t, state)
            }

            fn halted(&self) -> bool {
                $crate::ode::Stepper::halted(&self.$field)
            }
        }
    };
}
pub(crate) use delegate_stepper;
