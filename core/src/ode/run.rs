//! A run of any [`Stepper`] to an end time, with samples, derived quantities, an observer of
//! every accepted step, events and progress reports.

use super::error::{OdeError, check_stop};
use super::events::{Event, EventHit, EventSlot, StepRoots, crossing, locate_root};
use super::sampling::{SampleClock, Sampling};
use super::scan::{first_pass_times, scan_step};
use super::stepper::Stepper;
use super::system::Stats;
use super::trajectory::{Named, Quantities, Trajectory};

/// What an observer asks for after a step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Control {
    /// Go on.
    Continue,
    /// End the run here.
    Stop,
}

/// Why a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StopReason {
    /// It reached the end time.
    End,
    /// A terminal event fired (its index).
    Event(usize),
    /// The observer returned [`Control::Stop`].
    Observer,
    /// The stepper halted the run by itself: a [`Hybrid`](super::Hybrid) run whose scene
    /// stopped it (read its outcome with [`Hybrid::halt`](super::Hybrid::halt)).
    Halted,
}

/// How far a run has come, for a progress callback.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Progress {
    /// Current time.
    pub t: f64,
    /// Start of the run.
    pub t_start: f64,
    /// End of the run.
    pub t_end: f64,
    /// Work done so far.
    pub stats: Stats,
}

impl Progress {
    /// (t − t_start)/(t_end − t_start), in [0, 1] (1 for an empty span).
    pub fn fraction(&self) -> f64 {
        let span = self.t_end - self.t_start;
        if span > 0.0 {
            ((self.t - self.t_start) / span).clamp(0.0, 1.0)
        } else {
            1.0
        }
    }
}

/// The result of a run.
#[derive(Debug, Clone, PartialEq)]
pub struct Outcome<St> {
    /// The recorded samples.
    pub trajectory: Trajectory<St>,
    /// The events that fired, in time order.
    pub events: Vec<EventHit<St>>,
    /// Why the run ended.
    pub stop: StopReason,
    /// The final time (the end, a terminal event's time, or the step the observer stopped).
    pub t: f64,
    /// The final state.
    pub state: St,
    /// The stepper's work over its life.
    pub stats: Stats,
}

impl<St> Outcome<St> {
    /// The hits of event `index`.
    pub fn hits(&self, index: usize) -> impl Iterator<Item = &EventHit<St>> {
        self.events.iter().filter(move |h| h.index == index)
    }
}

/// Progress is reported each time the fraction done passes another 1/`PROGRESS_STEPS`.
const PROGRESS_STEPS: f64 = 1000.0;

type Observer<'a, St> = Box<dyn FnMut(f64, &St) -> Control + 'a>;
type Reporter<'a> = Box<dyn FnMut(&Progress) + 'a>;

/// A run of a [`Stepper`] from where it stands to `t_end`: what to sample, which quantities
/// to derive per sample, which events to find, who watches each step, and who hears of the
/// progress. Built with chained calls, then [`Run::integrate`].
///
/// Per accepted step, in order: events are found and located, samples inside the step are
/// recorded, the observer sees the step's end, and progress is reported. Nothing allocates
/// per step except what is recorded (samples, event hits).
///
/// # Examples
///
/// A ball dropped from 10 m (z̈ = −9.81) hits the floor at √(2·10/9.81) s; a terminal
/// falling event on z stops the run there, and the trajectory carries the energy per sample:
///
/// ```
/// use approx::assert_relative_eq;
/// use precess_core::ode::{AdaptiveConfig, Dopri5, Event, FnSystem, Run, StopReason};
/// let fall = FnSystem(|_t: f64, y: &[f64; 2], d: &mut [f64; 2]| *d = [y[1], -9.81]);
/// let mut ode = Dopri5::new(fall, 0.0, [10.0, 0.0], AdaptiveConfig::default())?;
/// let out = Run::new(&mut ode, 5.0)
///     .sample_every(0.25)
///     .quantity("energy", |_t, y| 9.81 * y[0] + 0.5 * y[1] * y[1])
///     .event(Event::new("floor").falling().terminal(), |_t, y| y[0])
///     .integrate()?;
/// assert_eq!(out.stop, StopReason::Event(0));
/// assert_relative_eq!(out.t, (2.0 * 10.0 / 9.81f64).sqrt(), max_relative = 1e-14);
/// assert_eq!(out.trajectory.len(), 6); // t = 0, 0.25, …, 1.25 ≤ 1.428 s
/// for e in out.trajectory.column("energy").unwrap() {
///     assert_relative_eq!(e, 98.1, max_relative = 1e-13);
/// }
/// assert!(out.trajectory.to_csv().starts_with("t,y0,y1,energy\n0,10,0,"));
/// # Ok::<(), precess_core::ode::OdeError>(())
/// ```
pub struct Run<'a, S: Stepper> {
    stepper: &'a mut S,
    t_end: f64,
    sampling: Sampling,
    quantities: Vec<Box<dyn Quantities<S::State> + 'a>>,
    events: Vec<EventSlot<'a, S>>,
    observer: Option<Observer<'a, S::State>>,
    progress: Option<Reporter<'a>>,
    /// The points of the current step at which the scan evaluated one event's g, kept
    /// across steps so that the scan does not allocate.
    points: Vec<(f64, f64)>,
}

