//! Events: zero crossings of user functions g(t, y), found in each accepted step and located
//! on the stepper's own solution inside it.
//!
//! A crossing is a change of sign of g along the step: g < 0 before and g ≥ 0 after is
//! rising, g > 0 before and g ≤ 0 after is falling. A g that is exactly 0 where a crossing
//! would start (the run starts on a root, or the last event ended there) opens no crossing,
//! so an event is never reported twice.
//!
//! Every root inside a step is looked for, not only a change of sign between the step's
//! ends (two roots in one step would cancel there): g is interpolated along the step at
//! Chebyshev points, refined until the interpolant's coefficients decay, and evaluated at
//! the interpolant's critical points, so that each root sits alone between two points
//! where g has opposite signs ([`super::scan`]). What is guaranteed, as far as the
//! interpolant's error estimate ε (its last two Chebyshev coefficients) is its error: a
//! piece of the step is passed over as rootless only when its interpolant stays 8ε away
//! from 0 with ε at most 10⁻³ of max |g| on the piece; otherwise it is refined until
//! ε ≤ 10⁻¹⁰ max |g|, and there every pair of consecutive simple roots between which |g|
//! exceeds 2ε is found, however close the roots are. A step is cut into at most 64 pieces
//! of at most 17 points each, so a g faster than that (more than about 5 roots per 1/64 of
//! a step), or one that comes within ε of 0 without crossing, may still hide a pair; and ε
//! is an a-posteriori estimate, not a bound: a g that five points alias, with both last
//! coefficients below 10⁻³ max |g| by coincidence, can pass as rootless (shallow dips
//! planted in sums of sines, at random places in random steps: none missed in 20 000,
//! 49 when any ε 8 times from 0 was trusted). g is evaluated at times in any order inside
//! the step.
//!
//! Each root is bracketed by two of those points and located with the Anderson–Björck
//! variant of regula falsi (Anderson & Björck 1973), with a bisection whenever the bracket
//! fails to halve over two iterations, down to adjacent doubles: on the dense output of an
//! adaptive pair or of the Taylor integrator, or on the partial steps of a fixed-step
//! method, so the event is as accurate as the method.
//!
//! On the Taylor integrator, a g given as an expression of the state is found with a
//! guarantee instead of the scan's estimate: expanded with each step and its polynomial's
//! roots isolated (`StepRoots`, `Run::taylor_event`, `taylor::TaylorEvent`).

use super::error::OdeError;
use super::stepper::Stepper;

/// Which sign changes of g count.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Direction {
    /// Either way (the default).
    #[default]
    Both,
    /// g going from negative to zero or positive.
    Rising,
    /// g going from positive to zero or negative.
    Falling,
}

impl Direction {
    /// Whether a crossing in direction `crossing` (rising or falling) is wanted.
    fn admits(self, crossing: Direction) -> bool {
        self == Direction::Both || self == crossing
    }
}

/// What an event is: its name, the directions that count, and whether it ends the run.
///
/// ```
/// use precess_core::ode::{Direction, Event};
/// let floor = Event::new("floor").falling().terminal();
/// assert_eq!(floor.direction(), Direction::Falling);
/// assert!(floor.is_terminal());
/// assert_eq!(floor.name(), "floor");
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Event {
    name: String,
    direction: Direction,
    terminal: bool,
    ends_only: bool,
}

impl Event {
    /// An event named `name`, counting both directions, not terminal.
    pub fn new(name: impl Into<String>) -> Self {
        Self {
            name: name.into(),
            direction: Direction::Both,
            terminal: false,
            ends_only: false,
        }
    }

    /// Counts only rising crossings.
    pub fn rising(self) -> Self {
        self.with_direction(Direction::Rising)
    }

    /// Counts only falling crossings.
    pub fn falling(self) -> Self {
        self.with_direction(Direction::Falling)
    }

    /// Counts the crossings of `direction`.
    pub fn with_direction(mut self, direction: Direction) -> Self {
        self.direction = direction;
        self
    }

    /// Ends the run at the first counted crossing; the stepper is restarted there.
    pub fn terminal(mut self) -> Self {
        self.terminal = true;
        self
    }

    /// The name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The directions that count.
    pub fn direction(&self) -> Direction {
        self.direction
    }

    /// Whether the event ends the run.
    pub fn is_terminal(&self) -> bool {
        self.terminal
    }

    /// Looks only for a change of sign of g between the ends of each step, as events did
    /// before every root inside a step was looked for: one evaluation of g per step and no
    /// state inside it, but two roots inside one step cancel there and are missed without a
    /// word. For a g known to vary slowly against the step (or a step bounded below the
    /// shortest time between roots, `AdaptiveConfig::h_max`, `FixedStepConfig::h`), where
    /// the scan's cost matters: the fixed-step methods compute each state inside a step by
    /// a partial step, and DOP853 and Vern9 build their interpolant on every step a scan
    /// samples (3 and 4 evaluations of f).
    ///
    /// ```
    /// use precess_core::ode::Event;
    /// let fast = Event::new("slow g").step_ends_only();
    /// assert!(fast.is_step_ends_only());
    /// assert!(!Event::new("g").is_step_ends_only());
    /// ```
    pub fn step_ends_only(mut self) -> Self {
        self.ends_only = true;
        self
    }

