//! A Taylor event ([`EventSeries`]) in a [`Run`] of the Taylor integrator: after each step, g's
//! coefficients from the step's jet, the roots of its polynomial isolated ([`isolate`]),
//! and the points between which [`Run`] locates them.

use super::EventSeries;
use super::isolate::{Isolator, Piece};
use crate::ode::{Event, OdeError, Run, StepRoots};
use crate::taylor::{Taylor, TaylorSystem};

/// How far g's Taylor polynomial may be from g at a step's end, in tolerances times the
/// size of the polynomial's terms Σ|gₖ|hᵏ, before the event is refused as not resolved
/// ([`OdeError::EventNotResolved`]). A g that varies like the state is within about one
/// tolerance; 10³ leaves room for a g that amplifies the state's error (a difference of
/// close values) while refusing a g faster than the step (sin 50t on a step of 0.9 is off
/// by 10¹⁶).
pub const EVENT_MISMATCH: f64 = 1e3;

/// The state of one expanded event across a run: the event, its scratch, and the last
/// step's polynomial of g.
struct Expanded<'a, G: EventSeries<N>, const N: usize> {
    event: &'a G,
    ws: G::Workspace,
    /// g₀ … g_p of the last step, and the same scaled to s ∈ [0, 1] (aₖ = gₖ hᵏ).
    g: Vec<f64>,
    scaled: Vec<f64>,
    isolator: Isolator,
    pieces: Vec<Piece>,
    /// The last step's start (t + t_lo) and length.
    start: (f64, f64),
    h: f64,
}

impl<G: EventSeries<N>, const N: usize> Expanded<'_, G, N> {
    /// q(θ(t)), θ(t) = (t − t_start) − t_lo clamped to [0, h] as the dense output has it.
    fn q(&self, t: f64) -> f64 {
        let theta = ((t - self.start.0) - self.start.1).clamp(0.0, self.h);
        self.g.iter().rev().fold(0.0, |acc, &gk| acc * theta + gk)
    }
}

impl<S: TaylorSystem<N>, G: EventSeries<N>, const N: usize> StepRoots<Taylor<S, N>>
    for Expanded<'_, G, N>
{
    fn points(
        &mut self,
        stepper: &Taylor<S, N>,
        index: usize,
        (t_a, _g_a): (f64, f64),
        (t_b, g_b): (f64, f64),
        out: &mut Vec<(f64, f64)>,
    ) -> Result<(), OdeError> {
        let (t, t_lo, h, y, rows) = stepper.last_jet();
        (self.start, self.h) = ((t, t_lo), h);
        let p = rows.len();
        self.g.clear();
        self.g.resize(p + 1, 0.0);
        self.event
            .coefficients_into(&mut self.ws, t, y, rows, &mut self.g);
        if let Some(&value) = self.g.iter().find(|v| !v.is_finite()) {
            return Err(OdeError::NonFiniteEvent { index, t, value });
        }
        // aₖ = gₖ hᵏ: hᵏ by k multiplications and the product, k + 1 roundings at most.
        self.scaled.clear();
        let mut hk = 1.0;
        for &gk in &self.g {
            self.scaled.push(gk * hk);
            hk *= h;
        }
        // The polynomial must be g: at the step's end, where its truncation is largest, it
        // is compared with g evaluated there.
        let end: f64 = self.scaled.iter().sum();
        let size: f64 = self.scaled.iter().map(|a| a.abs()).sum();
        let cfg = stepper.config();
        let limit = EVENT_MISMATCH * cfg.rtol.max(cfg.atol).max(f64::EPSILON) * size;
        let mismatch = (end - g_b).abs();
        if mismatch > limit {
            return Err(OdeError::EventNotResolved {
                index,
                t: t_b,
                mismatch,
                limit,
            });
        }
        self.pieces.clear();
        // No root on the step when a₀ outweighs the other terms with room for the rounding
        // the isolation allows: each Bernstein coefficient is a₀ plus the others weighted by
        // C(j, k)/C(p, k) ≤ 1, so all have a₀'s sign beyond their error bounds and the
        // isolation would return no piece. p additions instead of its p²/2: most steps of a
        // run are far from a root.
        let rest: f64 = self.scaled.iter().skip(1).map(|a| a.abs()).sum();
        let margin = 20.0 * (p + 2) as f64 * f64::EPSILON * size;
        if self.scaled[0].abs() - rest <= margin {
            self.isolator
                .isolate(&self.scaled, (p + 1) as f64, &mut self.pieces);
        }
        // Each piece's ends, as times of the step: outside the pieces q has no root, inside
        // an isolated one exactly one. A piece's end at the step's start or end is the
        // point the run already has there.
        for piece in &self.pieces {
            let (lo, hi) = piece.ends();
            for s in [lo, hi] {
                let ts = (t + (t_lo + s * h)).clamp(t_a, t_b);
                if ts < t_b && out.last().is_none_or(|&(last, _)| ts > last) {
                    let value = self.q(ts);
                    out.push((ts, value));
                }
            }
        }
        out.push((t_b, g_b));
        Ok(())
    }

    fn value(&mut self, index: usize, t: f64) -> Result<f64, OdeError> {
        let value = self.q(t);
        if value.is_finite() {
            Ok(value)
        } else {
            Err(OdeError::NonFiniteEvent { index, t, value })
        }
    }
}

