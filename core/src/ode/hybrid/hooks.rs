//! What a scene gives the run loop ([`Hooks`], implemented by its system), what the loop
//! needs of the stepper it wraps ([`Switchable`]), and what the loop hands back (the
//! [`HybridState`], the [`Transition`]s).

use core::fmt::Debug;
use core::ops::Deref;

use crate::ode::error::OdeError;
use crate::ode::stepper::Stepper;
use crate::ode::trajectory::StateColumns;

/// A discrete mode of a scene: a chart, a contact's phase, or `()` for a scene with one.
pub trait Mode: Clone + PartialEq + Debug {
    /// The name of the mode's column in a trajectory's CSV, or `None` for a scene with one
    /// mode (no column).
    const COLUMN: Option<&'static str> = None;

    /// The mode as a number, for that column.
    fn number(&self) -> f64 {
        0.0
    }
}

impl Mode for () {}

/// A stepper whose system can be changed between steps: what the loop needs of the stepper
/// it wraps. Implemented by the adaptive pairs, [`Rk4`](crate::ode::Rk4), the fixed-step
/// methods and the Taylor integrator.
pub trait Switchable: Stepper {
    /// The system (or method) being integrated.
    type System;

    /// The system.
    fn system(&self) -> &Self::System;

    /// Changes the system with `change` and puts the stepper at `(t, state)`: as a fresh
    /// start when `fresh` (the first step size chosen again), as a continued run otherwise
    /// (the step size kept, as [`Stepper::restart`]).
    ///
    /// # Errors
    /// As [`Stepper::restart`]: the state's and the changed system's checks.
    fn switch(
        &mut self,
        t: f64,
        state: Self::State,
        fresh: bool,
        change: &mut dyn FnMut(&mut Self::System),
    ) -> Result<(), OdeError>;
}

/// The state of a hybrid run: the continuous state `x` and the mode it is integrated in.
/// It dereferences to `x`, so a quantity or event written for the continuous state reads it
/// unchanged (`|_t, s| s[0]`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HybridState<M, X> {
    /// The mode.
    pub mode: M,
    /// The continuous state.
    pub x: X,
}

impl<M, X> Deref for HybridState<M, X> {
    type Target = X;
    fn deref(&self) -> &X {
        &self.x
    }
}

/// The continuous state's columns, then the mode's (when [`Mode::COLUMN`] names one).
impl<M: Mode, X: StateColumns> StateColumns for HybridState<M, X> {
    fn column_count() -> usize {
        X::column_count() + usize::from(M::COLUMN.is_some())
    }
    fn column_name(i: usize) -> String {
        match M::COLUMN {
            Some(name) if i == X::column_count() => name.to_owned(),
            _ => X::column_name(i),
        }
    }
    fn column(&self, i: usize) -> f64 {
        if M::COLUMN.is_some() && i == X::column_count() {
            self.mode.number()
        } else {
            self.x.column(i)
        }
    }
}

/// What a hook asks of the loop.
#[derive(Debug, Clone, PartialEq)]
pub enum Action<M, X, H> {
    /// Go on as it is.
    Continue,
    /// Go on from `state` in `mode` (the same mode for an impulse that only changes the
    /// state); `fresh` restarts the wrapped stepper as new (its first step chosen again:
    /// for a state in other coordinates, a chart's), otherwise its step size is kept.
    Switch {
        /// The mode to go on in.
        mode: M,
        /// The state to go on from.
        state: X,
        /// Whether the wrapped stepper starts afresh.
        fresh: bool,
    },
    /// End the run here with the scene's outcome.
    Halt(H),
}

/// The action type of a scene's hooks over the state `X`.
pub type HookAction<H, X> = Action<<H as Hooks<X>>::Mode, X, <H as Hooks<X>>::Halt>;

/// Why a switch happened.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cause {
    /// At the start of the run ([`Hooks::start`]).
    Start,
    /// At the located root of the named witness, or at a mode's entry where it was ≤ 0.
    Witness(&'static str),
    /// At a step's end ([`Hooks::after_step`]: a guard, a chart switch).
    StepEnd,
}