impl<'a, S: Stepper> Run<'a, S> {
    /// A run of `stepper` from its current time to `t_end`, recording every step.
    pub fn new(stepper: &'a mut S, t_end: f64) -> Self {
        Self {
            stepper,
            t_end,
            sampling: Sampling::Steps,
            quantities: Vec::new(),
            events: Vec::new(),
            observer: None,
            progress: None,
            points: Vec::new(),
        }
    }

    /// Records the start and every accepted step (the default).
    pub fn sample_steps(mut self) -> Self {
        self.sampling = Sampling::Steps;
        self
    }

    /// Records nothing (the events, the observer and the final state are the answer).
    pub fn sample_none(self) -> Self {
        self.sample_at(Vec::new())
    }

    /// Records the states at `times` (ascending, from the start to `t_end`) from the
    /// stepper's solution inside each step; the steps stay the stepper's own.
    pub fn sample_at(mut self, times: impl Into<Vec<f64>>) -> Self {
        self.sampling = Sampling::Times(times.into());
        self
    }

    /// Records the states at t0, t0 + dt, t0 + 2 dt, … up to `t_end` (each time computed as
    /// t0 + k dt, so no round-off gathers). The times increase strictly.
    ///
    /// [`Run::integrate`] refuses before any work, with [`OdeError::InvalidStep`] a dt that
    /// is not finite and > 0, with [`OdeError::SampleIntervalBelowResolution`] one below
    /// [`MIN_SAMPLE_SPACINGS`](super::MIN_SAMPLE_SPACINGS) spacings of the doubles at the
    /// run's largest |t| (sampling every 1e-8 s from t0 = 1e9 s, where doubles are 1.2e-7
    /// apart), and with [`OdeError::TooManySamples`] more samples than
    /// [`MAX_SAMPLES`](super::MAX_SAMPLES).
    pub fn sample_every(mut self, dt: f64) -> Self {
        self.sampling = Sampling::Every(dt);
        self
    }

    /// Adds a derived quantity `name`, computed at each recorded sample.
    pub fn quantity(
        self,
        name: impl Into<String>,
        f: impl FnMut(f64, &S::State) -> f64 + 'a,
    ) -> Self {
        self.quantities(Named {
            name: name.into(),
            f,
        })
    }

    /// Adds a set of derived quantities (a scene's standard ones).
    pub fn quantities(mut self, q: impl Quantities<S::State> + 'a) -> Self {
        self.quantities.push(Box::new(q));
        self
    }

    /// Adds an event: the zero crossings of `g(t, y)` that `event` counts, every root inside
    /// each step (not only a change of sign between the step's ends), located on the
    /// stepper's solution. `g` is called at the step's ends and at inner times of the step
    /// in any order, three of them per step at least. What is guaranteed to be found, as far
    /// as the error estimate of g's interpolant on the step is its error (it is an
    /// a-posteriori estimate, not a bound): every root of g such that |g| exceeds twice that
    /// estimate (at most 1e-10 of max |g| where g is resolved) between it and each
    /// neighbouring root (`docs/trajectories.md`, Events).
    pub fn event(mut self, event: Event, g: impl FnMut(f64, &S::State) -> f64 + 'a) -> Self {
        self.events.push(EventSlot {
            event,
            g: Box::new(g),
            roots: None,
            last: 0.0,
        });
        self
    }

    /// Adds an event whose roots in each step `roots` isolates, with `g` its value at the
    /// steps' ends (for steppers that find an event's roots themselves: the Taylor
    /// integrator's [`Run::taylor_event`]).
    pub(crate) fn event_with_roots(
        mut self,
        event: Event,
        g: impl FnMut(f64, &S::State) -> f64 + 'a,
        roots: Box<dyn StepRoots<S> + 'a>,
    ) -> Self {
        self.events.push(EventSlot {
            event,
            g: Box::new(g),
            roots: Some(roots),
            last: 0.0,
        });
        self
    }

