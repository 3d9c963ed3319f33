//! [`BatchTaylor`]: `L` Taylor integrations stepped together, their jets and their ordinary
//! steps' size and sum computed in lanes, and the rest (the rule, the check, the commit,
//! events, every unusual step) lane by lane with the scalar code.

use super::events::{event_step, event_value};
use super::{Lanes, TaylorLanes};
use crate::ode::{OdeError, check_stop};
use crate::taylor::integrator::{PendingStep, StepRule};
use crate::taylor::{Taylor, TaylorConfig};

/// Where one lane stopped: the time and state, and whether its event ended it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LaneEnd<const N: usize> {
    /// The time the lane reached: its end time, or its event's root.
    pub t: f64,
    /// The state there.
    pub y: [f64; N],
    /// Whether the lane's event stopped it before its end time.
    pub event: bool,
}

/// One lane: its scalar integrator, or the error that put it out of the batch for good.
// A batch holds L of them, once: the size of the failed variant does not matter.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone)]
enum Lane<S: TaylorLanes<N, L>, const N: usize, const L: usize> {
    Live(Taylor<S, N>),
    Failed(OdeError),
}

/// `L` Taylor integrations of the systems of one type, each with its own parameters,
/// initial point, end time, step sizes and event, stepped together: each step computes the
/// jets of every lane in one call ([`TaylorLanes`], straight-line code on [`Lanes<L>`]
/// that the compiler vectorises), sizes and sums every lane's step from its own
/// coefficients in lane arithmetic, computes the jets at the steps' ends in one call more
/// (each lane's defect check reads its own, and its next step starts from it), and checks,
/// commits and runs each lane's event with the scalar integrator's code. The whole loop is
/// compiled for AVX-512, AVX2 and the baseline and dispatched on the processor at run time
/// (see the module's notes).
///
/// **Bitwise equal to scalar runs.** A lane is a [`Taylor`] whose jets come from the batch;
/// since a lane's coefficients are the scalar ones bit for bit ([`TaylorLanes`]) and the
/// lanes' step control does the scalar operations in the scalar order on each lane, every
/// lane takes the steps of a scalar [`Taylor`] run of the same system, start and
/// configuration, ends on the same bits and counts the same steps, jets and evaluations.
/// A step outside the ordinary (a jet whose top rows vanish or overflow, lanes at different
/// orders, a step the check cuts) is taken by that lane's scalar code.
///
/// **Divergence is masked.** The batch computes every lane's jet to the highest order any
/// active lane needs (a lane's lower orders do not depend on the higher ones). A lane that
/// has reached its end, met its event or failed is masked: its slot in the batch is filled
/// with an active lane's point and system, and its values are not read. An event's root is
/// refined in scalar, on that lane's step polynomial alone. The rare jet that vanishes to its
/// order (see [`Taylor::step`]) is computed again in scalar for that lane.
///
/// **Errors stay with their lane.** A lane whose start is refused by [`Taylor::new`] or whose
/// step fails (NaN parameters give [`OdeError::NonFiniteState`]) is out of the batch with its
/// error; the others finish.
///
/// The extended mode ([`TaylorConfig::extended`]) is not available in lanes: every lane
/// fails with [`OdeError::InvalidParameter`].
/// `taylor_system!` implements [`TaylorLanes`] for its systems; see `docs/lanes.md`.
#[derive(Debug, Clone)]
pub struct BatchTaylor<S: TaylorLanes<N, L>, const N: usize, const L: usize> {
    lanes: Vec<Lane<S, N, L>>,
    ws: S::LaneWorkspace,
    /// The lanes' jets at their points, orders 0 … the highest order any lane may use (lane
    /// l's is read only where the loop marks it valid).
    cur: Vec<[Lanes<L>; N]>,
    /// The batch's last computation: the jets at the steps' ends, or at points without a jet
    /// in `cur`.
    next: Vec<[Lanes<L>; N]>,
}

impl<S: TaylorLanes<N, L>, const N: usize, const L: usize> BatchTaylor<S, N, L> {
    /// Starts lane `l` at `(t0[l], y0[l])` with `systems[l]`, each as [`Taylor::new`] would;
    /// a lane it refuses keeps the error and is out of the batch.
    pub fn new(systems: [S; L], t0: [f64; L], y0: [[f64; N]; L], cfg: TaylorConfig) -> Self {
        let mut starts = systems.into_iter().zip(t0).zip(y0);
        Self::from_integrators(core::array::from_fn(|_| match starts.next() {
            Some(((s, t), y)) => Taylor::new(s, t, y, cfg),
            // The three arrays have L entries each: never reached.
            None => Err(OdeError::InvalidParameter {
                name: "lane without a start",
                value: f64::NAN,
            }),
        }))
    }

