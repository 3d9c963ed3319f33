//! Taylor's method: the normalised Taylor coefficients of a system's solution, computed by
//! automatic differentiation of its right-hand side, and the adaptive integrator that steps
//! with them.
//!
//! - [`TaylorSystem`] is what the integrator asks of a system: the coefficients
//!   y⁽ᵏ⁾(t)/k! of the solution through (t, y) up to an order.
//! - [`Tape`] decomposes a symbolic right-hand side into elementary operations on series,
//!   each with its automatic-differentiation recurrence; [`TaylorTape`] interprets it at run
//!   time and [`Tape::to_tokens`] emits it as Rust for the derive macros (`taylor = K`).
//! - [`batch`] steps `L` trajectories at once, their recurrences on SIMD lanes.
//! - [`Taylor`] steps with them: order and step from the tolerance, dense output from the
//!   step polynomial, compensated sums; [`solve`] and [`solve_dense`] drive it in one call.
//! - [`TaylorEvent`] is an event function expanded with the steps, whose roots on each step
//!   [`Run::taylor_event`](crate::ode::Run::taylor_event) isolates with a guarantee.

pub mod batch;
pub mod compact;
mod emit;
mod events;
mod integrator;
mod interpreted;
pub mod kernels;
mod recurrence;
mod recurrence_dd;
mod scalars;
mod tape;

pub use emit::TaylorTokens;
pub use events::{EVENT_MISMATCH, EventSeries, StateEvent, TaylorEvent};
pub use integrator::{OrderRule, StepScale, Taylor, TaylorConfig, solve, solve_dense};
pub use interpreted::{TaylorError, TaylorTape};
pub use tape::{ScalarOp, SeriesOp, SeriesStep, Tape, TapeCount, Value};

use crate::exact::Dd;

/// The largest maximum order a [`TaylorTape`] or a `taylor = K` key accepts. Double
/// precision needs about `−½ ln ε + 1 ≈ 19`; past 100 the coefficient table only costs
/// memory and time.
pub const MAX_TAYLOR_ORDER: usize = 100;

/// A system `y' = f(t, y)` on `ℝᴺ` that gives the normalised Taylor coefficients of its
/// solution, `c_k = y⁽ᵏ⁾(t)/k!` for `k = 0, …, order` (so `c_0 = y`, `c_1 = f(t, y)`).
///
/// Implemented by the recurrences generated for a scene (`taylor = …` on its attribute), by
/// the interpreted recurrences of any symbolic system, and by hand.
///
/// The coefficients of the intermediate series live in a [`TaylorSystem::Workspace`] the
/// caller owns and passes to every call (the integrator keeps one), so that a call neither
/// allocates nor zeroes: an implementation sizes it on its first use and then only writes
/// what it reads. A workspace carries no state between calls; any value of the type,
/// `Default::default()` included, gives the same coefficients.
///
/// ```
/// use precess_core::taylor::TaylorSystem;
/// /// y' = y: c_k = y/k!.
/// struct Growth;
/// impl TaylorSystem<1> for Growth {
///     type Workspace = ();
///     fn max_order(&self) -> usize { 30 }
///     fn coefficients_into(&self, _ws: &mut (), _t: f64, y: &[f64; 1], order: usize, c: &mut [[f64; 1]]) {
///         c[0] = *y;
///         for k in 1..=order {
///             c[k][0] = c[k - 1][0] / k as f64;
///         }
///     }
/// }
/// let mut c = [[0.0; 1]; 4];
/// Growth.coefficients(0.0, &[2.0], 3, &mut c);
/// approx::assert_relative_eq!(c[3][0], 2.0 / 6.0);
/// ```
pub trait TaylorSystem<const N: usize> {
    /// Scratch storage for the series of one computation (`()` when there is none).
    type Workspace: Default + Clone + std::fmt::Debug;

    /// The highest order [`TaylorSystem::coefficients_into`] can compute.
    fn max_order(&self) -> usize;

    /// Writes `c_k = y⁽ᵏ⁾(t)/k!` into `coeffs[k]` for `k = 0, …, order`, with `ws` as
    /// scratch.
    ///
    /// The caller guarantees `order ≤ self.max_order()` and `coeffs.len() > order`.
    fn coefficients_into(
        &self,
        ws: &mut Self::Workspace,
        t: f64,
        y: &[f64; N],
        order: usize,
        coeffs: &mut [[f64; N]],
    );

    /// [`TaylorSystem::coefficients_into`] with a workspace made for this one call: for a
    /// single computation; repeated ones should keep a workspace.
    fn coefficients(&self, t: f64, y: &[f64; N], order: usize, coeffs: &mut [[f64; N]]) {
        self.coefficients_into(&mut Self::Workspace::default(), t, y, order, coeffs);
    }