/// A switch the loop took: when, why, and the states on both sides.
#[derive(Debug, Clone, PartialEq)]
pub struct Transition<M, X> {
    /// When.
    pub t: f64,
    /// Why.
    pub cause: Cause,
    /// The state before (the mode it left and the state that mode reached).
    pub before: HybridState<M, X>,
    /// The state after (the mode it entered and the state it starts from, projected).
    pub after: HybridState<M, X>,
}

/// A scene's part in the run loop, implemented by the system the loop integrates (as Drake's
/// systems declare their witness functions): its mode, its witnesses, its projection, and
/// what it does at the start, at each step's end and at a witness's root.
///
/// The hooks take `&self`: what they decide is returned as an [`Action`] (a new state, a new
/// mode, a halt), never kept in the system, so a run's history is in its
/// [`Transition`]s and its outcome. They read the mode from what they are handed (the
/// [`HybridState`], the `mode` argument), never from `self`: a switch reaches the system
/// only when the next step starts, so that the last step's solution stays available.
pub trait Hooks<X> {
    /// The modes (`()` for a scene with one).
    type Mode: Mode;
    /// The typed outcome of a halt (lift-off, a disk fallen flat, …).
    type Halt: Clone + Debug + PartialEq;

    /// The current mode.
    fn mode(&self) -> Self::Mode;

    /// Puts the system in `mode`.
    fn set_mode(&mut self, mode: Self::Mode);

    /// The witnesses' names, by index; the index is the `id` of the other methods. The
    /// default has none.
    fn witness_names(&self) -> &[&'static str] {
        &[]
    }

    /// Whether witness `id` is watched in `mode`. The default watches every witness.
    fn watches(&self, _mode: &Self::Mode, _id: usize) -> bool {
        true
    }

    /// Witness `id` at `(t, x)` in `mode`: positive while the mode holds, its fall through
    /// zero the event. It must be continuous along the motion (what can jump is a guard of
    /// [`Hooks::after_step`]). The default is 1 (never falls).
    fn witness(&self, _mode: &Self::Mode, _id: usize, _t: f64, _x: &X) -> f64 {
        1.0
    }

    /// Puts `x` back on its manifold after an accepted step (a unit quaternion); returns
    /// whether it changed. The default changes nothing.
    fn project(&self, _x: &mut X) -> bool {
        false
    }

    /// At the start of the run, before the first step: a mode the state cannot start in is
    /// switched, a state that cannot go on halts. The default goes on.
    ///
    /// # Errors
    /// The scene's refusal of the start, as an [`OdeError`].
    fn start(
        &self,
        _t: f64,
        _s: &HybridState<Self::Mode, X>,
    ) -> Result<Action<Self::Mode, X, Self::Halt>, OdeError> {
        Ok(Action::Continue)
    }

    /// At the end of each accepted step without a witness's root, after the projection: the
    /// guards, and the switches made between steps (a chart near its singularity). The
    /// default goes on.
    ///
    /// # Errors
    /// The scene's failure, as an [`OdeError`].
    fn after_step(
        &self,
        _t: f64,
        _s: &HybridState<Self::Mode, X>,
    ) -> Result<Action<Self::Mode, X, Self::Halt>, OdeError> {
        Ok(Action::Continue)
    }

    /// At the root of witness `id` at `t` (or at a mode's entry where the witness is
    /// already ≤ 0): `s` is the state at the last double at which the witness was still
    /// positive (or exactly 0), projected, and `w` the witness there. The default goes on.
    ///
    /// # Errors
    /// The scene's failure, as an [`OdeError`].
    fn on_witness(
        &self,
        _id: usize,
        _t: f64,
        _s: &HybridState<Self::Mode, X>,
        _w: f64,
    ) -> Result<Action<Self::Mode, X, Self::Halt>, OdeError> {
        Ok(Action::Continue)
    }
}
