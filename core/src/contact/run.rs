//! A body on a table integrated by an adaptive embedded pair in the one run loop
//! ([`crate::ode::Hybrid`]): the phase, with the spin free or held by pivoting friction, is
//! the loop's mode, the quaternion is put back on the unit sphere after every accepted step
//! (and a held spin back to zero), and the stick–slip switches, the lift-off, the slip
//! stopping, Painlevé's paradox, a disk lying flat and a spin stopping or breaking loose are
//! the witnesses of [`super::phases`], located on the pair's dense output.

use super::dynamics::ContactDynamics;
use super::error::ContactError;
use super::outcome::{ContactOutcome, Switch};
use super::phases::check_start;
use super::scene::{ContactMode, Phase};
use super::state::STATE_LEN;
use super::system::ContactSystem;
use crate::ode::{
    Adaptive, AdaptiveConfig, Cause, Dop853Pair, EmbeddedPair, Hybrid, HybridState, Stats, Stepper,
};

/// The slip seeded when rolling gives way to sliding is twice the slip speed taken as zero:
/// 10⁻⁹ of the velocity scale ([`STICK_FRACTION`](super::STICK_FRACTION)), or what the run's
/// tolerances resolve where that is larger; this is kept as the order of magnitude for a body
/// moving at about 1 m/s at tight tolerances.
pub const SEED_SLIP: f64 = 2e-9;

/// A body on a table integrated by the pair `P` (DOP853 by default).
///
/// ```
/// use approx::assert_relative_eq;
/// use nalgebra::{UnitQuaternion, Vector3};
/// use precess_core::contact::{
///     ContactDynamics, ContactLaw, ContactModel, ContactOutcome, ContactRun, ContactScene, Phase,
///     Surface,
/// };
/// use precess_core::ode::AdaptiveConfig;
/// use precess_core::sym::Arena;
///
/// // A uniform ball rolls straight at 0.5 m/s: after 2 s it is 1 m on.
/// let mut a = Arena::new();
/// let (m, rho, g, i) = (a.parameter("m"), a.parameter("rho"), a.parameter("g"), a.parameter("I"));
/// let z = a.zero();
/// let scene = ContactScene {
///     mass: m,
///     center: [z; 3],
///     inertia: [[i, z, z], [z, i, z], [z, z, i]],
///     surface: Surface::Sphere { center: [z; 3], radius: rho },
///     law: ContactLaw::Rolling { rolling_resistance: None, spin_resistance: None },
///     gravity: g,
/// };
/// let d = scene.derive(&mut a)?;
/// let ball = ContactModel::new(&mut a, &d, &[("m", 1.0), ("rho", 0.1), ("g", 9.81), ("I", 0.004)])?;
/// let y0 = ball.rolling_state([0.0, 0.0], &UnitQuaternion::identity(), &Vector3::new(0.0, 5.0, 0.0))?;
/// let mut run = ContactRun::new(&ball, Phase::Rolling, 0.0, y0, AdaptiveConfig::with_tol(1e-12, 1e-12))?;
/// assert_eq!(run.advance_to(2.0)?, ContactOutcome::Reached { t: 2.0 });
/// assert_relative_eq!(run.y()[0], 1.0, max_relative = 1e-12);
/// # Ok::<(), precess_core::contact::ContactError>(())
/// ```
#[derive(Debug)]
pub struct ContactRun<'a, D: ContactDynamics + ?Sized, P: EmbeddedPair = Dop853Pair> {
    run: Hybrid<Adaptive<ContactSystem<'a, D>, P, STATE_LEN>>,
}

impl<'a, D: ContactDynamics + ?Sized> ContactRun<'a, D, Dop853Pair> {
    /// Starts `body` in `phase` at `y0`, time `t0`, with DOP853.
    ///
    /// # Errors
    /// As [`ContactDynamics::check_parameters`] and [`ContactDynamics::check_state`];
    /// [`ContactError::NotPressed`] for a state the table would have to pull on,
    /// [`ContactError::Painleve`] for a Coulomb sliding state without a consistent normal
    /// force, [`ContactError::ZeroSlip`] for a Coulomb sliding start without a slip;
    /// [`ContactError::Ode`] for a bad configuration or a right-hand side not finite at the
    /// start.
    pub fn new(
        body: &'a D,
        phase: Phase,
        t0: f64,
        y0: [f64; STATE_LEN],
        cfg: AdaptiveConfig,
    ) -> Result<Self, ContactError> {
        Self::with_pair(body, phase, t0, y0, cfg)
    }
}

