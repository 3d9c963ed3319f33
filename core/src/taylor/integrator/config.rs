//! The settings of the Taylor integrator and the rules that turn a tolerance into an order and
//! a step (the orders themselves: `order.rs`).

use super::order::{self, OrderRule};
use crate::ode::{OdeError, check_tolerances};
use crate::taylor::MAX_TAYLOR_ORDER;

/// Settings of [`Taylor`](super::Taylor). Every field has a documented default
/// (`TaylorConfig::default()`), so callers override only what they mean.
///
/// The tolerances serve each component as the pairs' do: component i is held to
/// max(rtol·|yᵢ|, atol), so a large component (a position of 10⁵ m) does not loosen a small
/// one (an angular velocity of 1 rad/s). The order comes from one ε per step, as in heyoka
/// and TIDES: the step is in the relative mode, ε = `rtol`, when `rtol·‖y‖∞ > atol`, and in
/// the absolute mode, ε = `atol`, otherwise, and each component's coefficients are measured
/// against its own scale max(|yᵢ|, atol/rtol), resp. 1, so that ε times the scale is the
/// component's tolerance. The mode's ε gives the order, by default the order of least
/// modelled work per unit time ([`OrderRule::MinimumWork`], about 1.5 times Jorba and Zou's
/// p = ⌈1 − ½ ln ε⌉, which [`OrderRule::JorbaZou`] takes), capped by
/// [`TaylorConfig::max_order`] and by the system's own
/// [`TaylorSystem::max_order`](crate::taylor::TaylorSystem::max_order); below the rule's
/// order the step is shortened instead (see [`TaylorConfig::max_order`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TaylorConfig {
    /// Relative tolerance (default 1e-6).
    pub rtol: f64,
    /// Absolute tolerance (default 1e-9).
    pub atol: f64,
    /// Highest order used (default 40; at least 2). A tolerance whose Jorba–Zou order is
    /// above this cap (or the system's) is met with the capped order and a shorter step,
    /// which keeps the estimated error at ε (see `TaylorConfig::step_factor`). A jet whose
    /// orders 1 … p all vanish is computed again to this order before the step is sized.
    pub max_order: usize,
    /// A fixed order instead of the tolerance's (default `None`): for convergence studies.
    /// Above `max_order` it is refused by [`TaylorConfig::validate`], above the system's
    /// maximum by [`Taylor::new`](super::Taylor::new) ([`OdeError::TaylorOrderTooHigh`]):
    /// the run could not use the order it was asked for.
    pub order: Option<usize>,
    /// A fixed step instead of the adaptive one (default `None`): for convergence studies.
    /// Stop times are still landed on exactly, with a shorter last step.
    pub fixed_step: Option<f64>,
    /// Largest step (default +∞).
    pub h_max: f64,
    /// Largest number of steps towards one stop before [`OdeError::MaxStepsExceeded`]
    /// (default 100 000). The budget is per run: it counts the steps taken towards the same
    /// stop time (one [`Taylor::advance_to`](super::Taylor::advance_to), a
    /// [`Run`](crate::ode::Run) to its end, an interval of [`solve`](super::solve) between
    /// stops) and starts again at a restart or a new stop, as CVODE's `mxstep` does; a
    /// reused integrator never runs out of it. [`Stats::steps`](crate::ode::Stats::steps)
    /// keeps the whole count. A step taken again, shorter, after its defect check (see
    /// [`TaylorConfig::defect_check`]) counts once.
    pub max_steps: u64,
    /// The extended mode (default `None`, off): `Some(L)` computes the coefficients of orders
    /// 0 … L in double-double from the state kept in double-double, so that neither the
    /// rounding of the state nor that of f(y) gathers over the steps, and tolerances below
    /// 1e-16 mean what they say. Needs a system that implements
    /// [`TaylorSystem::coefficients_extended_into`](crate::taylor::TaylorSystem::coefficients_extended_into);
    /// see [`TaylorConfig::extended_orders`].
    pub extended: Option<usize>,
    /// Whether each summed step is checked against the equation at its end (default `true`):
    /// the defect f(t + h, y_p(h)) − y_p′(h) of the step polynomial y_p, which estimates the
    /// step's error as ‖δ‖·h/(p + 1) and catches a step the rows 0 … p underestimated
    /// because the rows past p are large (x' = P(t) y with P = 0.03 t¹⁰ − 1.9 t¹³ from t = 0
    /// went 0.98 in one step of order 6 with an error of 0.69 at 1e-4). A failed check takes
    /// the step again, shorter, from the same jet ([`Stats::rejections`](crate::ode::Stats::rejections)).
    /// The check reads the jet at the step's end, which is the next step's and is computed
    /// once (its rows f and f′/2 against the polynomial's y_p′(h) and y_p″(h)/2, the second
    /// catching a defect that vanishes at the end by chance), so it costs two Horner chains
    /// beside the step's sum and changes no bit of a step that passes. `false` is Jorba and Zou's rule alone, as heyoka runs
    /// it: for timing the rule, or a system whose jet is not computed from the state it is
    /// given. A fixed step is never checked.
    pub defect_check: bool,
    /// What each component's coefficients are measured against when the step is sized
    /// (default [`StepScale::Componentwise`], each at its own scale). See [`StepScale`].
    pub scale: StepScale,
    /// How the tolerance chooses the order and the step factor (default
    /// [`OrderRule::MinimumWork`]): the order of least work per unit time under a cost model
    /// of the whole step, about 1.5 times Jorba and Zou's, with the step that keeps the
    /// estimated error at the tolerance there. [`OrderRule::JorbaZou`] is heyoka's rule. The
    /// extended mode always takes Jorba and Zou's (see [`TaylorConfig::effective_order_rule`]).
    /// Ignored when [`TaylorConfig::order`] fixes the order, except for the step factor.
    pub order_rule: OrderRule,
}

