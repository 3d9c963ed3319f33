//! Pivoting friction in the run loop: the torque −ℓ_p N sign(ω·γ) γ is Coulomb's law for the
//! spin about the vertical, set-valued where the spin is zero. A run has two modes for it in
//! each phase: the spin free (the phase's derived equations) and the spin held at zero.
//!
//! **The spin stops.** The `spin` witness |ω·γ| − δ_ω (δ_ω = 10⁻⁹ of the angular velocity
//! scale V/|r|) falls through zero where a spin stops; there the flow on either side
//! decides, as Filippov's construction does for any switched vector field. The spin's rate
//! d(ω·γ)/dt = ω̇·γ (γ̇ ⊥ ω) on the two sides, ρ₊ under the friction −ℓ_p N γ and ρ₋ under
//! +ℓ_p N γ, differs by the friction alone, so ρ₊ < ρ₋, and:
//!
//! - ρ₊ ≤ 0 ≤ ρ₋, both pointing back to zero: the friction holds the spin (the couple the
//!   held motion needs, below, is within ℓ_p N: the `pivot cone` margin is ≥ 0). The spin is
//!   set to zero (under rolling the horizontal velocity put back on the constraint; the
//!   energy never raised) and the run goes on in the same phase with the spin held;
//! - both of one sign: the spin passes through zero, the way the couple the held motion
//!   would need could not hold it. It is set to 2δ_ω on the far side (the velocities then
//!   scaled back to the kinetic energy they had) and the phase goes on with the spin free.
//!
//! The test is the held motion's own margin, so that a spin held is never let go at once.
//!
//! **The spin held.** The phase's equations with the constraint d(ω·γ)/dt = ω̇·γ = 0 and a
//! pivot couple λγ in place of the friction, λ a multiplier. The equations are linear in the
//! accelerations and the contact's forces, so ẏ, N and the friction force are affine in λ:
//! ẏ(λ) = a + λ b. The derived equations at a spin of ±h (h far above the rounding of ω·γ,
//! far below δ_ω; their sign is then exactly ±1) are two points of that line, λ = ∓ℓ_p N_±,
//! and the held motion is the one point of it where ω̇·γ = 0:
//!
//! ẏ = ẏ₋ + θ (ẏ₊ − ẏ₋), θ = ρ₋/(ρ₋ − ρ₊), ρ_± = ω̇_±·γ,
//! N = N₋ + θ (N₊ − N₋), λ = ℓ_p ((1 − θ) N₋ − θ N₊)
//!
//! — Filippov's convex combination of the two sides, with the same θ for N and λ. The
//! couple does no work (its power is λ ω·γ = 0), so the energy balance is the phase's own.
//! The mode lasts while the `pivot cone` witness ℓ_p N − |λ| = 2ℓ_p min(θ N₊, (1 − θ) N₋)
//! is positive; at its root the couple the motion needs reaches ℓ_p N and the spin breaks
//! loose: it is seeded at 2δ_ω against the couple (the way the rest of the motion turns it),
//! the velocities scaled back to the kinetic energy they had, and the spin is free again.
//! The probes are at ±h with h = 10⁻¹³ (|ω| + |v|/|r|) + 10⁻¹⁰⁰ rad/s (some 300 times the
//! rounding of ω·γ), so the held motion is the constrained one to about 10⁻¹³ of the state's
//! own scales.
//!
//! The sign in the equations is ω·γ/√((ω·γ)² + ε²) with ε = 10⁻¹⁵⁰ rad/s, so the
//! right-hand side is finite, if meaningless, at a spin of exactly zero; a held run never
//! evaluates it there.

use nalgebra::Vector3;

use super::dynamics::{ContactDynamics, Reaction};
use super::error::ContactError;
use super::outcome::ContactOutcome;
use super::phases::{STICK_FRACTION, keep_kinetic, velocity_scale};
use super::scene::{ContactMode, Phase};
use super::state::{STATE_LEN, layout};
use super::system::Watch;
use crate::ode::Action;

type State = [f64; STATE_LEN];

/// The probes' spin h as a fraction of the state's angular scale |ω| + |v|/|r|.
const PROBE_FRACTION: f64 = 1e-13;

/// The probes' spin at a body at rest: far above the sign's ε = 10⁻¹⁵⁰ rad/s, so the sign is
/// exactly ±1 there too.
const PROBE_FLOOR: f64 = 1e-100;

/// A spin that breaks loose is seeded at this many times the spin taken as zero, so that
/// the `spin` witness starts positive.
const SEED_OVER_THRESHOLD: f64 = 2.0;

/// The motion of a body on a table with its spin about the vertical held at zero by a pivot
/// couple λγ ([`held_spin`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeldSpin {
    /// ẏ under the phase with ω̇·γ = 0.
    pub rates: [f64; STATE_LEN],
    /// The pivot couple λ about the vertical γ (N·m): the torque λγ the table puts on the
    /// body to hold the spin.
    pub couple: f64,
    /// The force of the table on the body with the couple in place.
    pub reaction: Reaction,
    /// ℓ_p N − |λ|: the room left in the pivot cone (the spin breaks loose at its root).
    pub margin: f64,
}

