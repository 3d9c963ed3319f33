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

    /// Names the cause of a right-hand side that came out NaN or ±∞ at `(t, y)`: the
    /// steppers call it where f was not finite (at the stage that failed, or the step's
    /// start where they do not keep the stage), and report its error in place of the generic
    /// [`OdeError::NonFiniteState`]. Never called on the steppers' inner loops, so it may
    /// evaluate what it likes again.
    ///
    /// The default names nothing (`None`). The derived scenes with driven rotors evaluate
    /// their motors at `(t, y)`.
    ///
    /// ```
    /// use precess_core::ode::{AdaptiveConfig, Dopri5, OdeError, System};
    /// /// y' = u(t) with an input u that fails after t = 1.
    /// struct Fed;
    /// fn u(t: f64) -> f64 { if t > 1.0 { f64::NAN } else { 1.0 } }
    /// impl System<1> for Fed {
    ///     fn rhs(&self, t: f64, _y: &[f64; 1], d: &mut [f64; 1]) { d[0] = u(t); }
    ///     fn explain_non_finite(&self, t: f64, _y: &[f64; 1]) -> Option<OdeError> {
    ///         let value = u(t);
    ///         (!value.is_finite()).then(|| OdeError::NonFiniteInput { input: "u".into(), t, value })
    ///     }
    /// }
    /// let mut ode = Dopri5::new(Fed, 0.0, [0.0], AdaptiveConfig::default())?;
    /// let e = ode.advance_to(2.0).unwrap_err();
    /// assert!(matches!(e, OdeError::NonFiniteInput { t, .. } if t > 1.0));
    /// # Ok::<(), OdeError>(())
    /// ```
    ///
    /// # Errors
    /// None: the error it returns is the explanation, [`OdeError::NonFiniteInput`] or the
    /// scene's own.
    fn explain_non_finite(&self, t: f64, y: &[f64; N]) -> Option<OdeError> {
        let _ = (t, y);
        None
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

/// The methods of a trait's impl for `&S` that call the same method of `S` (the `System` and
/// `TaylorSystem` impls for references): each signature written once, the forwarding call
/// made from it, so a reference runs exactly as the system it points to. A method left out
/// would silently take the trait's default instead; list every one the trait has. Invoked
/// inside the impl as `forward_to_referent! { fn name(&self, arg: Type, …) -> Output; … }`.
macro_rules! forward_to_referent {
    ($(fn $name:ident(&self $(, $arg:ident: $ty:ty)* $(,)?) $(-> $out:ty)?;)*) => {
        $(
            fn $name(&self $(, $arg: $ty)*) $(-> $out)? {
                (**self).$name($($arg),*)
            }
        )*
    };
}
pub(crate) use forward_to_referent;

impl<S: System<N> + ?Sized, const N: usize> System<N> for &S {
    forward_to_referent! {
        fn rhs(&self, t: f64, y: &[f64; N], dydt: &mut [f64; N]);
        fn check_parameters(&self) -> Result<(), OdeError>;
        fn explain_non_finite(&self, t: f64, y: &[f64; N]) -> Option<OdeError>;
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

/// The error of a right-hand side found not finite at `(t, y)` in the step from `t_step`:
/// the system's explanation ([`System::explain_non_finite`]) when the state there is finite
/// (a non-finite state is the blow-up itself, not an input's fault), else
/// [`OdeError::NonFiniteState`] naming the step's start.
pub(crate) fn non_finite<S: System<N> + ?Sized, const N: usize>(
    sys: &S,
    t_step: f64,
    (t, y): (f64, &[f64; N]),
) -> OdeError {
    all_finite(y)
        .then(|| sys.explain_non_finite(t, y))
        .flatten()
        .unwrap_or(OdeError::NonFiniteState { t: t_step })
}

/// `true` when every component is finite.
pub(crate) fn all_finite<const N: usize>(y: &[f64; N]) -> bool {
    y.iter().all(|v| v.is_finite())
}
