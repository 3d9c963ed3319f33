//! Pivoting friction in the run loop: the torque −ℓ_p N sign(ω·γ) γ is Coulomb's law for the
//! spin about the vertical, set-valued where the spin is zero. The `spin` witness
//! |ω·γ| − δ_ω (δ_ω = 10⁻⁹ of the angular velocity scale V/|r|) falls through zero where a
//! spin stops; there the flow on either side decides, as Filippov's construction does for
//! any switched vector field:
//!
//! - the spin's rate d(ω·γ)/dt = ω̇·γ (γ̇ ⊥ ω) is evaluated at the spins +δ_ω and −δ_ω
//!   (each the phase's own equations, the rest of the state the same);
//! - both point back to zero: the friction holds the spin (the torque the rest of the motion
//!   puts on it is within ℓ_p N). The run halts with
//!   [`ContactOutcome::SpinStopped`](super::ContactOutcome::SpinStopped): a phase with the
//!   spin held is not modelled;
//! - both point the same way: the spin passes through zero. It is set to 2δ_ω on the far
//!   side (the velocities then scaled back to the kinetic energy they had, and under rolling
//!   the horizontal velocity put back on the constraint) and the phase goes on.
//!
//! The sign in the equations is ω·γ/√((ω·γ)² + ε²) with ε = 10⁻¹⁵⁰ rad/s, so the
//! right-hand side is finite, if meaningless, at a spin of exactly zero.

use nalgebra::Vector3;

use super::dynamics::ContactDynamics;
use super::outcome::ContactOutcome;
use super::phases::{STICK_FRACTION, keep_kinetic, velocity_scale};
use super::scene::Phase;
use super::state::{STATE_LEN, layout};
use super::system::Watch;
use crate::ode::Action;

type State = [f64; STATE_LEN];

/// The spin taken as zero at `x`: 10⁻⁹ of V/|r|, V the velocity scale, or what the stepper
/// resolves at that scale where that is larger.
pub(crate) fn spin_threshold<D: ContactDynamics + ?Sized>(body: &D, w: &Watch, x: &State) -> f64 {
    let r = body.contact(x).body.norm().max(f64::MIN_POSITIVE);
    let scale = velocity_scale(body, w, x) / r;
    (STICK_FRACTION * scale).max(w.resolved(scale))
}

/// The spin about the vertical, ω·γ.
pub(crate) fn spin<D: ContactDynamics + ?Sized>(body: &D, x: &State) -> f64 {
    body.contact(x).gamma.dot(&omega(x))
}

fn omega(x: &State) -> Vector3<f64> {
    Vector3::new(x[layout::OMEGA], x[layout::OMEGA + 1], x[layout::OMEGA + 2])
}

/// |ω·γ| − δ_ω: positive while the body spins.
pub(crate) fn spin_margin<D: ContactDynamics + ?Sized>(body: &D, w: &Watch, x: &State) -> f64 {
    spin(body, x).abs() - spin_threshold(body, w, x)
}

/// `x` with its spin ω·γ set to `target`, the rest of ω kept; under rolling the horizontal
/// velocity is put back on the constraint the new ω sets.
fn with_spin<D: ContactDynamics + ?Sized>(body: &D, phase: Phase, x: &State, target: f64) -> State {
    let c = body.contact(x);
    let w = omega(x) + (target - c.gamma.dot(&omega(x))) * c.gamma;
    let mut y = *x;
    y[layout::OMEGA..layout::OMEGA + 3].copy_from_slice(w.as_slice());
    if phase == Phase::Rolling {
        let u = body.contact(&y).velocity;
        y[layout::VELOCITY] -= u.x;
        y[layout::VELOCITY + 1] -= u.y;
    }
    y
}

/// d(ω·γ)/dt = ω̇·γ under `phase` at `x`.
fn spin_rate<D: ContactDynamics + ?Sized>(body: &D, phase: Phase, t: f64, x: &State) -> f64 {
    let mut d = [0.0; STATE_LEN];
    body.phase_rhs(phase, t, x, &mut d);
    let w_dot = Vector3::new(d[layout::OMEGA], d[layout::OMEGA + 1], d[layout::OMEGA + 2]);
    w_dot.dot(&body.contact(x).gamma)
}

/// The spin of `x` has fallen to δ_ω under `phase` at `t`: halt where the friction holds it,
/// otherwise carry it through zero (see the module's note).
pub(crate) fn spin_stopped<D: ContactDynamics + ?Sized>(
    body: &D,
    w: &Watch,
    t: f64,
    phase: Phase,
    x: State,
) -> Action<Phase, State, ContactOutcome> {
    let delta = spin_threshold(body, w, &x);
    let up = spin_rate(body, phase, t, &with_spin(body, phase, &x, delta));
    let down = spin_rate(body, phase, t, &with_spin(body, phase, &x, -delta));
    if up <= 0.0 && down >= 0.0 {
        return Action::Halt(ContactOutcome::SpinStopped {
            t,
            state: x,
            spin: spin(body, &x),
            threshold: delta,
        });
    }
    let target = if up + down > 0.0 { 2.0 } else { -2.0 } * delta;
    let y = with_spin(body, phase, &x, target);
    Action::Switch {
        mode: phase,
        state: keep_kinetic(body, w, (phase, &x), (phase, y)),
        fresh: false,
    }
}