/// The motion of `body` under `phase` at `(t, y)` with its spin ω·γ held at zero by a pivot
/// couple λγ, λ solved with the phase's equations (see the module's note in the docs:
/// "Pivoting friction in the run loop"). The spin of `y` itself is not read: the motion is
/// the held one through `y` with its spin set to zero.
///
/// # Errors
/// As [`ContactDynamics::check_parameters`] and [`ContactDynamics::check_state`];
/// [`ContactError::NoPivoting`] for a body without pivoting friction.
pub fn held_spin<D: ContactDynamics + ?Sized>(
    body: &D,
    phase: Phase,
    t: f64,
    y: &State,
) -> Result<HeldSpin, ContactError> {
    body.check_parameters()?;
    body.check_state(phase, y)?;
    let pivoting = body
        .values()
        .coefficients
        .iter()
        .find(|(n, _)| *n == "pivoting")
        .map(|&(_, l)| l)
        .ok_or(ContactError::NoPivoting {
            law: body.law().name(),
        })?;
    Ok(held(body, pivoting, phase, t, y))
}

/// The held motion at `x` under `phase` with pivoting coefficient `pivoting`, unchecked.
pub(crate) fn held<D: ContactDynamics + ?Sized>(
    body: &D,
    pivoting: f64,
    phase: Phase,
    t: f64,
    x: &State,
) -> HeldSpin {
    let c = body.contact(x);
    let r = c.body.norm().max(f64::MIN_POSITIVE);
    let v = x[layout::VELOCITY].hypot(x[layout::VELOCITY + 1]);
    let h = PROBE_FRACTION * (omega(x).norm() + v / r) + PROBE_FLOOR;
    let probe = |s: f64| {
        let y = with_spin(body, phase, x, s);
        let mut d = [0.0; STATE_LEN];
        body.phase_rhs(phase, t, &y, &mut d);
        let w_dot = Vector3::new(d[layout::OMEGA], d[layout::OMEGA + 1], d[layout::OMEGA + 2]);
        (d, w_dot.dot(&c.gamma), body.reaction(phase, &y))
    };
    let (up, rate_up, r_up) = probe(h);
    let (down, rate_down, r_down) = probe(-h);
    let span = rate_down - rate_up;
    // ρ₋ − ρ₊ = ℓ_p (N₊ + N₋) γ·(∂ω̇/∂λ): zero only without friction or without a push.
    let theta = if span != 0.0 && span.is_finite() {
        rate_down / span
    } else {
        0.5
    };
    let mix = |plus: f64, minus: f64| minus + theta * (plus - minus);
    let rates = std::array::from_fn(|k| mix(up[k], down[k]));
    let normal = mix(r_up.normal, r_down.normal);
    let friction = r_down.friction + theta * (r_up.friction - r_down.friction);
    let couple = mix(-pivoting * r_up.normal, pivoting * r_down.normal);
    HeldSpin {
        rates,
        couple,
        reaction: Reaction { normal, friction },
        margin: pivoting * normal - couple.abs(),
    }
}

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
pub(crate) fn with_spin<D: ContactDynamics + ?Sized>(
    body: &D,
    phase: Phase,
    x: &State,
    target: f64,
) -> State {
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

/// `x` with its spin set to zero under `phase`, its velocities scaled down to the kinetic
/// energy of `x` should that have raised it (under rolling the horizontal velocity follows
/// ω): holding the spin never adds energy.
pub(crate) fn spin_zeroed<D: ContactDynamics + ?Sized>(
    body: &D,
    w: &Watch,
    phase: Phase,
    x: &State,
) -> State {
    let y = with_spin(body, phase, x, 0.0);
    if body.energy(phase, &y) > body.energy(phase, x) {
        keep_kinetic(body, w, (phase, x), (phase, y))
    } else {
        y
    }
}

/// The spin of `x` has fallen to δ_ω under `phase` at `t`: held at zero where the friction
/// holds it, otherwise carried through zero (see the module's note).
pub(crate) fn spin_stopped<D: ContactDynamics + ?Sized>(
    body: &D,
    w: &Watch,
    t: f64,
    phase: Phase,
    x: State,
) -> Action<ContactMode, State, ContactOutcome> {
    let held = held(body, w.pivoting.unwrap_or(0.0), phase, t, &x);
    if held.margin >= 0.0 {
        return Action::Switch {
            mode: ContactMode::held(phase),
            state: spin_zeroed(body, w, phase, &x),
            fresh: false,
        };
    }
    loose(body, w, phase, x, held.couple)
}

/// The pivot couple a held spin needs has reached ℓ_p N at `x` under `phase`: the spin
/// breaks loose, seeded at 2δ_ω against the couple (the way the rest of the motion turns
/// it), the velocities scaled back to the kinetic energy they had.
pub(crate) fn break_loose<D: ContactDynamics + ?Sized>(
    body: &D,
    w: &Watch,
    t: f64,
    phase: Phase,
    x: State,
) -> Action<ContactMode, State, ContactOutcome> {
    let couple = held(body, w.pivoting.unwrap_or(0.0), phase, t, &x).couple;
    loose(body, w, phase, x, couple)
}

/// The spin of `x` let go under `phase`: seeded at 2δ_ω against `couple`, the pivot couple
/// that could not hold it (the way the rest of the motion turns it), the velocities scaled
/// back to the kinetic energy they had.
fn loose<D: ContactDynamics + ?Sized>(
    body: &D,
    w: &Watch,
    phase: Phase,
    x: State,
    couple: f64,
) -> Action<ContactMode, State, ContactOutcome> {
    let target = -couple.signum() * SEED_OVER_THRESHOLD * spin_threshold(body, w, &x);
    let y = with_spin(body, phase, &x, target);
    Action::Switch {
        mode: ContactMode::free(phase),
        state: keep_kinetic(body, w, (phase, &x), (phase, y)),
        fresh: false,
    }
}