    /// Calls `observer(t, y)` after every accepted step; [`Control::Stop`] ends the run there.
    pub fn observe(mut self, observer: impl FnMut(f64, &S::State) -> Control + 'a) -> Self {
        self.observer = Some(Box::new(observer));
        self
    }

    /// Calls `report` at the start, each time another thousandth of the span is done, and at
    /// the end (for a progress bar).
    pub fn progress(mut self, report: impl FnMut(&Progress) + 'a) -> Self {
        self.progress = Some(Box::new(report));
        self
    }

    /// Runs to `t_end`, a terminal event, the observer's stop, or the stepper's own halt.
    ///
    /// # Errors
    /// Before any work: [`OdeError::NonFiniteTime`] and [`OdeError::StopBeforeCurrent`] for a
    /// bad end or sample time, [`OdeError::SampleAfterEnd`], [`OdeError::InvalidStep`] for a
    /// sample interval that is not finite and > 0, [`OdeError::NonFiniteEvent`] at the start.
    /// While running: the stepper's errors, [`OdeError::NonFiniteEvent`],
    /// [`OdeError::NonFiniteQuantity`], [`OdeError::EventNotResolved`] (an event of
    /// `Run::taylor_event` whose polynomial on a step is not g).
    pub fn integrate(mut self) -> Result<Outcome<S::State>, OdeError> {
        let t0 = self.stepper.t();
        let t_end = self.t_end;
        check_stop(t0, t_end)?;
        let sampling = core::mem::replace(&mut self.sampling, Sampling::Steps);
        let mut samples = SampleClock::new(sampling, t0, t_end)?;
        let y0 = self.stepper.state().clone();
        for (index, slot) in self.events.iter_mut().enumerate() {
            slot.last = slot.eval(index, t0, &y0)?;
        }
        let sets: Vec<Vec<String>> = self.quantities.iter().map(|q| q.names()).collect();
        let counts: Vec<usize> = sets.iter().map(Vec::len).collect();
        let names: Vec<String> = sets.into_iter().flatten().collect();
        let mut values = vec![0.0; names.len()];
        let mut out = Outcome {
            trajectory: Trajectory::new(names),
            events: Vec::new(),
            stop: StopReason::End,
            t: t0,
            state: y0.clone(),
            stats: self.stepper.stats(),
        };
        if samples.take_start(t0) {
            self.record(&mut out.trajectory, (&counts, &mut values), t0, y0)?;
        }
        let mut level = -1.0;
        self.report(&mut level, (t0, t0, t_end), true);
        while self.stepper.t() < t_end {
            if self.stepper.halted() {
                out.stop = StopReason::Halted;
                break;
            }
            self.stepper.step(t_end)?;
            let (t_a, t_b) = (self.stepper.step_start(), self.stepper.t());
            let y_b = self.stepper.state().clone();
            let first_new = out.events.len();
            self.find_events(&mut out.events, t_a, t_b, &y_b)?;
            let terminal = out.events[first_new..].iter().position(|h| h.terminal);
            let t_stop = match terminal {
                Some(k) => {
                    out.events.truncate(first_new + k + 1);
                    let hit = &out.events[first_new + k];
                    out.stop = StopReason::Event(hit.index);
                    hit.t
                }
                None => t_b,
            };
            while let Some(ts) = samples.next_until(t_stop) {
                let y = self.stepper.state_at(ts)?;
                self.record(&mut out.trajectory, (&counts, &mut values), ts, y)?;
            }
            if let Some(k) = terminal {
                let hit = &out.events[first_new + k];
                let (t_hit, y_hit) = (hit.t, hit.state.clone());
                if samples.steps() {
                    self.record(
                        &mut out.trajectory,
                        (&counts, &mut values),
                        t_hit,
                        y_hit.clone(),
                    )?;
                }
                self.stepper.restart(t_hit, y_hit)?;
                break;
            }
            if samples.steps() {
                self.record(
                    &mut out.trajectory,
                    (&counts, &mut values),
                    t_b,
                    y_b.clone(),
                )?;
            }
            if let Some(obs) = self.observer.as_mut()
                && obs(t_b, &y_b) == Control::Stop
            {
                out.stop = StopReason::Observer;
                break;
            }
            self.report(&mut level, (t0, t_b, t_end), false);
        }
        if out.stop == StopReason::End && self.stepper.halted() {
            out.stop = StopReason::Halted;
        }
        out.t = self.stepper.t();
        out.state = self.stepper.state().clone();
        out.stats = self.stepper.stats();
        self.report(&mut level, (t0, out.t, t_end), true);
        Ok(out)
    }

