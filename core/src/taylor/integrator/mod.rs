//! The adaptive Taylor integrator: each step computes the normalised Taylor coefficients of
//! the solution at the step's start (a [`TaylorSystem`]), chooses order and step from the
//! tolerance by the Jorba–Zou rules, and sums the step polynomial.
//!
//! - Order p = ⌈1 − ½ ln ε⌉ and step h = e⁻²·e^(−0.7/(p−1))·ρ, ρ the radius of convergence
//!   estimated from the last rows of coefficients that do not vanish, each component measured
//!   against its own scale sᵢ (|yᵢ| in the relative mode, with atol/rtol as a floor, and 1 in
//!   the absolute one; see [`TaylorConfig`] and the `radius` module). The estimate comes
//!   before the step, from the coefficients the step needs anyway.
//! - After the sum, the step polynomial is compared with the jet at the step's end, which is
//!   the next step's jet, computed once (the `defect` module): its rows d₁ = f(y_p(h)) and
//!   d₂ against y_p′(h) and y_p″(h)/2. A step whose rows of order ≤ p missed what the rows
//!   past p hold is taken again, shorter, from the same jet, and counted in
//!   [`Stats::rejections`]. An ordinary step passes and keeps its bits, and the check costs
//!   two Horner chains beside the step's own.
//! - The estimate never trusts a vanishing coefficient: rows that are zero are skipped, rows
//!   that are tiny are bounded by the rows below them, a jet that vanishes to its order is
//!   computed again to the highest order allowed, and a step grows at most tenfold over the
//!   last natural one.
//! - The step polynomial Σ c_k θᵏ is summed by Horner for the increment, and the increment is
//!   added to the state with Kahan's compensated summation, the time too: rounding does not
//!   gather over millions of steps.
//! - Dense output inside the last step is the same polynomial at θ = t − t_start: no extra
//!   evaluation, the accuracy of the step itself. Events of [`Run`](crate::ode::Run) are
//!   located on it.

mod config;
mod defect;
mod drivers;
mod extended;
mod lane_control;
mod lanes;
mod order;
mod radius;

pub use config::{StepScale, TaylorConfig};
pub use drivers::{solve, solve_dense};
pub(crate) use lanes::PendingStep;
pub use order::OrderRule;

use super::TaylorSystem;
use crate::exact::Dd;
use crate::ode::{OdeError, Stats, check_finite, check_stop};

