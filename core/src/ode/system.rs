//! The system trait: a right-hand side written in place.

use super::error::OdeError;

/// An ordinary differential equation `y' = f(t, y)` on `ℝᴺ`.
///
/// The state is a fixed-size array so the steppers never allocate.
///
/// ```
/// use precess_core::ode::System;
/// struct Decay;
/// impl System<1> for Decay {
///     fn rhs(&self, _t: f64, y: &[f64; 1], dydt: &mut [f64; 1]) {
///         dydt[0] = -y[0];
///     }
/// }
/// let mut d = [0.0];
/// Decay.rhs(0.0, &[2.0], &mut d);
/// approx::assert_relative_eq!(d[0], -2.0);
/// ```
pub trait System<const N: usize> {
    /// Writes `f(t, y)` into `dydt`.
    fn rhs(&self, t: f64, y: &[f64; N], dydt: &mut [f64; N]);

    /// Checks the system's parameters (masses, gravity, stiffnesses, … read from a struct's
    /// fields or bound at run time) under the rules of its scene. Every integrator calls it
    /// once when it is built or restarted, so no run starts on unphysical values; the
    /// right-hand side itself stays unchecked, for the steppers' inner loops.
    ///
    /// The default has nothing to check. The derived scenes and the interpreted models
    /// implement it with the checks their checked methods already make.
    ///
    /// # Errors
    /// [`OdeError::InvalidSystemParameter`] naming the quantity and carrying its value.
    fn check_parameters(&self) -> Result<(), OdeError> {
        Ok(())
    }
}

/// Adapts a closure `|t, y, dydt|` into a [`System`].
///
/// ```
/// use precess_core::ode::{FnSystem, System};
/// let sys = FnSystem(|t: f64, _y: &[f64; 1], d: &mut [f64; 1]| d[0] = t);
/// let mut d = [0.0];
/// sys.rhs(3.0, &[0.0], &mut d);
/// approx::assert_relative_eq!(d[0], 3.0);
/// ```
#[derive(Debug, Clone, Copy)]
pub struct FnSystem<F>(pub F);

impl<F, const N: usize> System<N> for FnSystem<F>
where
    F: Fn(f64, &[f64; N], &mut [f64; N]),
{
    fn rhs(&self, t: f64, y: &[f64; N], dydt: &mut [f64; N]) {
        (self.0)(t, y, dydt)
    }
}

impl<S: System<N> + ?Sized, const N: usize> System<N> for &S {
    fn rhs(&self, t: f64, y: &[f64; N], dydt: &mut [f64; N]) {
        (**self).rhs(t, y, dydt)
    }

    fn check_parameters(&self) -> Result<(), OdeError> {
        (**self).check_parameters()
    }
}

/// Counts of the work an integration did.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Stats {
    /// Accepted steps.
    pub steps: u64,
    /// Rejected step attempts.
    pub rejections: u64,
    /// Right-hand-side evaluations, including the initial-step guess and dense output.
    pub rhs_evals: u64,
}

impl core::ops::AddAssign for Stats {
    /// Adds the work of another integration (a chart switch restarts the integrator; the
    /// totals carry on).
    ///
    /// ```
    /// use precess_core::ode::Stats;
    /// let mut total = Stats { steps: 3, rejections: 1, rhs_evals: 20 };
    /// total += Stats { steps: 2, rejections: 0, rhs_evals: 12 };
    /// assert_eq!(total, Stats { steps: 5, rejections: 1, rhs_evals: 32 });
    /// ```
    fn add_assign(&mut self, other: Stats) {
        self.steps += other.steps;
        self.rejections += other.rejections;
        self.rhs_evals += other.rhs_evals;
    }
}

impl core::ops::Add for Stats {
    type Output = Stats;
    /// The work of two integrations together; see the `+=` form.
    fn add(mut self, other: Stats) -> Stats {
        self += other;
        self
    }
}

/// `true` when every component is finite.
pub(crate) fn all_finite<const N: usize>(y: &[f64; N]) -> bool {
    y.iter().all(|v| v.is_finite())
}
