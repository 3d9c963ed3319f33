//! Taylor's method: the normalised Taylor coefficients of a system's solution, computed by
//! automatic differentiation of its right-hand side, and the adaptive integrator that steps
//! with them.
//!
//! - [`TaylorSystem`] is what the integrator asks of a system: the coefficients
//!   y⁽ᵏ⁾(t)/k! of the solution through (t, y) up to an order.
//! - [`Tape`] decomposes a symbolic right-hand side into elementary operations on series,
//!   each with its automatic-differentiation recurrence; [`TaylorTape`] interprets it at run
//!   time and [`Tape::to_tokens`] emits it as Rust for the derive macros (`taylor = K`).
//! - [`Taylor`] steps with them: order and step from the tolerance, dense output from the
//!   step polynomial, compensated sums; [`solve`] and [`solve_dense`] drive it in one call.

mod emit;
mod integrator;
mod interpreted;
mod recurrence;
mod tape;

pub use emit::TaylorTokens;
pub use integrator::{Taylor, TaylorConfig, solve, solve_dense};
pub use interpreted::{TaylorError, TaylorTape};
pub use tape::{ScalarOp, SeriesOp, SeriesStep, Tape, TapeCount, Value};

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
/// ```
/// use precess_core::taylor::TaylorSystem;
/// /// y' = y: c_k = y/k!.
/// struct Growth;
/// impl TaylorSystem<1> for Growth {
///     fn max_order(&self) -> usize { 30 }
///     fn coefficients(&self, _t: f64, y: &[f64; 1], order: usize, c: &mut [[f64; 1]]) {
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
    /// The highest order [`TaylorSystem::coefficients`] can compute.
    fn max_order(&self) -> usize;

    /// Writes `c_k = y⁽ᵏ⁾(t)/k!` into `coeffs[k]` for `k = 0, …, order`.
    ///
    /// The caller guarantees `order ≤ self.max_order()` and `coeffs.len() > order`.
    fn coefficients(&self, t: f64, y: &[f64; N], order: usize, coeffs: &mut [[f64; N]]);
}

impl<S: TaylorSystem<N> + ?Sized, const N: usize> TaylorSystem<N> for &S {
    fn max_order(&self) -> usize {
        (**self).max_order()
    }

    fn coefficients(&self, t: f64, y: &[f64; N], order: usize, coeffs: &mut [[f64; N]]) {
        (**self).coefficients(t, y, order, coeffs)
    }
}

#[cfg(test)]
mod tests;