/// An adaptive Taylor integrator of a [`TaylorSystem`] `S` of dimension `N`.
///
/// Owns its coefficient storage (allocated once, for the highest order the tolerances can
/// ask) and the system's [`TaylorSystem::Workspace`], so stepping never allocates. It implements [`Stepper`](crate::ode::Stepper):
/// [`Run`](crate::ode::Run) gives it samples, trajectories and events.
///
/// [`Stats::rhs_evals`] counts each computation of the coefficients to order p (a *jet*) as
/// p right-hand-side evaluations, so that work counts compare with the Runge–Kutta pairs'
/// (the jet at a step's end that the defect check reads, [`TaylorConfig::defect_check`], is
/// the next step's, counted once; where it is not kept, the lanes and the extended mode, the
/// check's jet of order 2 counts as 2); [`Taylor::jets`] counts the jets themselves. The recurrence of a product costs k + 1
/// multiply-adds at order k, so a jet costs about p²/2 products per product of f while its
/// linear parts cost p; the measured ratio (jet time over one evaluation of f, both
/// hand-written, on B5) is in `docs/taylor-integrator.md`, with the command that measures it.
///
/// ```
/// use precess_core::taylor::{Taylor, TaylorConfig, TaylorSystem};
/// /// y' = −y: c_k = (−1)ᵏ y/k!.
/// struct Decay;
/// impl TaylorSystem<1> for Decay {
///     fn max_order(&self) -> usize { 40 }
///     type Workspace = ();
///     fn coefficients_into(&self, _ws: &mut (), _t: f64, y: &[f64; 1], order: usize, c: &mut [[f64; 1]]) {
///         c[0] = *y;
///         for k in 1..=order {
///             c[k][0] = -c[k - 1][0] / k as f64;
///         }
///     }
/// }
/// let mut ode = Taylor::new(Decay, 0.0, [1.0], TaylorConfig::with_tol(1e-15, 1e-15))?;
/// ode.advance_to(10.0)?;
/// approx::assert_relative_eq!(ode.y()[0], (-10.0f64).exp(), max_relative = 1e-14);
/// # Ok::<(), precess_core::ode::OdeError>(())
/// ```
#[derive(Debug, Clone)]
pub struct Taylor<S: TaylorSystem<N>, const N: usize> {
    sys: S,
    cfg: TaylorConfig,
    /// Order and step factor of the relative mode ([0], ε = rtol) and of the absolute one
    /// ([1], ε = atol): fixed by the configuration, so computed once, not per step (they
    /// cost a logarithm and two exponentials).
    rules: [(usize, f64); 2],
    /// Time as an unevaluated sum t + t_lo.
    t: f64,
    t_lo: f64,
    y: [f64; N],
    /// Kahan compensation of y: the rounding of the last additions, to subtract next time.
    y_comp: [f64; N],
    /// c_k of the last step, k = 0, …, `last_order`.
    coeffs: Vec<[f64; N]>,
    /// The jet at the current state to order `ahead_order` (0: none), computed by the defect
    /// check of the step that ended here: the next step's jet, swapped into `coeffs`.
    ahead: Vec<[f64; N]>,
    ahead_order: usize,
    /// The system's scratch, kept across steps so that a jet neither allocates nor zeroes.
    ws: S::Workspace,
    /// The double-double coefficients of the extended mode, orders 0 … L (empty when off).
    low: Vec<[Dd; N]>,
    last: LastStep<N>,
    /// The highest order a step may use: `max_order` capped by the system's. A jet that
    /// vanishes at the rule's order is computed again to this one.
    top_order: usize,
    /// The last step that was not shortened to land on a stop (+∞ before the first and
    /// after a restart): the next step is at most [`GROWTH`] times it.
    prev_natural: f64,
    /// Steps taken towards `run_target`, the stop of the current run: the budget
    /// [`TaylorConfig::max_steps`] counts these, not the integrator's whole life.
    run_steps: u64,
    run_target: f64,
    stats: Stats,
    jets: u64,
}

/// How much a step may grow over the last natural one: a radius estimated from a jet whose
/// top rows are nearly zero is not taken on trust, while a smooth run, whose steps change by
/// a few per cent, never meets the bound.
const GROWTH: f64 = 10.0;

/// What the dense output needs of the last step.
#[derive(Debug, Clone, Copy)]
struct LastStep<const N: usize> {
    t: f64,
    t_lo: f64,
    y: [f64; N],
    y_comp: [f64; N],
    h: f64,
    order: usize,
}

/// What a step's mode fixes before its jet: the order, the step factor, the mode's ε, and
/// the weight of each component, wᵢ = 1/sᵢ (see [`Taylor::step_rule`]).
#[derive(Clone, Copy)]
pub(crate) struct StepRule<const N: usize> {
    pub(crate) order: usize,
    factor: f64,
    eps: f64,
    weights: [f64; N],
}