/// The scale each component's coefficients are measured against when a step is sized, in
/// the relative mode (in the absolute mode every scale is 1).
///
/// The step is h = κ·ρ with ρ the radius estimated from the rows' norms; the scale decides
/// which component holds the radius down. Measured on the heavy top in Euler–Poisson form
/// (ω₃ = 150 rad/s beside direction cosines of size 1, `docs/performance.md`), the two give
/// different errors at the same tolerance (the direction cosines held 150 times tighter by
/// [`StepScale::Componentwise`]) and 150^(1/p) times as many steps (1.46 at p = 13).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum StepScale {
    /// Component i against max(|yᵢ|, atol/rtol): held to max(rtol·|yᵢ|, atol), as the
    /// pairs hold it, so a position of 10⁵ m does not loosen an attitude of size 1.
    #[default]
    Componentwise,
    /// Every component against max(‖y‖∞, atol/rtol): the ‖y‖∞ scale of heyoka and TIDES,
    /// under which a small component beside a large one is held to rtol·‖y‖∞, not to its
    /// own size.
    MaxNorm,
}

impl Default for TaylorConfig {
    fn default() -> Self {
        Self {
            rtol: 1e-6,
            atol: 1e-9,
            max_order: 40,
            order: None,
            fixed_step: None,
            h_max: f64::INFINITY,
            max_steps: 100_000,
            extended: None,
            defect_check: true,
            scale: StepScale::Componentwise,
            order_rule: OrderRule::MinimumWork,
        }
    }
}

impl TaylorConfig {
    /// The default configuration with the given tolerances.
    ///
    /// ```
    /// let c = precess_core::taylor::TaylorConfig::with_tol(1e-12, 1e-14);
    /// assert_eq!(c.max_order, 40);
    /// approx::assert_relative_eq!(c.atol, 1e-14);
    /// ```
    pub fn with_tol(rtol: f64, atol: f64) -> Self {
        Self {
            rtol,
            atol,
            ..Self::default()
        }
    }

    /// Fixed order `order` and fixed step `h` (the tolerances are then unused).
    ///
    /// ```
    /// let c = precess_core::taylor::TaylorConfig::fixed(8, 0.1);
    /// assert_eq!((c.order, c.fixed_step), (Some(8), Some(0.1)));
    /// ```
    pub fn fixed(order: usize, h: f64) -> Self {
        Self {
            order: Some(order),
            fixed_step: Some(h),
            ..Self::default()
        }
    }

    /// This configuration in the extended mode with the orders 0 … `low` in double-double
    /// (see [`TaylorConfig::extended`]). A step of order p adds Σ c_k hᵏ with c_k hᵏ ≈
    /// e⁻²ᵏ‖y‖, so the `f64` orders past `low` lose about 2⁻⁵³e⁻²⁽ˡᵒʷ⁺¹⁾ relative per step:
    /// `low = 6` puts that below 1e-22, where it stays under the last bit of the state even
    /// on a problem that amplifies it 10⁴-fold (the torque-free body next to its middle
    /// axis, `docs/taylor-integrator.md`); `low = 4` leaves 5e-21, which there shows as 1e-15.
    ///
    /// ```
    /// let c = precess_core::taylor::TaylorConfig::with_tol(1e-18, 1e-18).extended_orders(6);
    /// assert_eq!(c.extended, Some(6));
    /// assert!(c.validate().is_ok());
    /// ```
    pub fn extended_orders(self, low: usize) -> Self {
        Self {
            extended: Some(low),
            ..self
        }
    }