    /// Whether only the steps' ends are compared ([`Event::step_ends_only`]).
    pub fn is_step_ends_only(&self) -> bool {
        self.ends_only
    }
}

/// An event that fired: which one, when, the state then, and which way g crossed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EventHit<St> {
    /// Index of the event, in the order the events were added to the run.
    pub index: usize,
    /// Time of the crossing: the end of the located bracket, where g has its new sign or is 0.
    pub t: f64,
    /// The stepper's solution at `t`.
    pub state: St,
    /// [`Direction::Rising`] or [`Direction::Falling`].
    pub direction: Direction,
    /// Whether the event was terminal (and so the last of the run).
    pub terminal: bool,
}

/// A function of (t, y), boxed once per run.
pub(crate) type StateFn<'a, St> = Box<dyn FnMut(f64, &St) -> f64 + 'a>;

/// The roots of an event's function in each step, isolated by the stepper's own means
/// instead of the scan of g's samples ([`super::scan`]): the Taylor integrator expands g
/// along its step (`taylor::TaylorEvent`). What [`Run`](super::Run) asks of such an event
/// after each step.
pub(crate) trait StepRoots<S: Stepper> {
    /// Appends to `out` (which ends with `(t_a, g_a)`, the step's start) the points of the
    /// step after t_a, ascending and ending with `(t_b, g_b)`, such that the function
    /// [`StepRoots::value`] has at most one root between two consecutive ones wherever the
    /// implementation proves it. `index` names the event in errors.
    ///
    /// # Errors
    /// [`OdeError::NonFiniteEvent`] for a function that is not finite on the step.
    fn points(
        &mut self,
        stepper: &S,
        index: usize,
        a: (f64, f64),
        b: (f64, f64),
        out: &mut Vec<(f64, f64)>,
    ) -> Result<(), OdeError>;

    /// The function whose roots [`StepRoots::points`] isolated, at `t` inside the last
    /// step: the roots are located on it.
    ///
    /// # Errors
    /// [`OdeError::NonFiniteEvent`].
    fn value(&mut self, index: usize, t: f64) -> Result<f64, OdeError>;
}

/// An event with its function, how its roots are found in a step (scanned when `roots` is
/// `None`), and the value of g at the end of the last step.
pub(crate) struct EventSlot<'a, S: Stepper> {
    pub(crate) event: Event,
    pub(crate) g: StateFn<'a, S::State>,
    pub(crate) roots: Option<Box<dyn StepRoots<S> + 'a>>,
    pub(crate) last: f64,
}

impl<S: Stepper> EventSlot<'_, S> {
    /// g(t, y), refused when not finite.
    ///
    /// # Errors
    /// [`OdeError::NonFiniteEvent`].
    pub(crate) fn eval(&mut self, index: usize, t: f64, y: &S::State) -> Result<f64, OdeError> {
        let value = (self.g)(t, y);
        if value.is_finite() {
            Ok(value)
        } else {
            Err(OdeError::NonFiniteEvent { index, t, value })
        }
    }
}

/// The crossing from `g_old` to `g_new` (in that order in time) if `wanted` counts it: g < 0
/// then g ≥ 0 is rising, g > 0 then g ≤ 0 falling; from exactly 0 there is none.
pub(crate) fn crossing(wanted: Direction, g_old: f64, g_new: f64) -> Option<Direction> {
    let dir = if g_old < 0.0 && g_new >= 0.0 {
        Direction::Rising
    } else if g_old > 0.0 && g_new <= 0.0 {
        Direction::Falling
    } else {
        return None;
    };
    wanted.admits(dir).then_some(dir)
}

/// Iterations after which [`locate_root`] gives up refining (the bisection safeguard needs
/// about 2 × 64 to reach one ulp from any bracket of doubles).
const MAX_ITERATIONS: usize = 200;

/// The root of `f` in `[a, b]`, given `f(a) = fa` and `f(b) = fb` of opposite signs (or
/// `fb = 0`), down to adjacent doubles: returns the right end of the final bracket, where f
/// has the sign of `fb` or is 0.
///
/// # Errors
/// What `f` returns.
pub(crate) fn locate_root(
    f: impl FnMut(f64) -> Result<f64, OdeError>,
    left: (f64, f64),
    right: (f64, f64),
) -> Result<f64, OdeError> {
    Ok(locate_bracket(f, left, right)?.1.0)
}

/// A point (t, f(t)) of a bracket.
pub(crate) type Point = (f64, f64);