    /// Finds the counted crossings of every event in the step `[t_a, t_b]`, every root of g
    /// inside the step and not only a change of sign between its ends (see
    /// [`super::scan`]), each located on the stepper's solution; appends them in time order.
    fn find_events(
        &mut self,
        hits: &mut Vec<EventHit<S::State>>,
        t_a: f64,
        t_b: f64,
        y_b: &S::State,
    ) -> Result<(), OdeError> {
        if self.events.is_empty() {
            return Ok(());
        }
        let first_new = hits.len();
        let stepper = &mut *self.stepper;
        // The first pass's inner states, shared by every event that scans.
        let times = first_pass_times(t_a, t_b);
        let states = if self
            .events
            .iter()
            .all(|s| s.event.is_step_ends_only() || s.roots.is_some())
        {
            None
        } else {
            Some([
                stepper.state_at(times[0])?,
                stepper.state_at(times[1])?,
                stepper.state_at(times[2])?,
            ])
        };
        for (index, slot) in self.events.iter_mut().enumerate() {
            let (wanted, terminal) = (slot.event.direction(), slot.event.is_terminal());
            let g_b = slot.eval(index, t_b, y_b)?;
            let g_a = core::mem::replace(&mut slot.last, g_b);
            let points = &mut self.points;
            points.clear();
            points.push((t_a, g_a));
            match &states {
                // An event whose roots the stepper isolates itself (not scanned).
                _ if slot.roots.is_some() && !slot.event.is_step_ends_only() => {
                    if let Some(roots) = slot.roots.as_mut() {
                        roots.points(stepper, index, (t_a, g_a), (t_b, g_b), points)?;
                    }
                }
                Some(states) if !slot.event.is_step_ends_only() => {
                    let inner = [
                        slot.eval(index, times[0], &states[0])?,
                        slot.eval(index, times[1], &states[1])?,
                        slot.eval(index, times[2], &states[2])?,
                    ];
                    scan_step(
                        &mut |t| g_at(stepper, slot, index, t),
                        (t_a, g_a),
                        (t_b, g_b),
                        inner,
                        points,
                    )?;
                }
                _ => points.push((t_b, g_b)),
            }
            for pair in points.windows(2) {
                let [left, right] = [pair[0], pair[1]];
                let Some(direction) = crossing(wanted, left.1, right.1) else {
                    continue;
                };
                // Located on what isolated the root: the stepper's function for an event it
                // isolates, g on the stepper's solution otherwise (and for the ends only).
                let t = match &mut slot.roots {
                    Some(roots) if !slot.event.is_step_ends_only() => {
                        locate_root(|t| roots.value(index, t), left, right)?
                    }
                    _ => locate_root(|t| g_at(stepper, slot, index, t), left, right)?,
                };
                hits.push(EventHit {
                    index,
                    t,
                    state: stepper.state_at(t)?,
                    direction,
                    terminal,
                });
            }
        }
        hits[first_new..].sort_by(|a, b| a.t.total_cmp(&b.t));
        Ok(())
    }

    /// Appends a sample with its derived quantities (`counts[i]` of them from the i-th set).
    fn record(
        &mut self,
        trajectory: &mut Trajectory<S::State>,
        (counts, values): (&[usize], &mut [f64]),
        t: f64,
        y: S::State,
    ) -> Result<(), OdeError> {
        let mut start = 0;
        for (q, &k) in self.quantities.iter_mut().zip(counts) {
            if let Some(out) = values.get_mut(start..start + k) {
                q.evaluate(t, &y, out);
            }
            start += k;
        }
        trajectory.push(t, y, values)
    }

    /// Reports progress when `force`d or when another thousandth of the span is done.
    fn report(&mut self, level: &mut f64, (t_start, t, t_end): (f64, f64, f64), force: bool) {
        let Some(report) = self.progress.as_mut() else {
            return;
        };
        let p = Progress {
            t,
            t_start,
            t_end,
            stats: self.stepper.stats(),
        };
        let now = (p.fraction() * PROGRESS_STEPS).floor();
        if force || now > *level {
            *level = now;
            report(&p);
        }
    }
}

/// g of `slot` (event `index`) on the stepper's solution at `t` inside the last step.
fn g_at<S: Stepper>(
    stepper: &mut S,
    slot: &mut EventSlot<'_, S>,
    index: usize,
    t: f64,
) -> Result<f64, OdeError> {
    let y = stepper.state_at(t)?;
    slot.eval(index, t, &y)
}