    /// Checks every field.
    ///
    /// # Errors
    /// [`OdeError::InvalidTolerance`], [`OdeError::InvalidStep`] or
    /// [`OdeError::InvalidParameter`] (`max_order` or `order` below 2, `extended` outside
    /// `1 ..= MAX_TAYLOR_ORDER`), [`OdeError::TaylorOrderTooHigh`] (`order` above
    /// `max_order`) for the first field out of range.
    ///
    /// ```
    /// use precess_core::ode::OdeError;
    /// use precess_core::taylor::TaylorConfig;
    /// assert!(matches!(
    ///     TaylorConfig::fixed(1000, 0.1).validate(),
    ///     Err(OdeError::TaylorOrderTooHigh { order: 1000, cap: 40, .. })
    /// ));
    /// ```
    pub fn validate(&self) -> Result<(), OdeError> {
        check_tolerances(self.rtol, self.atol, self.fixed_step, self.h_max)?;
        if self.max_order < 2 {
            return Err(OdeError::InvalidParameter {
                name: "max_order",
                value: self.max_order as f64,
            });
        }
        if let Some(p) = self.order
            && p < 2
        {
            return Err(OdeError::InvalidParameter {
                name: "order",
                value: p as f64,
            });
        }
        if let Some(order) = self.order
            && order > self.max_order
        {
            return Err(OdeError::TaylorOrderTooHigh {
                order,
                cap: self.max_order,
                limit: "TaylorConfig::max_order",
            });
        }
        if let Some(low) = self.extended
            && !(1..=MAX_TAYLOR_ORDER).contains(&low)
        {
            return Err(OdeError::InvalidParameter {
                name: "extended (orders in double-double, 1 ..= MAX_TAYLOR_ORDER)",
                value: low as f64,
            });
        }
        Ok(())
    }

    /// The Jorba–Zou order of a tolerance, p = ⌈1 − ½ ln ε⌉, before any cap.
    ///
    /// ```
    /// use precess_core::taylor::TaylorConfig;
    /// assert_eq!(TaylorConfig::jorba_zou_order(1e-16), 20);
    /// assert_eq!(TaylorConfig::jorba_zou_order(1e-6), 8);
    /// ```
    pub fn jorba_zou_order(eps: f64) -> usize {
        order::jorba_zou(eps)
    }

    /// The rule the run follows: [`TaylorConfig::order_rule`], except in the extended mode,
    /// which takes [`OrderRule::JorbaZou`]. There the orders above the double-double ones are
    /// computed in double, and the longer steps of the minimum-work order (κ ≈ 0.27 against
    /// e⁻² ≈ 0.14 at ε = 1e-16) let their rounding through: the (3, 5, 9) body ended 2e-15
    /// from the exact solution at 1e-16, where Jorba and Zou's order reaches 1e-15.
    pub fn effective_order_rule(&self) -> OrderRule {
        if self.extended.is_some() {
            OrderRule::JorbaZou
        } else {
            self.order_rule
        }
    }

    /// The order a step uses at tolerance `eps` for a system of `n` components, with the
    /// caps of the configuration and of the system (`system_max`) applied; at least 2 when
    /// the system allows it.
    pub(crate) fn order_for(&self, eps: f64, system_max: usize, n: usize) -> usize {
        let cap = self.max_order.min(system_max);
        let wanted = match (self.order, self.effective_order_rule()) {
            (Some(p), _) => p,
            (None, OrderRule::JorbaZou) => Self::jorba_zou_order(eps),
            (None, OrderRule::MinimumWork) => order::minimum_work(eps, n, cap),
        };
        wanted.min(cap)
    }

    /// The factor κ of the step h = κ·ρ, ρ the radius of convergence estimated from the last
    /// coefficients that do not vanish, at `order` under the rule `rule`.
    ///
    /// The balance κ = ε^(1/(p−1))·e^(−0.7/(p−1)) keeps the truncation error ≈ (h/ρ)^(p+1)
    /// below ε at any order. At and above the Jorba–Zou order [`OrderRule::JorbaZou`] takes
    /// heyoka's and TIDES' e⁻²·e^(−0.7/(p−1)), the balance at the rule's own order, so a
    /// fixed order above it changes the error and not the step; below it (capped or fixed)
    /// it takes the balance. [`OrderRule::MinimumWork`] takes the balance at every order.
    pub(crate) fn step_factor(eps: f64, order: usize, rule: OrderRule) -> f64 {
        if rule == OrderRule::JorbaZou && order >= Self::jorba_zou_order(eps) {
            let pm1 = (order.max(2) - 1) as f64;
            (-2.0f64).exp() * (-0.7 / pm1).exp()
        } else {
            order::balanced_factor(eps, order)
        }
    }
}