    /// Puts `L` scalar integrators (each with its own configuration, as
    /// [`Taylor::new`] built it) into one batch; an `Err` lane is out of the batch with
    /// its error, as is one in the extended mode ([`OdeError::InvalidParameter`]).
    ///
    /// Each lane then takes exactly the steps the integrator would have taken alone.
    pub fn from_integrators(odes: [Result<Taylor<S, N>, OdeError>; L]) -> Self {
        let lanes: Vec<Lane<S, N, L>> = odes
            .into_iter()
            .map(|ode| match ode {
                Ok(ode) => match ode.config().extended {
                    None => Lane::Live(ode),
                    Some(low) => Lane::Failed(OdeError::InvalidParameter {
                        name: "extended (the lanes step in f64 only)",
                        value: low as f64,
                    }),
                },
                Err(e) => Lane::Failed(e),
            })
            .collect();
        let rows = lanes
            .iter()
            .filter_map(|lane| match lane {
                Lane::Live(ode) => Some(ode.config().max_order.min(ode.system().max_order())),
                Lane::Failed(_) => None,
            })
            .max()
            .unwrap_or(0);
        Self {
            lanes,
            ws: S::LaneWorkspace::default(),
            cur: vec![[Lanes::splat(0.0); N]; rows + 1],
            next: vec![[Lanes::splat(0.0); N]; rows + 1],
        }
    }

    /// Lane `l`'s integrator, or the error that put it out of the batch (`None` past `L`).
    pub fn lane(&self, l: usize) -> Option<Result<&Taylor<S, N>, OdeError>> {
        self.lanes.get(l).map(|lane| match lane {
            Lane::Live(ode) => Ok(ode),
            Lane::Failed(e) => Err(e.clone()),
        })
    }

    /// Steps every lane to its own `t_end[l]`, exactly as [`Taylor::advance_to`] would.
    ///
    /// # Errors
    /// Per lane: a lane failed before, or [`Taylor::advance_to`]'s errors for this lane
    /// ([`OdeError::StopBeforeCurrent`], [`OdeError::NonFiniteState`], …); the lane is then
    /// out of the batch and the others go on.
    pub fn advance_to(&mut self, t_end: [f64; L]) -> [Result<LaneEnd<N>, OdeError>; L] {
        self.advance_until(t_end, |_, _, _| 1.0)
    }

    /// [`BatchTaylor::advance_to`] with a terminal event per lane: lane `l` stops at the
    /// first time its `g(l, t, y)` changes sign (from the sign it has at the start; a start
    /// on g = 0 waits for g to leave zero and come back). The crossing is detected at the
    /// ends of the lane's steps and its root refined on the lane's step polynomial
    /// (bisection with the secant, to the resolution of t), in scalar; the lane is put at
    /// the root ([`LaneEnd::event`]).
    ///
    /// # Errors
    /// As [`BatchTaylor::advance_to`], and [`OdeError::NonFiniteEvent`] (index 0) when g is
    /// not finite on the lane.
    pub fn advance_until(
        &mut self,
        t_end: [f64; L],
        mut g: impl FnMut(usize, f64, &[f64; N]) -> f64,
    ) -> [Result<LaneEnd<N>, OdeError>; L] {
        // The whole stepping, jets and step control, compiled for the best instruction set
        // the processor has (AVX-512, AVX2 or the target's baseline), chosen here at run
        // time: `pulp` keeps the `#[target_feature]` functions and their `unsafe` calls, and
        // the code inlined into them (`#[inline(always)]` down to the lanes' arithmetic) is
        // compiled once per set. No set changes a lane's bits: Rust fuses no multiply-add
        // whatever the target, and every operation here rounds as its scalar one.
        pulp::Arch::new().dispatch(Advance {
            batch: self,
            t_end,
            g: &mut g,
        })
    }