impl<'a, D: ContactDynamics + ?Sized, P: EmbeddedPair> ContactRun<'a, D, P> {
    /// Starts as [`ContactRun::new`] with the pair `P`
    /// (`ContactRun::<_, Dopri5Pair>::with_pair(..)`). A stick–slip body started rolling
    /// where rolling needs at least μN slides from the start (a switch at `t0`).
    ///
    /// # Errors
    /// As [`ContactRun::new`].
    pub fn with_pair(
        body: &'a D,
        phase: Phase,
        t0: f64,
        y0: [f64; STATE_LEN],
        cfg: AdaptiveConfig,
    ) -> Result<Self, ContactError> {
        body.check_state(phase, &y0)?;
        let sys = ContactSystem::new(body, phase)?.resolving(cfg.atol, cfg.rtol);
        check_start(&sys, t0, &y0)?;
        let ode = Adaptive::new(sys, t0, y0, cfg)?;
        Ok(ContactRun {
            run: Hybrid::new(ode)?.with_max_steps(cfg.max_steps),
        })
    }

    /// Current time.
    pub fn t(&self) -> f64 {
        self.run.t()
    }

    /// The current state array.
    pub fn y(&self) -> &[f64; STATE_LEN] {
        &self.run.state().x
    }

    /// The current phase.
    pub fn phase(&self) -> Phase {
        self.run.mode().phase
    }

    /// Whether pivoting friction holds the spin about the vertical at zero now. While it
    /// does, the body's own [`ContactDynamics::reaction`] of the phase is the one with the
    /// full friction ∓ℓ_p N of whatever sign the rounding gives ω·γ; the reaction with the
    /// pivot couple in place, and the couple, are [`super::held_spin`]'s.
    pub fn spin_held(&self) -> bool {
        self.run.mode().spin_held
    }

    /// The phase switches so far, each from the loop's transitions.
    pub fn switches(&self) -> Vec<Switch> {
        self.run
            .transitions()
            .iter()
            .map(|tr| Switch {
                t: tr.t,
                from: tr.before.mode.phase,
                to: tr.after.mode.phase,
                spin_held_before: tr.before.mode.spin_held,
                spin_held_after: tr.after.mode.spin_held,
                state: tr.before.x,
                after: tr.after.x,
                witness: match tr.cause {
                    Cause::Witness(name) => Some(name),
                    _ => None,
                },
            })
            .collect()
    }

    /// Work done so far.
    pub fn stats(&self) -> Stats {
        self.run.stats()
    }

    /// Evaluations of the witnesses so far, each on one state: the cost of looking for
    /// events.
    pub fn event_evaluations(&self) -> u64 {
        self.run.witness_evaluations()
    }

    /// The run loop itself (its transitions, its halt).
    pub fn run(&self) -> &Hybrid<Adaptive<ContactSystem<'a, D>, P, STATE_LEN>> {
        &self.run
    }

    /// Steps until `t == t_stop`, or until the scene halts the run (lift-off, a disk lying
    /// flat, Painlevé's paradox, a normal force that would jump below zero). Asked again
    /// after a halt, it answers the same outcome.
    ///
    /// # Errors
    /// [`ContactError::SlipStopped`] when the slip of pure Coulomb sliding stops;
    /// [`ContactError::Ode`] as [`Adaptive::step`] (a non-finite or past `t_stop`, a step
    /// size underflow, a non-finite state, more than `max_steps` attempts towards
    /// `t_stop`), and [`crate::ode::OdeError::NonFiniteWitness`] for a witness that is not
    /// finite inside a step.
    pub fn advance_to(&mut self, t_stop: f64) -> Result<ContactOutcome, ContactError> {
        if self.run.halt().is_none() {
            self.run.advance_to(t_stop)?;
        }
        match self.run.halt() {
            None => Ok(ContactOutcome::Reached { t: self.t() }),
            Some(&ContactOutcome::SlipStopped {
                t, slip, threshold, ..
            }) => Err(ContactError::SlipStopped { t, slip, threshold }),
            Some(outcome) => Ok(*outcome),
        }
    }
}

crate::ode::delegate_stepper!(
    [D: ContactDynamics + ?Sized, P: EmbeddedPair] ContactRun<'_, D, P>,
    run,
    HybridState<ContactMode, [f64; STATE_LEN]>
);