    /// The coefficients with their low orders in double-double, from a state given in
    /// double-double: what the extended mode of the integrator
    /// ([`TaylorConfig::extended_orders`]) steps with. Returns `false`, having written
    /// nothing it promises, when the system cannot (the default).
    ///
    /// With `y = y.hi + y.lo` (each component an unevaluated sum, [`Dd`]) and `t` likewise,
    /// an implementation that returns `true` has written
    /// - `coeffs[k]`, `k = 0, …, order`: the coefficients in `f64`, as
    ///   [`TaylorSystem::coefficients_into`] would from the rounded state (a few ulps of
    ///   difference are allowed: these orders enter the step multiplied by hᵏ, k > `low`);
    /// - `low[k]`, `k = 0, …, L` with `L = min(low.len() − 1, order)`: the same coefficients
    ///   in double-double, `|low[k] − c_k| ≲ 2⁻¹⁰⁰·Σ|terms|` where `c_k` is the exact
    ///   coefficient of the solution through `(t, y)` — the recurrences run on the exact
    ///   state, with the system's constants in double-double, and each sum rounded to about
    ///   106 bits.
    ///
    /// Why the split works: a step adds Σₖ c_k hᵏ with h ≈ e⁻²ρ, so c_k hᵏ ≈ e⁻²ᵏ‖y‖ and
    /// the `f64` rounding of an order k > L costs about 2⁻⁵³e⁻²ᵏ relative; at L = 6 that is
    /// below 1e-22. The first orders, c₀ = y and c₁ = f(y), carry the digits that a rounded
    /// state and a rounded f lose at every step.
    ///
    /// The caller guarantees `order ≤ self.max_order()`, `coeffs.len() > order` and
    /// `low.len() ≥ 1`; `low` longer than `order + 1` is filled to `order` only.
    ///
    /// ```
    /// use precess_core::exact::Dd;
    /// use precess_core::taylor::TaylorSystem;
    /// /// y' = y/3: c_k = y/(3ᵏ k!), which no double holds exactly from k = 1.
    /// struct Third;
    /// impl TaylorSystem<1> for Third {
    ///     type Workspace = ();
    ///     fn max_order(&self) -> usize { 30 }
    ///     fn coefficients_into(&self, _ws: &mut (), _t: f64, y: &[f64; 1], order: usize, c: &mut [[f64; 1]]) {
    ///         c[0] = *y;
    ///         for k in 1..=order {
    ///             c[k][0] = c[k - 1][0] / (3 * k) as f64;
    ///         }
    ///     }
    ///     fn coefficients_extended_into(&self, ws: &mut (), t: Dd, y: &[Dd; 1], order: usize, c: &mut [[f64; 1]], low: &mut [[Dd; 1]]) -> bool {
    ///         self.coefficients_into(ws, t.hi, &[y[0].hi], order, c);
    ///         low[0] = *y;
    ///         for k in 1..low.len().min(order + 1) {
    ///             low[k][0] = low[k - 1][0] / Dd::from((3 * k) as f64);
    ///         }
    ///         true
    ///     }
    /// }
    /// let mut c = [[0.0; 1]; 4];
    /// let mut low = [[Dd::default(); 1]; 2];
    /// assert!(Third.coefficients_extended_into(&mut (), Dd::from(0.0), &[Dd::from(1.0)], 3, &mut c, &mut low));
    /// // c₁ = 1/3 to about 32 digits: 3·c₁ − 1 vanishes far below an ulp of 1.
    /// let residual = (low[1][0] * Dd::from(3.0) - Dd::from(1.0)).to_f64();
    /// assert!(residual.abs() < 1e-30);
    /// ```
    fn coefficients_extended_into(
        &self,
        ws: &mut Self::Workspace,
        t: Dd,
        y: &[Dd; N],
        order: usize,
        coeffs: &mut [[f64; N]],
        low: &mut [[Dd; N]],
    ) -> bool {
        let _ = (ws, t, y, order, coeffs, low);
        false
    }

    /// Checks the system's parameters under the rules of its scene, once, when the
    /// [`Taylor`] integrator is built or restarted: the same hook as
    /// [`System::check_parameters`](crate::ode::System::check_parameters). The default has
    /// nothing to check; the derived scenes implement it with their own checks.
    ///
    /// # Errors
    /// [`OdeError::InvalidSystemParameter`](crate::ode::OdeError::InvalidSystemParameter)
    /// naming the quantity and carrying its value.
    fn check_parameters(&self) -> Result<(), crate::ode::OdeError> {
        Ok(())
    }
}

impl<S: TaylorSystem<N> + ?Sized, const N: usize> TaylorSystem<N> for &S {
    type Workspace = S::Workspace;

    crate::ode::forward_to_referent! {
        fn check_parameters(&self) -> Result<(), crate::ode::OdeError>;
        fn max_order(&self) -> usize;
        fn coefficients_into(&self, ws: &mut Self::Workspace, t: f64, y: &[f64; N], order: usize,
            coeffs: &mut [[f64; N]]);
        fn coefficients_extended_into(&self, ws: &mut Self::Workspace, t: Dd, y: &[Dd; N],
            order: usize, coeffs: &mut [[f64; N]], low: &mut [[Dd; N]]) -> bool;
    }
}

#[cfg(test)]
mod tests;