impl<S: TaylorSystem<N>, const N: usize> Taylor<S, N> {
    /// Starts at `(t0, y0)`; validates everything before any work.
    ///
    /// # Errors
    /// An invalid configuration ([`TaylorConfig::validate`]), a system whose
    /// [`TaylorSystem::max_order`] is below 2 ([`OdeError::InvalidParameter`] naming
    /// `TaylorSystem::max_order`), a fixed [`TaylorConfig::order`] above that maximum
    /// ([`OdeError::TaylorOrderTooHigh`]), the extended mode asked of a system that does not
    /// implement it ([`OdeError::NoExtendedCoefficients`]), a
    /// non-finite `t0` ([`OdeError::NonFiniteTime`]) or `y0`
    /// ([`OdeError::NonFiniteInitialState`]), the system's own refusal of its parameters
    /// ([`TaylorSystem::check_parameters`]).
    pub fn new(sys: S, t0: f64, y0: [f64; N], cfg: TaylorConfig) -> Result<Self, OdeError> {
        cfg.validate()?;
        if !t0.is_finite() {
            return Err(OdeError::NonFiniteTime { t: t0 });
        }
        check_finite(&y0)?;
        sys.check_parameters()?;
        let system_max = sys.max_order();
        if system_max < 2 {
            return Err(OdeError::InvalidParameter {
                name: "TaylorSystem::max_order",
                value: system_max as f64,
            });
        }
        if let Some(order) = cfg.order
            && order > system_max
        {
            return Err(OdeError::TaylorOrderTooHigh {
                order,
                cap: system_max,
                limit: "TaylorSystem::max_order",
            });
        }
        let rule = |eps: f64| {
            let p = cfg.order_for(eps, system_max, N);
            (
                p,
                TaylorConfig::step_factor(eps, p, cfg.effective_order_rule()),
            )
        };
        let rules = [rule(cfg.rtol), rule(cfg.atol)];
        let top_order = cfg.max_order.min(system_max);
        let mut ws = S::Workspace::default();
        let low = match cfg.extended {
            Some(l) => extended::low_table(&sys, &mut ws, l, t0, &y0)?,
            None => Vec::new(),
        };
        Ok(Self {
            sys,
            cfg,
            rules,
            t: t0,
            t_lo: 0.0,
            y: y0,
            y_comp: [0.0; N],
            coeffs: vec![[0.0; N]; top_order + 1],
            ahead: vec![[0.0; N]; top_order + 1],
            ahead_order: 0,
            ws,
            low,
            last: LastStep {
                t: t0,
                t_lo: 0.0,
                y: y0,
                y_comp: [0.0; N],
                h: 0.0,
                order: 0,
            },
            top_order,
            prev_natural: f64::INFINITY,
            run_steps: 0,
            run_target: f64::NAN,
            stats: Stats::default(),
            jets: 0,
        })
    }