/// The final bracket of [`locate_root`]: `((a, f_a), (b, f_b))` with a and b adjacent
/// doubles (or b a zero of f, a the last point before it), f(a) of the sign of `fa` and f(b)
/// of the sign of `fb` or 0 (the values as the iteration holds them: the Anderson–Björck
/// scaling may have shrunk them; their signs are f's). A hybrid run's witness acts at the left end, the last time its
/// mode held.
///
/// # Errors
/// What `f` returns.
pub(crate) fn locate_bracket(
    mut f: impl FnMut(f64) -> Result<f64, OdeError>,
    (mut a, mut fa): (f64, f64),
    (mut b, mut fb): (f64, f64),
) -> Result<(Point, Point), OdeError> {
    // The side replaced last (−1 left, +1 right) and the bracket widths of the last two
    // iterations, for the Anderson–Björck scaling and the bisection safeguard.
    let mut last_side = 0;
    let mut widths = [f64::INFINITY; 2];
    for _ in 0..MAX_ITERATIONS {
        if fb == 0.0 {
            return Ok(((a, fa), (b, fb)));
        }
        let width = b - a;
        // Down to adjacent doubles (the midpoint rounds onto an end): b is then within an
        // ulp of the root of f as computed.
        let middle = 0.5 * (a + b);
        if middle <= a || middle >= b {
            return Ok(((a, fa), (b, fb)));
        }
        let bisect = width > 0.5 * widths[0];
        widths = [widths[1], width];
        let secant = b - fb * (width / (fb - fa));
        // A secant that rounds onto an end (f there is negligible against the other end's:
        // the root is within rounding of it) probes one tolerance inside that end, which
        // closes the bracket at once when the root is there; bisecting instead would halve
        // the bracket down to an ulp, tens of evaluations.
        let tol = f64::EPSILON * a.abs().max(b.abs());
        let c = if bisect {
            middle
        } else if secant >= b {
            (b - tol).max(a.next_up())
        } else if secant <= a {
            (a + tol).min(b.next_down())
        } else if secant > a && secant < b {
            secant
        } else {
            middle
        };
        if c <= a || c >= b {
            // a and b are adjacent doubles.
            return Ok(((a, fa), (b, fb)));
        }
        let fc = f(c)?;
        if fc == 0.0 {
            return Ok(((a, fa), (c, fc)));
        }
        if (fc < 0.0) == (fb < 0.0) {
            // c replaces b; when b's side moves twice running, a is stale: scale fa down.
            if last_side == 1 {
                let m = 1.0 - fc / fb;
                fa *= if m > 0.0 { m } else { 0.5 };
            }
            (b, fb, last_side) = (c, fc, 1);
        } else {
            if last_side == -1 {
                let m = 1.0 - fc / fa;
                fb *= if m > 0.0 { m } else { 0.5 };
            }
            (a, fa, last_side) = (c, fc, -1);
        }
    }
    Ok(((a, fa), (b, fb)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn root_of_a_smooth_function_to_an_ulp() {
        // cos t = t at 0.739085133215160641655312087673873404 (the Dottie number).
        let f = |t: f64| Ok(t.cos() - t);
        let root = locate_root(f, (0.0, 1.0), (1.0, 1f64.cos() - 1.0)).unwrap();
        assert!((root - 0.739_085_133_215_160_6).abs() <= 2.0 * f64::EPSILON);
    }

    #[test]
    fn root_of_a_flat_function_converges() {
        // (t − 0.3)⁵: regula falsi alone stalls on one side; the safeguards converge.
        let g = |t: f64| (t - 0.3).powi(5);
        let mut calls = 0;
        let f = |t: f64| {
            calls += 1;
            Ok(g(t))
        };
        let root = locate_root(f, (0.0, g(0.0)), (1.0, g(1.0))).unwrap();
        assert!((root - 0.3).abs() < 1e-3, "{root}");
        assert!(calls < MAX_ITERATIONS);
        // The returned end has the sign of f at the right end (or is a zero).
        assert!(g(root) >= 0.0);
    }

    #[test]
    fn a_secant_onto_an_end_closes_the_bracket_without_bisecting() {
        // A root at 0.1232 with rounding-sized noise, as g has on a step polynomial near
        // its root: a secant lands on a point whose f is ~1e-17, and the next secant rounds
        // onto it. Bisecting from there took 70 evaluations; probing inside the end, 23.
        let r = 0.1232;
        let g = |t: f64| (t - r) * (1.0 + t) + 3e-17 * (1e15 * t).sin();
        let mut calls = 0;
        let f = |t: f64| {
            calls += 1;
            Ok(g(t))
        };
        let root = locate_root(f, (0.0, g(0.0)), (1.0, g(1.0))).unwrap();
        assert!((root - r).abs() <= 1e-16, "{root}");
        assert!(calls <= 30, "{calls} evaluations");
    }

    #[test]
    fn the_returned_end_is_on_the_new_side() {
        // Falling: f(a) > 0, f(b) < 0; the answer has f ≤ 0.
        let f = |t: f64| Ok(0.5 - t);
        let root = locate_root(f, (0.0, 0.5), (1.0, -0.5)).unwrap();
        assert!(0.5 - root <= 0.0 && (root - 0.5).abs() <= f64::EPSILON);
    }
}
