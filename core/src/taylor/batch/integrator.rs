//! [`BatchTaylor`]: `L` Taylor integrations stepped together, their jets computed in lanes
//! and everything else (order, step size, sum, events) lane by lane with the scalar code.

use super::{Lanes, TaylorLanes};
use crate::ode::{OdeError, check_stop};
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
/// that the compiler vectorises), then each lane sizes its own step from its own
/// coefficients, sums it and checks its event with the scalar integrator's code.
///
/// **Bitwise equal to scalar runs.** A lane is a [`Taylor`] whose jets come from the batch;
/// since a lane's coefficients are the scalar ones bit for bit ([`TaylorLanes`]), every lane
/// takes the steps of a scalar [`Taylor`] run of the same system, start and configuration,
/// and ends on the same bits.
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
    /// The batch's jet, orders 0 … the highest order any lane may use.
    coeffs: Vec<[Lanes<L>; N]>,
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
            coeffs: vec![[Lanes::splat(0.0); N]; rows + 1],
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
        let mut ends: [Option<Result<LaneEnd<N>, OdeError>>; L] = core::array::from_fn(|_| None);
        let mut g_last = [0.0f64; L];
        for (l, lane) in self.lanes.iter().enumerate() {
            match lane {
                Lane::Live(ode) => match check_stop(ode.t(), t_end[l])
                    .and_then(|()| event_value(&mut g, l, ode.t(), ode.y()))
                {
                    Ok(v) => g_last[l] = v,
                    Err(e) => ends[l] = Some(Err(e)),
                },
                Lane::Failed(e) => ends[l] = Some(Err(e.clone())),
            }
        }
        let mut orders = [None::<usize>; L];
        loop {
            // The order each active lane needs, or its end.
            for (l, lane) in self.lanes.iter().enumerate() {
                orders[l] = None;
                if ends[l].is_some() {
                    continue;
                }
                let Lane::Live(ode) = lane else { continue };
                match ode.lane_order(t_end[l]) {
                    Ok(Some(p)) => orders[l] = Some(p),
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
            let Some(order) = orders.iter().flatten().copied().max() else {
                break;
            };
            self.batch_jet(&orders, order);
            for l in 0..L {
                if orders[l].is_none() {
                    continue;
                }
                let Some(Lane::Live(ode)) = self.lanes.get_mut(l) else {
                    continue;
                };
                let coeffs = &self.coeffs;
                let stepped = ode.lane_step(t_end[l], |rows| {
                    for (row, batch) in rows.iter_mut().zip(coeffs) {
                        for (v, lanes) in row.iter_mut().zip(batch) {
                            *v = lanes.0[l];
                        }
                    }
                });
                let end = stepped.and_then(|()| event_step(ode, l, &mut g, &mut g_last[l]));
                match end {
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

    /// The jets of every lane to `order` into `self.coeffs`; the lanes without an order
    /// (finished or failed) take the first active lane's point and system, and are not read.
    fn batch_jet(&mut self, orders: &[Option<usize>; L], order: usize) {
        let live = |l: usize| match self.lanes.get(l) {
            Some(Lane::Live(ode)) if orders[l].is_some() => Some(ode),
            _ => None,
        };
        let Some(first) = (0..L).find_map(live) else {
            return;
        };
        let odes: [&Taylor<S, N>; L] = core::array::from_fn(|l| live(l).unwrap_or(first));
        let systems = odes.map(Taylor::system);
        let t = Lanes(odes.map(Taylor::t));
        let y: [Lanes<L>; N] = core::array::from_fn(|i| Lanes(odes.map(|o| o.y()[i])));
        let Some(rows) = self.coeffs.get_mut(..=order) else {
            return;
        };
        S::lane_coefficients_into(systems, &mut self.ws, t, &y, order, rows);
    }
}

/// g at a lane's point, checked finite.
fn event_value<const N: usize>(
    g: &mut impl FnMut(usize, f64, &[f64; N]) -> f64,
    l: usize,
    t: f64,
    y: &[f64; N],
) -> Result<f64, OdeError> {
    let v = g(l, t, y);
    if v.is_finite() {
        Ok(v)
    } else {
        Err(OdeError::NonFiniteEvent {
            index: 0,
            t,
            value: v,
        })
    }
}

/// After a lane's step: the lane's end if its event changed sign in the step (the lane put
/// at the root), else `None`; `g_last` follows the step.
fn event_step<S: TaylorLanes<N, L>, const N: usize, const L: usize>(
    ode: &mut Taylor<S, N>,
    l: usize,
    g: &mut impl FnMut(usize, f64, &[f64; N]) -> f64,
    g_last: &mut f64,
) -> Result<Option<LaneEnd<N>>, OdeError> {
    let (t_a, t_b) = (ode.last_step_start(), ode.t());
    let g_b = event_value(g, l, t_b, ode.y())?;
    let g_a = *g_last;
    *g_last = g_b;
    if g_a == 0.0 {
        // A start on g = 0: the sign to leave from is the first one g takes.
        return Ok(None);
    }
    if (g_a < 0.0) == (g_b < 0.0) && g_b != 0.0 {
        return Ok(None);
    }
    // Bisection with the secant (Illinois), on the step polynomial: [lo, hi] brackets the
    // root, g(lo) has g_a's sign.
    let (mut lo, mut hi, mut g_lo, mut g_hi) = (t_a, t_b, g_a, g_b);
    let mut side = 0i8;
    for _ in 0..200 {
        if g_hi == 0.0 {
            break;
        }
        let secant = hi - g_hi * (hi - lo) / (g_hi - g_lo);
        let mid = 0.5 * (lo + hi);
        let t = if secant > lo && secant < hi {
            secant
        } else {
            mid
        };
        if t <= lo || t >= hi {
            break;
        }
        let v = event_value(g, l, t, &ode.dense_at(t)?)?;
        if (v < 0.0) == (g_lo < 0.0) && v != 0.0 {
            (lo, g_lo) = (t, v);
            if side == -1 {
                g_hi *= 0.5;
            }
            side = -1;
        } else {
            (hi, g_hi) = (t, v);
            if side == 1 {
                g_lo *= 0.5;
            }
            side = 1;
        }
    }
    let y = ode.dense_at(hi)?;
    ode.reset_state(hi, y);
    Ok(Some(LaneEnd {
        t: hi,
        y,
        event: true,
    }))
}