    crate::ode::state_accessors!(N, #[doc = "A jet of order p counts as p evaluations."]);

    /// Computations of the Taylor coefficients so far (one per step).
    pub fn jets(&self) -> u64 {
        self.jets
    }

    /// The system being integrated.
    pub fn system(&self) -> &S {
        &self.sys
    }

    /// The configuration.
    pub fn config(&self) -> &TaylorConfig {
        &self.cfg
    }

    /// Order and size of the last step (`(0, 0.0)` before any step and after a restart).
    pub fn last_step(&self) -> (usize, f64) {
        (self.last.order, self.last.h)
    }

    /// Start of the last step: dense output covers `[last_step_start, t]`.
    pub fn last_step_start(&self) -> f64 {
        self.last.t
    }

    /// The last step's polynomial, for the events expanded along it: its start as
    /// t + t_lo, its length h, the state y at its start and the rows c₁ … c_p (empty before
    /// any step and after a restart). The dense output is y + Σ cₖ θᵏ at
    /// θ = (t′ − t) − t_lo.
    pub(crate) fn last_jet(&self) -> (f64, f64, f64, &[f64; N], &[[f64; N]]) {
        let p = self.last.order;
        let rows = self.coeffs.get(1..=p).unwrap_or(&[]);
        (self.last.t, self.last.t_lo, self.last.h, &self.last.y, rows)
    }

    /// The system, to be changed between steps by a hybrid run (which restarts the
    /// integrator at once); the jet computed ahead with the old system is dropped.
    pub(crate) fn system_mut(&mut self) -> &mut S {
        self.ahead_order = 0;
        &mut self.sys
    }

    /// [`TaylorSystem::check_parameters`] of the integrator's system, for a restart.
    pub(crate) fn check_system(&self) -> Result<(), OdeError> {
        self.sys.check_parameters()
    }

    /// Puts the integrator at `(t, y)` (the caller checks the values): no dense output
    /// before it, compensations cleared, a new run (its step budget and the bound on the
    /// step's growth start afresh).
    pub(crate) fn reset_state(&mut self, t: f64, y: [f64; N]) {
        (self.t, self.t_lo, self.y, self.y_comp) = (t, 0.0, y, [0.0; N]);
        (self.prev_natural, self.run_steps, self.run_target) = (f64::INFINITY, 0, f64::NAN);
        self.ahead_order = 0;
        self.last = LastStep {
            t,
            t_lo: 0.0,
            y,
            y_comp: [0.0; N],
            h: 0.0,
            order: 0,
        };
    }

    /// Takes one step that does not pass `t_limit`, landing on it exactly when the natural
    /// step would reach it.
    ///
    /// # Errors
    /// [`OdeError::NonFiniteTime`] for a NaN or infinite `t_limit`,
    /// [`OdeError::StopBeforeCurrent`] if `t_limit < t`, [`OdeError::MaxStepsExceeded`]
    /// after [`TaylorConfig::max_steps`] steps towards the same `t_limit` (a restart or
    /// another limit starts the count again), [`OdeError::NonFiniteState`] for non-finite
    /// coefficients or state, [`OdeError::StepSizeUnderflow`] when the step no longer
    /// changes t. The state is left as it was on error.
    pub fn step(&mut self, t_limit: f64) -> Result<(), OdeError> {
        if !self.low.is_empty() {
            return self.step_extended(t_limit);
        }
        let Some(rule) = self.step_rule(t_limit)? else {
            return Ok(());
        };
        if self.ahead_order >= rule.order {
            // The jet the last step's check computed here: its rows 0 … p are those of a
            // jet of order p, bit for bit (an order reads only the orders below it).
            std::mem::swap(&mut self.coeffs, &mut self.ahead);
            self.ahead_order = 0;
        } else {
            self.ahead_order = 0;
            self.jet(rule.order)?;
        }
        self.finish_step(rule, t_limit, true)
    }

    /// The step after its jet of order `rule.order`: the jet again at the top order if it
    /// vanishes, the step size, the sum, the defect check (against the next step's jet,
    /// kept when `keep_ahead`, or a jet of order 2 at the step's end) and the commit.
    fn finish_step(
        &mut self,
        rule: StepRule<N>,
        t_limit: f64,
        keep_ahead: bool,
    ) -> Result<(), OdeError> {
        let (rule, h, clamped) = self.size_step(rule, t_limit)?;
        if !self.cfg.defect_check || self.cfg.fixed_step.is_some() {
            return self.commit_unchecked(rule.order, h, clamped, t_limit);
        }
        self.checked_steps(rule, h, clamped, t_limit, keep_ahead)
    }

    /// The rule (its order raised to the top one, and the jet computed again there, if the
    /// jet vanishes) and the step size and whether it was clamped to land on `t_limit`.
    fn size_step(
        &mut self,
        mut rule: StepRule<N>,
        t_limit: f64,
    ) -> Result<(StepRule<N>, f64, bool), OdeError> {
        if self.cfg.fixed_step.is_none()
            && rule.order < self.top_order
            && radius::vanishes(&self.coeffs[..=rule.order])
        {
            // Orders 1 … p all zero say nothing of the step (x' = tᵐ y at t = 0 for m ≥ p):
            // ask the system for every order it allows before taking the jet as constant.
            rule.order = self.top_order;
            rule.factor =
                TaylorConfig::step_factor(rule.eps, rule.order, self.cfg.effective_order_rule());
            self.jet(rule.order)?;
        }
        // No scan of every coefficient for finiteness: a NaN or ∞ in c_1 … c_p reaches the
        // new state through Horner (h > 0), which is checked in `commit_step`, and an ∞ in
        // the rows the step size reads is caught by `radius::radius`.
        let (h, clamped) = self.step_size(&self.coeffs[..=rule.order], rule, t_limit)?;
        Ok((rule, h, clamped))
    }

    /// The step of `h` summed from the jet of order `p` and committed, without a check.
    fn commit_unchecked(
        &mut self,
        p: usize,
        h: f64,
        clamped: bool,
        t_limit: f64,
    ) -> Result<(), OdeError> {
        let increment = horner_increment(&self.coeffs[..=p], h);
        let (y_new, comp_new) = kahan_add(self.y, self.y_comp, increment);
        self.commit_step(h, p, clamped, t_limit, y_new, comp_new)
    }

    /// The step of `h` summed, checked, taken again shorter from the same jet until the
    /// check passes, and committed.
    fn checked_steps(
        &mut self,
        rule: StepRule<N>,
        mut h: f64,
        mut clamped: bool,
        t_limit: f64,
        keep_ahead: bool,
    ) -> Result<(), OdeError> {
        let p = rule.order;
        loop {
            let (increment, slope) = defect::increment_and_slope(&self.coeffs[..=p], h);
            let (y_new, comp_new) = kahan_add(self.y, self.y_comp, increment);
            let t_new = self.advanced(h, clamped, t_limit).0;
            match self.checked(t_new, &y_new, &slope, &rule, keep_ahead)? {
                Some(shorter) => (h, clamped) = (shorter, false),
                None => return self.commit_step(h, p, clamped, t_limit, y_new, comp_new),
            }
        }
    }

    /// The defect check of a step summed to `y_new` at `t_new`, its polynomial re-expanded
    /// at its end `slope` (the `defect` module), in both modes: `None` to keep the step, or
    /// the shorter step to take again from the same jet (counted as a rejection). With
    /// `keep_ahead` the jet at the end is the next step's, to its order, kept in `ahead`;
    /// otherwise a jet of order 2. Off with [`TaylorConfig::defect_check`]; a fixed step is
    /// the caller's choice and is not checked.
    ///
    /// # Errors
    /// [`OdeError::StepSizeUnderflow`] when the shorter step no longer changes t.
    fn checked(
        &mut self,
        t_new: f64,
        y_new: &[f64; N],
        slope: &defect::Slope<N>,
        rule: &StepRule<N>,
        keep_ahead: bool,
    ) -> Result<Option<f64>, OdeError> {
        // A non-finite new state (a NaN or ∞ in the jet) is the commit's to refuse, as
        // `NonFiniteState`: no shorter step from the same jet can mend it.
        if !self.cfg.defect_check
            || self.cfg.fixed_step.is_some()
            || y_new.iter().any(|v| !v.is_finite())
        {
            return Ok(None);
        }
        let shorter = if keep_ahead {
            let q = self.next_order(y_new);
            let rows = rows_to_order(&mut self.ahead, q)?;
            self.sys
                .coefficients_into(&mut self.ws, t_new, y_new, q, rows);
            self.judge_ahead(q, slope, rule)
        } else {
            let rows = defect::end_rows(&self.sys, &mut self.ws, t_new, y_new);
            self.stats.rhs_evals += defect::ORDER as u64;
            let c = self.coeffs.get(..=rule.order).unwrap_or(&[]);
            defect::shorter_step(c, slope, &rows[1..], &rule.weights, rule.eps)
        };
        self.cut(shorter)
    }

    /// The order the next step's rule gives at `y` (`step_rule`'s mode test): that of the
    /// jet a check computes at a step's end and keeps.
    fn next_order(&self, y: &[f64; N]) -> usize {
        let relative = self.cfg.rtol * max_abs(y) > self.cfg.atol;
        self.rules[usize::from(!relative)].0
    }

    /// The defect check against the jet at the step's end, of order `q`, just written into
    /// `ahead` (counted here as the jet it is, and kept as the next step's).
    fn judge_ahead(
        &mut self,
        q: usize,
        slope: &defect::Slope<N>,
        rule: &StepRule<N>,
    ) -> Option<f64> {
        self.jets += 1;
        self.stats.rhs_evals += q as u64;
        self.ahead_order = q;
        let d = self.ahead.get(1..=q.min(defect::ORDER)).unwrap_or(&[]);
        let c = self.coeffs.get(..=rule.order).unwrap_or(&[]);
        defect::shorter_step(c, slope, d, &rule.weights, rule.eps)
    }

    /// A check's verdict: `shorter` passed on, a rejection counted and its jet ahead
    /// dropped, or [`OdeError::StepSizeUnderflow`] when the shorter step no longer changes t.
    fn cut(&mut self, shorter: Option<f64>) -> Result<Option<f64>, OdeError> {
        if let Some(h) = shorter {
            self.ahead_order = 0;
            self.stats.rejections += 1;
            if self.t + h == self.t {
                return Err(OdeError::StepSizeUnderflow { t: self.t, h });
            }
        }
        Ok(shorter)
    }

    /// The coefficients of orders 0 … `order` at the current point, into `self.coeffs`.
    fn jet(&mut self, order: usize) -> Result<(), OdeError> {
        let c = rows_to_order(&mut self.coeffs, order)?;
        self.sys
            .coefficients_into(&mut self.ws, self.t, &self.y, order, c);
        self.jets += 1;
        self.stats.rhs_evals += order as u64;
        Ok(())
    }

    /// The start of a step, shared by both modes: the stop checks and the step budget, then
    /// the order, the step factor and the weights of the step's mode; `None` when `t_limit`
    /// is the current time (nothing to do).
    ///
    /// The mode is relative, ε = rtol, when rtol·‖y‖∞ > atol, and absolute, ε = atol,
    /// otherwise; ε gives the order. Each component is then served at its own tolerance
    /// max(rtol·|yᵢ|, atol) = ε·sᵢ: sᵢ = max(|yᵢ|, atol/rtol) in the relative mode and 1 in
    /// the absolute one (where rtol·|yᵢ| ≤ atol for every i). The pairs weigh by
    /// atol + rtol·|yᵢ|, within a factor 2 of this; with one component, or all of one size,
    /// it is the ‖y‖∞ scale of heyoka and TIDES.
    fn step_rule(&self, t_limit: f64) -> Result<Option<StepRule<N>>, OdeError> {
        check_stop(self.t, t_limit)?;
        if t_limit == self.t {
            return Ok(None);
        }
        if t_limit == self.run_target && self.run_steps >= self.cfg.max_steps {
            return Err(OdeError::MaxStepsExceeded {
                t: self.t,
                max_steps: self.cfg.max_steps,
            });
        }
        let norm = max_abs(&self.y);
        let relative = self.cfg.rtol * norm > self.cfg.atol;
        let (order, factor) = self.rules[usize::from(!relative)];
        let (eps, weights) = if relative {
            // The floor keeps a component crossing zero at the absolute tolerance (and a
            // weight finite when atol/rtol underflows).
            let floor = (self.cfg.atol / self.cfg.rtol).max(f64::MIN_POSITIVE);
            let weights = match self.cfg.scale {
                StepScale::Componentwise => self.y.map(|v| 1.0 / v.abs().max(floor)),
                StepScale::MaxNorm => [1.0 / norm.max(floor); N],
            };
            (self.cfg.rtol, weights)
        } else {
            (self.cfg.atol, [1.0; N])
        };
        Ok(Some(StepRule {
            order,
            factor,
            eps,
            weights,
        }))
    }

    /// The step from the coefficients `c` (orders 0 … p) under `rule`, and whether it was
    /// clamped to land on `t_limit`.
    fn step_size(
        &self,
        c: &[[f64; N]],
        rule: StepRule<N>,
        t_limit: f64,
    ) -> Result<(f64, bool), OdeError> {
        let natural = match self.cfg.fixed_step {
            Some(h) => h,
            None => {
                let Some(rho) = radius::radius(c, &rule.weights) else {
                    return Err(OdeError::NonFiniteState { t: self.t });
                };
                (rule.factor * rho).min(GROWTH * self.prev_natural)
            }
        }
        .min(self.cfg.h_max);
        if natural.is_nan() {
            return Err(OdeError::NonFiniteState { t: self.t });
        }
        let remaining = (t_limit - self.t) - self.t_lo;
        let clamped = natural >= remaining;
        let h = if clamped { remaining } else { natural };
        if h <= 0.0 || (!clamped && self.t + h == self.t) {
            return Err(OdeError::StepSizeUnderflow { t: self.t, h });
        }
        Ok((h, clamped))
    }

    /// The end of a step, shared by both modes: checks the new state (y_new with its Kahan
    /// term), keeps the step for dense output, and advances the time as a two-sum.
    fn commit_step(
        &mut self,
        h: f64,
        order: usize,
        clamped: bool,
        t_limit: f64,
        y_new: [f64; N],
        comp_new: [f64; N],
    ) -> Result<(), OdeError> {
        if y_new.iter().any(|v| !v.is_finite()) {
            return Err(OdeError::NonFiniteState { t: self.t });
        }
        self.last = LastStep {
            t: self.t,
            t_lo: self.t_lo,
            y: self.y,
            y_comp: self.y_comp,
            h,
            order,
        };
        (self.t, self.t_lo) = self.advanced(h, clamped, t_limit);
        self.y = y_new;
        self.y_comp = comp_new;
        self.stats.steps += 1;
        if !clamped {
            self.prev_natural = h;
        }
        if t_limit != self.run_target {
            (self.run_target, self.run_steps) = (t_limit, 0);
        }
        self.run_steps += 1;
        Ok(())
    }

    /// The time after a step of `h` as t + t_lo: `t_limit` when the step was clamped to land
    /// on it, else the two-sum of t + h with its rounding kept in t_lo.
    fn advanced(&self, h: f64, clamped: bool, t_limit: f64) -> (f64, f64) {
        if clamped {
            return (t_limit, 0.0);
        }
        let s = self.t + h;
        let b = s - self.t;
        let err = (self.t - (s - b)) + (h - b);
        let lo = self.t_lo + err;
        let hi = s + lo;
        (hi, lo - (hi - s))
    }

    /// Steps until `t == t_stop` exactly; no step crosses `t_stop`. The steps towards one
    /// `t_stop` are a run for [`TaylorConfig::max_steps`]: another call with another stop
    /// has a budget of its own.
    ///
    /// # Errors
    /// As [`Taylor::step`].
    pub fn advance_to(&mut self, t_stop: f64) -> Result<(), OdeError> {
        check_stop(self.t, t_stop)?;
        while self.t < t_stop {
            self.step(t_stop)?;
        }
        Ok(())
    }

    /// The solution at `t` inside the last step, from the step's own polynomial (no
    /// evaluation of the system).
    ///
    /// # Errors
    /// [`OdeError::NonFiniteTime`], [`OdeError::OutsideLastStep`].
    pub fn dense_at(&self, t: f64) -> Result<[f64; N], OdeError> {
        if !t.is_finite() {
            return Err(OdeError::NonFiniteTime { t });
        }
        if !(t >= self.last.t && t <= self.t) {
            return Err(OdeError::OutsideLastStep {
                t,
                t_prev: self.last.t,
                t_now: self.t,
            });
        }
        if t == self.t || self.last.order == 0 {
            return Ok(self.y);
        }
        let theta = ((t - self.last.t) - self.last.t_lo).clamp(0.0, self.last.h);
        let p = self.last.order;
        let mut out = self.last.y;
        if let Some(c) = self.coeffs.get(..=p) {
            let increment = horner_increment(c, theta);
            for ((o, inc), comp) in out.iter_mut().zip(increment).zip(self.last.y_comp) {
                *o += inc - comp;
            }
        }
        Ok(out)
    }
}

/// The coefficient rows of orders 0 … p. The rows are allocated at construction for the
/// highest order either mode can pick, so this fails only if that invariant breaks.
fn rows_to_order<const N: usize>(
    coeffs: &mut [[f64; N]],
    p: usize,
) -> Result<&mut [[f64; N]], OdeError> {
    coeffs.get_mut(..=p).ok_or(OdeError::InvalidParameter {
        name: "order",
        value: p as f64,
    })
}

/// ‖y‖∞ of a state. NaN entries are skipped (`f64::max`).
fn max_abs<const N: usize>(c: &[f64; N]) -> f64 {
    c.iter().fold(0.0f64, |m, v| m.max(v.abs()))
}

/// Σ_{k=1}^{p} c_k θᵏ for every component (p = c.len() − 1 ≥ 1), by Horner with the order in
/// the outer loop: the N components are N independent chains of multiply-adds that overlap,
/// where a loop over components outside would wait on each chain in turn. Each component's
/// operations are the same, in the same order, as its own Horner sum.
fn horner_increment<const N: usize>(c: &[[f64; N]], theta: f64) -> [f64; N] {
    let Some((top, lower)) = c.split_last() else {
        return [0.0; N];
    };
    let mut s = *top;
    for ck in lower.iter().skip(1).rev() {
        for (si, cki) in s.iter_mut().zip(ck) {
            *si = *si * theta + cki;
        }
    }
    s.map(|si| si * theta)
}

/// y + increment with Kahan's compensated summation: returns the new state and the rounding
/// of each addition, which the next addition subtracts.
fn kahan_add<const N: usize>(
    mut y: [f64; N],
    mut comp: [f64; N],
    increment: [f64; N],
) -> ([f64; N], [f64; N]) {
    for ((yi, ci), inc) in y.iter_mut().zip(comp.iter_mut()).zip(increment) {
        let inc = inc - *ci;
        let sum = *yi + inc;
        *ci = (sum - *yi) - inc;
        *yi = sum;
    }
    (y, comp)
}
