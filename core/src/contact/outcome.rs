//! What a run of a body on a table reports: how it ended ([`ContactOutcome`], the halt the
//! contact's hooks in `phases.rs` give the run loop) and each change of phase ([`Switch`]).

use super::scene::Phase;
use super::state::STATE_LEN;

/// How a [`ContactRun::advance_to`] ended, and the outcome of a run its scene halted
/// ([`Hybrid::halt`]: every variant but `Reached`). Every state an outcome carries is one of
/// the phase that reached it, with N ≥ 0.
///
/// [`ContactRun::advance_to`]: super::ContactRun::advance_to
/// [`Hybrid::halt`]: crate::ode::Hybrid::halt
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ContactOutcome {
    /// The stop time was reached with the body on the table.
    Reached {
        /// The stop time.
        t: f64,
    },
    /// The normal force fell continuously to zero: the body leaves the table here (the run
    /// stops; the model of a body on a table ends, and a free flight would begin).
    LiftOff {
        /// The last time N was ≥ 0 (N is 0 there to the located root's accuracy).
        t: f64,
        /// The state then.
        state: [f64; STATE_LEN],
    },
    /// A slip restarting in a new direction (a Coulomb slip reversal) would need a negative
    /// normal force: N jumps there, which no rigid contact can give.
    NormalForceJump {
        /// When.
        t: f64,
        /// The state then (the new slip seeded).
        state: [f64; STATE_LEN],
        /// The phase left.
        phase: Phase,
        /// N in the phase left.
        before: f64,
        /// N sliding again (negative).
        after: f64,
    },
    /// Painlevé's paradox: under Coulomb sliding the normal force's denominator reached
    /// zero, so the rigid-body equations give no consistent N (as the denominator nears zero
    /// N grows without bound).
    Painleve {
        /// The last time the denominator was positive.
        t: f64,
        /// The state then.
        state: [f64; STATE_LEN],
        /// The denominator there (≥ 0, at the root).
        denominator: f64,
        /// N there.
        normal: f64,
    },
    /// The support map can no longer place the contact: a disk rim or torus lying flat (its
    /// axis within `MIN_TILT` of the vertical), a paraboloid touching past its rim.
    Unsupported {
        /// The last time the contact was placed.
        t: f64,
        /// The state then.
        state: [f64; STATE_LEN],
        /// The surface.
        surface: &'static str,
        /// The witness there: sin(tilt) − sin(MIN_TILT) for a disk rim or torus, γ₃ for a
        /// paraboloid (≥ 0 at the root).
        margin: f64,
    },
    /// Pure Coulomb sliding whose slip stopped (through a [`Run`](crate::ode::Run); a
    /// [`ContactRun::advance_to`] returns [`ContactError::SlipStopped`] instead).
    ///
    /// [`ContactRun::advance_to`]: super::ContactRun::advance_to
    /// [`ContactError::SlipStopped`]: super::ContactError::SlipStopped
    SlipStopped {
        /// When.
        t: f64,
        /// The state then.
        state: [f64; STATE_LEN],
        /// The slip speed there.
        slip: f64,
        /// The slip speed taken as zero.
        threshold: f64,
    },
}

/// A change of phase during a run: the loop's [`Transition`](crate::ode::Transition) of a
/// contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Switch {
    /// When.
    pub t: f64,
    /// The phase before.
    pub from: Phase,
    /// The phase after (the same for a slip restarted in a new direction, and for a spin
    /// that pivoting friction comes to hold or lets go).
    pub to: Phase,
    /// Whether pivoting friction held the spin at zero before.
    pub spin_held_before: bool,
    /// Whether it holds it after.
    pub spin_held_after: bool,
    /// The state at the switch, as the phase before left it (before the slip is seeded or
    /// the contact point brought to rest).
    pub state: [f64; STATE_LEN],
    /// The state the phase after starts from.
    pub after: [f64; STATE_LEN],
    /// The witness whose root it was (`friction cone`, `slip speed`, `spin`, `pivot cone`),
    /// or `None` for a switch the start made.
    pub witness: Option<&'static str>,
}