    /// [`BatchTaylor::advance_until`]'s loop, inlined into each of its dispatched copies.
    #[inline(always)]
    fn advance_lanes(
        &mut self,
        t_end: [f64; L],
        g: &mut impl FnMut(usize, f64, &[f64; N]) -> f64,
    ) -> [Result<LaneEnd<N>, OdeError>; L] {
        let mut ends: [Option<Result<LaneEnd<N>, OdeError>>; L] = core::array::from_fn(|_| None);
        let mut g_last = [0.0f64; L];
        for (l, lane) in self.lanes.iter().enumerate() {
            match lane {
                Lane::Live(ode) => match check_stop(ode.t(), t_end[l])
                    .and_then(|()| event_value(g, l, ode.t(), ode.y()))
                {
                    Ok(v) => g_last[l] = v,
                    Err(e) => ends[l] = Some(Err(e)),
                },
                Lane::Failed(e) => ends[l] = Some(Err(e.clone())),
            }
        }
        let mut rules: [Option<StepRule<N>>; L] = [None; L];
        let mut pending: [Option<PendingStep<N>>; L] = [None; L];
        // Whether lane l's jet at its point is in `self.cur` (to its rule's order).
        let mut valid = [false; L];
        loop {
            // The rule of each active lane's next step, or its end.
            for (l, lane) in self.lanes.iter().enumerate() {
                rules[l] = None;
                if ends[l].is_some() {
                    continue;
                }
                let Lane::Live(ode) = lane else { continue };
                match ode.lane_rule(t_end[l]) {
                    Ok(Some(rule)) => rules[l] = Some(rule),
                    Ok(None) => {
                        ends[l] = Some(Ok(LaneEnd {
                            t: ode.t(),
                            y: *ode.y(),
                            event: false,
                        }))
                    }
                    Err(e) => ends[l] = Some(Err(e)),
                }
            }
            if rules.iter().all(Option::is_none) {
                break;
            }
            self.fresh_jets(&rules, &mut valid, &mut ends);
            // Each lane sizes and sums its step (in lanes where it is an ordinary one); the
            // batch computes the jets at the steps' ends, which each lane's check reads and
            // its next step starts from.
            for (l, lane) in self.lanes.iter_mut().enumerate() {
                if let (Lane::Live(ode), Some(rule), None) = (lane, rules[l], &ends[l])
                    && let Err(e) = ode.lane_take_jet(&rule)
                {
                    ends[l] = Some(Err(e));
                }
            }
            let active: [Option<(&Taylor<S, N>, StepRule<N>)>; L] =
                core::array::from_fn(|l| match (self.lanes.get(l), rules[l], &ends[l]) {
                    (Some(Lane::Live(ode)), Some(rule), None) => Some((ode, rule)),
                    _ => None,
                });
            let summed = Taylor::lanes_begin(active, t_end, &self.cur);
            let mut stepped = [false; L];
            for (l, lane) in self.lanes.iter_mut().enumerate() {
                let (Lane::Live(ode), Some(rule), None) = (lane, rules[l], &ends[l]) else {
                    continue;
                };
                let step = match summed[l] {
                    Some(step) => Ok(Some(step)),
                    None => ode.lane_begin_ruled(rule, t_end[l]),
                };
                match step {
                    Ok(step) => (pending[l], stepped[l]) = (step, true),
                    Err(e) => ends[l] = Some(Err(e)),
                }
            }
            let at_ends = pending
                .each_ref()
                .map(|s| s.as_ref().map(|s| (s.order, s.t_new, s.y_new)));
            self.batch_jet(&at_ends);
            valid = [false; L];
            for (l, step) in pending.iter_mut().enumerate() {
                let (Some(step), Some(Lane::Live(ode))) = (step.take(), self.lanes.get_mut(l))
                else {
                    continue;
                };
                match ode.lane_finish(step, |rows| column(&self.next, l, rows)) {
                    Ok(kept) => valid[l] = kept,
                    Err(e) => (ends[l], stepped[l]) = (Some(Err(e)), false),
                }
            }
            std::mem::swap(&mut self.cur, &mut self.next);
            for (l, lane) in self.lanes.iter_mut().enumerate() {
                let Lane::Live(ode) = lane else { continue };
                if !stepped[l] {
                    continue;
                }
                match event_step(ode, l, g, &mut g_last[l]) {
                    Ok(Some(end)) => ends[l] = Some(Ok(end)),
                    Ok(None) => {}
                    Err(e) => ends[l] = Some(Err(e)),
                }
            }
        }
        // A lane whose step failed is out of the batch from now on.
        for (lane, end) in self.lanes.iter_mut().zip(&ends) {
            if let (Lane::Live(_), Some(Err(e))) = (&*lane, end) {
                *lane = Lane::Failed(e.clone());
            }
        }
        // Every lane has its end when no lane needs an order: the fallback is never taken.
        ends.map(|end| {
            end.unwrap_or(Err(OdeError::InvalidParameter {
                name: "lane without an end",
                value: f64::NAN,
            }))
        })
    }