impl<'a, S: TaylorSystem<N>, const N: usize> Run<'a, Taylor<S, N>> {
    /// Adds an event whose function is an expression expanded with each Taylor step
    /// ([`EventSeries`]): the crossings that `event` counts, every root of g's Taylor
    /// polynomial on each step found with a guarantee (isolated by Descartes' rule of signs
    /// on its Bernstein form, not sampled), each located to adjacent doubles on that
    /// polynomial; the hit's state is the step's dense output there. The hits are
    /// [`EventHit`](crate::ode::EventHit)s like any other event's, and terminal events
    /// stop the run the same way. [`Event::step_ends_only`] compares the steps' ends only,
    /// as for [`Run::event`].
    ///
    /// What is guaranteed: every root of q, g's Taylor polynomial of the step's order
    /// along the step, which differs from g on the step's solution by the truncation of
    /// g's series (the step's own error, scaled by g's slope in the state); roots of q
    /// closer than 2⁻⁵⁰ of the step, or where q is within its rounding of 0, count by the
    /// change of sign they make (`docs/trajectories.md`, "Events on Taylor steps"). g is evaluated directly at the steps' ends, where the
    /// run compares signs, so that a step's end and the next step's start agree bit for
    /// bit.
    ///
    /// That the polynomial is g is checked at each step's end, where its truncation is
    /// largest: a g that varies faster than the step resolves is refused with
    /// [`OdeError::EventNotResolved`] by [`Run::integrate`], rather than its polynomial's
    /// roots taken for g's.
    ///
    /// `g` is any [`EventSeries`]: an interpreted [`TaylorEvent`](super::TaylorEvent) (a tape walked at every
    /// step), the compiled type `taylor_system!` emits for an `event Name = …;` statement
    /// (the same recurrences as Rust), or a [`StateEvent`](super::StateEvent) (g = yᵢ, the
    /// jet's column itself).
    ///
    /// Cost per step: g's recurrences to order p (as if g were one more component of the
    /// system), the Bernstein form (p²/2 additions) and, only where a piece is not
    /// decided at once, p²/2 additions per halving.
    ///
    /// # Examples
    /// x = cos t; g = x − cos 0.01 dips below 0 for 0.02 around 2π, inside one step:
    /// ```
    /// use precess_core::ode::{Event, Run};
    /// use precess_core::sym::Arena;
    /// use precess_core::taylor::{Taylor, TaylorConfig, TaylorEvent, TaylorTape};
    /// let mut a = Arena::new();
    /// let (x, v) = (a.coordinate("x"), a.coordinate("v"));
    /// let minus_x = a.neg(x);
    /// let system = TaylorTape::new(&a, [x, v], [v, minus_x], None, &[], 30)?;
    /// let level = a.parameter("level");
    /// let g = a.sub(x, level);
    /// let event = TaylorEvent::new(&a, [x, v], None, g, &[("level", 0.01f64.cos())])?;
    /// let mut ode = Taylor::new(system, 0.0, [1.0, 0.0], TaylorConfig::with_tol(1e-14, 1e-14))?;
    /// let out = Run::new(&mut ode, 7.0).taylor_event(Event::new("dip"), &event).integrate()?;
    /// let times: Vec<f64> = out.events.iter().map(|h| h.t).collect();
    /// let pi2 = 2.0 * std::f64::consts::PI;
    /// assert_eq!(times.len(), 3);
    /// for (t, exact) in times.iter().zip([0.01, pi2 - 0.01, pi2 + 0.01]) {
    ///     assert!((t - exact).abs() < 1e-10, "{t} against {exact}");
    /// }
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn taylor_event<G: EventSeries<N>>(self, event: Event, g: &'a G) -> Self {
        let mut ws = G::Workspace::default();
        let value = move |t: f64, y: &[f64; N]| g.value(&mut ws, t, y);
        let roots = Expanded {
            event: g,
            ws: G::Workspace::default(),
            g: Vec::new(),
            scaled: Vec::new(),
            isolator: Isolator::default(),
            pieces: Vec::new(),
            start: (0.0, 0.0),
            h: 0.0,
        };
        self.event_with_roots(event, value, Box::new(roots))
    }
}