    /// Puts the jet at its point of every lane with a rule and no jet in `self.cur`: the one
    /// the lane's integrator kept (a step its check cut ends on a scalar jet), or one batch
    /// computation for the others, written to their integrators as well (the first step,
    /// one after an event).
    #[inline(always)]
    fn fresh_jets(
        &mut self,
        rules: &[Option<StepRule<N>>; L],
        valid: &mut [bool; L],
        ends: &mut [Option<Result<LaneEnd<N>, OdeError>>; L],
    ) {
        let mut points = [None; L];
        for (l, lane) in self.lanes.iter().enumerate() {
            let (Lane::Live(ode), Some(rule), false) = (lane, rules[l], valid[l]) else {
                continue;
            };
            let kept = ode.lane_kept_jet();
            if kept.len() > rule.order {
                set_column(&mut self.cur, l, kept);
                valid[l] = true;
            } else {
                points[l] = Some((rule.order, ode.t(), *ode.y()));
            }
        }
        self.batch_jet(&points);
        for (l, point) in points.iter().enumerate() {
            let (Some((p, _, _)), Some(Lane::Live(ode))) = (point, self.lanes.get_mut(l)) else {
                continue;
            };
            match ode.lane_set_jet(*p, |rows| column(&self.next, l, rows)) {
                Ok(()) => {
                    set_column(&mut self.cur, l, ode.lane_kept_jet());
                    valid[l] = true;
                }
                Err(e) => ends[l] = Some(Err(e)),
            }
        }
    }

    /// The jets at `points` (lane l's order, t and y, or `None` for a lane with nothing to
    /// compute) into `self.next`, in one batch computation to the highest order asked (a
    /// lane's lower orders do not depend on the higher ones). A lane without a point takes
    /// the first one's point and system, and is not read; no point, no computation.
    #[inline(always)]
    fn batch_jet(&mut self, points: &[Option<(usize, f64, [f64; N])>; L]) {
        let live = |l: usize| match (self.lanes.get(l), points[l]) {
            (Some(Lane::Live(ode)), Some((_, t, y))) => Some((ode.system(), t, y)),
            _ => None,
        };
        let Some(first) = (0..L).find_map(live) else {
            return;
        };
        let Some(order) = points.iter().flatten().map(|p| p.0).max() else {
            return;
        };
        let at: [(&S, f64, [f64; N]); L] = core::array::from_fn(|l| live(l).unwrap_or(first));
        let t = Lanes(at.map(|a| a.1));
        let y: [Lanes<L>; N] = core::array::from_fn(|i| Lanes(at.map(|a| a.2[i])));
        let Some(rows) = self.next.get_mut(..=order) else {
            return;
        };
        S::lane_coefficients_into(at.map(|a| a.0), &mut self.ws, t, &y, order, rows);
    }
}

/// `rows` into lane `l` of the batch's jet `batch`.
#[inline(always)]
fn set_column<const N: usize, const L: usize>(
    batch: &mut [[Lanes<L>; N]],
    l: usize,
    rows: &[[f64; N]],
) {
    for (lanes, row) in batch.iter_mut().zip(rows) {
        for (lane, v) in lanes.iter_mut().zip(row) {
            lane.0[l] = *v;
        }
    }
}

/// [`BatchTaylor::advance_lanes`] as an operation for `pulp`'s dispatch: its `with_simd`
/// is inlined into the `#[target_feature]` function of each instruction set, and the loop
/// into it (a closure would be called out of line, compiled for the baseline alone).
struct Advance<'b, S: TaylorLanes<N, L>, G, const N: usize, const L: usize> {
    batch: &'b mut BatchTaylor<S, N, L>,
    t_end: [f64; L],
    g: &'b mut G,
}

impl<S, G, const N: usize, const L: usize> pulp::WithSimd for Advance<'_, S, G, N, L>
where
    S: TaylorLanes<N, L>,
    G: FnMut(usize, f64, &[f64; N]) -> f64,
{
    type Output = [Result<LaneEnd<N>, OdeError>; L];

    #[inline(always)]
    fn with_simd<Simd: pulp::Simd>(self, _: Simd) -> Self::Output {
        self.batch.advance_lanes(self.t_end, self.g)
    }
}

/// Lane `l`'s rows of the batch's jet `batch`, into `rows`.
#[inline(always)]
fn column<const N: usize, const L: usize>(
    batch: &[[Lanes<L>; N]],
    l: usize,
    rows: &mut [[f64; N]],
) {
    for (row, lanes) in rows.iter_mut().zip(batch) {
        for (v, lane) in row.iter_mut().zip(lanes) {
            *v = lane.0[l];
        }
    }
}
