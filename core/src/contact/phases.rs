//! The contact's hooks in the run loop: its phases (rolling, sliding), each with the spin
//! free or held at zero by pivoting friction ([`ContactMode`]), as the loop's modes, and the
//! witnesses at whose roots a body on a table changes mode or stops.
//!
//! | witness | watched | positive while | at its root |
//! | --- | --- | --- | --- |
//! | `normal force` N | always | the table pushes | lift-off (halt) |
//! | `friction cone` μN − \|F_t\| | rolling, stick–slip | rolling can hold | slip seeded against the friction rolling needs |
//! | `slip speed` \|u\| − δ | Coulomb sliding | the body slides | a plastic tangential impulse removes u; rolling if it holds, else the slip restarts (stick–slip); halt with [`ContactError::SlipStopped`] (pure Coulomb) |
//! | `solvability` D | Coulomb sliding | N has one value | Painlevé's paradox (halt) |
//! | `support` | disk rims, tori, paraboloids | the support map places the contact | lying flat or past the rim (halt) |
//! | `spin` \|ω·γ\| − δ_ω | pivoting friction, spin free | the body spins | the friction holds the spin: the same phase with the spin held; or the spin passes zero (`pivot.rs`) |
//! | `pivot cone` ℓ_p N − \|λ\| | spin held | the couple λ holding the spin is within ℓ_p N | the spin breaks loose, seeded against the couple (`pivot.rs`) |
//!
//! δ is 10⁻⁹ of the velocity scale V = |v| + |ω||r| + √(g|r|), the rolling states' own
//! tolerance, or what the run's stepper resolves (atol + rtol V) where that is larger: a slip
//! below the stepper's accuracy cannot be told from zero, and under Coulomb friction it
//! chatters there, the friction reversing from step to step, until it falls below δ by
//! chance (δ_ω likewise, at the scale V/|r|). Every witness is continuous along a phase's motion (D > 0 keeps N continuous
//! under Coulomb sliding), so each root is located on the stepper's solution; what can jump
//! — N when a slip restarts in a new direction — jumps only at a switch, where the new phase
//! is checked before it is entered: a restart that would need N < 0 (or D ≤ 0) halts and
//! names the jump. No state the loop returns has N < 0.
//!
//! Sticking is a plastic impulse, not a reset of the velocity: the tangential impulse
//! P = −K⁻¹u at the contact point, K = 1/M − [r]ₓ I⁻¹ [r]ₓ (space axes), brings the contact
//! point to rest and changes the energy by −½ uᵀK⁻¹u ≤ 0; a seeded slip keeps the kinetic
//! energy (the velocities scaled back by 1 + O(10⁻⁹)), so no switch ever adds energy.

use nalgebra::{Matrix3, Vector3};

use super::checks::MIN_TILT;
use super::dynamics::ContactDynamics;
use super::dynamics::Reaction;
use super::error::ContactError;
use super::outcome::ContactOutcome;
use super::pivot;
use super::scene::{ContactMode, LawKind, Phase};
use super::state::{STATE_LEN, attitude_of, layout};
use super::surface::SurfaceKind;
use super::system::{ContactSystem, Watch};
use crate::ode::{Action, Hooks, HybridState, Mode, OdeError};
use crate::rigid::normalise_quaternion;

/// The slip speed taken as zero, as a fraction of the velocity scale V = |v| + |ω||r| +
/// √(g|r|): the rolling states' tolerance (`ROLLING_TOLERANCE`).
pub const STICK_FRACTION: f64 = 1e-9;

/// A seeded slip is this many times the slip speed taken as zero, so that the slip witness
/// starts positive.
const SEED_OVER_STICK: f64 = 2.0;

/// The witnesses, by index.
const NAMES: [&str; 7] = [
    "normal force",
    "friction cone",
    "slip speed",
    "solvability",
    "support",
    "spin",
    "pivot cone",
];
const NORMAL: usize = 0;
const CONE: usize = 1;
const SLIP: usize = 2;
const SOLVABLE: usize = 3;
const SUPPORT: usize = 4;
const SPIN: usize = 5;
const PIVOT: usize = 6;

type State = [f64; STATE_LEN];
type ContactAction = Action<ContactMode, State, ContactOutcome>;

/// The phase as the mode of a run: its CSV column `phase` holds 0 rolling, 1 sliding, and 2
/// more where the spin is held (2 rolling, 3 sliding).
impl Mode for ContactMode {
    const COLUMN: Option<&'static str> = Some("phase");

    fn number(&self) -> f64 {
        let phase = match self.phase {
            Phase::Rolling => 0.0,
            Phase::Sliding => 1.0,
        };
        if self.spin_held { phase + 2.0 } else { phase }
    }
}

impl<D: ContactDynamics + ?Sized> Hooks<State> for ContactSystem<'_, D> {
    type Mode = ContactMode;
    type Halt = ContactOutcome;

    fn mode(&self) -> ContactMode {
        ContactMode {
            phase: self.phase,
            spin_held: self.spin_held,
        }
    }

    fn set_mode(&mut self, mode: ContactMode) {
        self.phase = mode.phase;
        self.spin_held = mode.spin_held;
    }

    fn witness_names(&self) -> &[&'static str] {
        &NAMES
    }

    fn watches(&self, mode: &ContactMode, id: usize) -> bool {
        let w = &self.watch;
        let sliding = mode.phase == Phase::Sliding;
        let coulomb_sliding = sliding && w.mu.is_some();
        // N solves a linear equation whose coefficient a friction or torque proportional to
        // N can bring to zero.
        let scaled = w.mu.is_some() || w.normal_viscous.is_some() || w.pivoting.is_some();
        match id {
            NORMAL => true,
            CONE => mode.phase == Phase::Rolling && w.law == LawKind::StickSlip,
            SLIP => coulomb_sliding,
            SOLVABLE => sliding && scaled,
            SPIN => w.pivoting.is_some() && !mode.spin_held,
            PIVOT => w.pivoting.is_some() && mode.spin_held,
            SUPPORT => matches!(
                w.surface,
                SurfaceKind::DiskRim | SurfaceKind::Torus | SurfaceKind::Paraboloid
            ),
            _ => false,
        }
    }

    fn witness(&self, mode: &ContactMode, id: usize, t: f64, x: &State) -> f64 {
        let (body, w) = (self.body, &self.watch);
        match id {
            NORMAL => reaction(body, w, *mode, x).normal,
            CONE => cone_margin(body, w, mode.spin_held, x),
            SLIP => {
                let u = slip(body, x);
                u.norm() - stick_speed(body, w, x)
            }
            SOLVABLE => denominator(body, w, mode.spin_held, x),
            SUPPORT => support_margin(w, x),
            SPIN => pivot::spin_margin(body, w, x),
            PIVOT => pivot::held(body, w.pivoting.unwrap_or(0.0), mode.phase, t, x).margin,
            _ => 1.0,
        }
    }

    /// The quaternion back on the unit sphere; with the spin held, a spin the steps let
    /// drift (below δ_ω: a spin seeded as it breaks loose is twice that) back to zero, under
    /// rolling the horizontal velocity with it.
    fn project(&self, x: &mut State) -> bool {
        let mut changed = normalise_quaternion(x, layout::QUATERNION);
        if self.spin_held
            && pivot::spin(self.body, x) != 0.0
            && pivot::spin_margin(self.body, &self.watch, x) < 0.0
        {
            *x = pivot::with_spin(self.body, self.phase, x, 0.0);
            changed = true;
        }
        changed
    }

    fn on_witness(
        &self,
        id: usize,
        t: f64,
        s: &HybridState<ContactMode, State>,
        _w: f64,
    ) -> Result<ContactAction, OdeError> {
        let (body, w, x) = (self.body, &self.watch, s.x);
        let held = s.mode.spin_held;
        Ok(match id {
            NORMAL => Action::Halt(ContactOutcome::LiftOff { t, state: x }),
            CONE => enter_sliding(body, w, t, seeded(body, w, held, x), s.mode),
            SLIP => match w.law {
                LawKind::StickSlip => stick(body, w, t, x, held),
                _ => Action::Halt(ContactOutcome::SlipStopped {
                    t,
                    state: x,
                    slip: slip(body, &x).norm(),
                    threshold: stick_speed(body, w, &x),
                }),
            },
            SOLVABLE => Action::Halt(ContactOutcome::Painleve {
                t,
                state: x,
                denominator: denominator(body, w, held, &x),
                normal: reaction(body, w, s.mode, &x).normal,
            }),
            SUPPORT => Action::Halt(ContactOutcome::Unsupported {
                t,
                state: x,
                surface: w.surface.name(),
                margin: support_margin(w, &x),
            }),
            SPIN => pivot::spin_stopped(body, w, t, s.mode.phase, x),
            PIVOT => pivot::break_loose(body, w, t, s.mode.phase, x),
            _ => Action::Continue,
        })
    }
}

/// The force of the table on the body in `mode`: the phase's own, or with the spin held
/// the one with the pivot couple in place.
fn reaction<D: ContactDynamics + ?Sized>(
    body: &D,
    w: &Watch,
    mode: ContactMode,
    x: &State,
) -> Reaction {
    if mode.spin_held {
        pivot::held(body, w.pivoting.unwrap_or(0.0), mode.phase, 0.0, x).reaction
    } else {
        body.reaction(mode.phase, x)
    }
}

/// The slip velocity of the contact point (space axes, horizontal).
fn slip<D: ContactDynamics + ?Sized>(body: &D, x: &State) -> Vector3<f64> {
    let u = body.contact(x).velocity;
    Vector3::new(u.x, u.y, 0.0)
}

/// The velocity scale V = |v| + |ω||r| + √(g|r|) of a state.
pub(crate) fn velocity_scale<D: ContactDynamics + ?Sized>(body: &D, w: &Watch, x: &State) -> f64 {
    let c = body.contact(x);
    let v = Vector3::new(x[layout::VELOCITY], x[layout::VELOCITY + 1], 0.0);
    let omega = omega(x);
    let r = c.body.norm();
    v.norm() + omega.norm() * r + (w.gravity * r).sqrt()
}

/// The slip speed taken as zero at `x`: 10⁻⁹ of the velocity scale V, or what the stepper
/// resolves at V (atol + rtol V) where that is larger.
pub(crate) fn stick_speed<D: ContactDynamics + ?Sized>(body: &D, w: &Watch, x: &State) -> f64 {
    let scale = velocity_scale(body, w, x);
    (STICK_FRACTION * scale).max(w.resolved(scale))
}

fn omega(x: &State) -> Vector3<f64> {
    Vector3::new(x[layout::OMEGA], x[layout::OMEGA + 1], x[layout::OMEGA + 2])
}

/// μN − |F_t| of rolling at `x` (the spin held or not): the room left in the friction cone.
fn cone_margin<D: ContactDynamics + ?Sized>(body: &D, w: &Watch, held: bool, x: &State) -> f64 {
    let mode = ContactMode {
        phase: Phase::Rolling,
        spin_held: held,
    };
    let r = reaction(body, w, mode, x);
    w.mu.unwrap_or(0.0) * r.normal - r.friction.norm()
}

/// The denominator D = 1 − M (γ × r)·I⁻¹(r × e + κ) of the normal force of sliding
/// (description axes), the contact force being F₀ + N e and the torque N κ: e = γ − μ û
/// under Coulomb friction, γ − μ u under F = −μ N u, κ = −ℓ_p sign(ω·γ) γ for pivoting
/// friction. N = A/D with A free of them, so D ≤ 0 is Painlevé's paradox. Under Coulomb
/// friction, 1 when the slip has no direction. With the spin held (`held`) the pivot couple
/// λγ solves ω̇·γ = 0, which takes the part of N's torque about γ away:
/// κ = −γ (γ·I⁻¹(r × e))/(γ·I⁻¹γ).
pub(crate) fn denominator<D: ContactDynamics + ?Sized>(
    body: &D,
    w: &Watch,
    held: bool,
    x: &State,
) -> f64 {
    let c = body.contact(x);
    let u_space = slip(body, x);
    let speed = u_space.norm();
    let u_body = attitude_of(x).inverse_transform_vector(&u_space);
    let e = match (w.mu, w.normal_viscous) {
        (Some(_), _) if speed == 0.0 => return 1.0,
        (Some(mu), _) => c.gamma - mu * u_body / speed,
        (None, Some(mu)) => c.gamma - mu * u_body,
        (None, None) => c.gamma,
    };
    let spin = c.gamma.dot(&omega(x));
    let kappa = match w.pivoting {
        _ if held => {
            let along = w.inertia_inv * c.gamma;
            -c.gamma * c.gamma.dot(&(w.inertia_inv * c.body.cross(&e))) / c.gamma.dot(&along)
        }
        Some(l) if spin != 0.0 => -l * spin.signum() * c.gamma,
        _ => Vector3::zeros(),
    };
    let beta = w.inertia_inv * (c.body.cross(&e) + kappa);
    1.0 - w.mass * c.gamma.cross(&c.body).dot(&beta)
}

/// The denominator D = 1 − M (γ × r)·I⁻¹(r × e), e = γ − μ û, of the normal force of
/// Coulomb sliding at `y` (description axes): N = A/D with A free of μ, so D ≤ 0 is
/// Painlevé's paradox, which a run watches for. 1 where the slip is zero (no direction) or
/// the law has no Coulomb friction (μ = 0).
///
/// # Errors
/// As [`ContactDynamics::check_parameters`].
pub fn normal_denominator<D: ContactDynamics + ?Sized>(
    body: &D,
    y: &State,
) -> Result<f64, ContactError> {
    let sys = ContactSystem::new(body, Phase::Sliding)?;
    Ok(denominator(body, &sys.watch, false, y))
}

/// How far the support map is from its singular set: sin(tilt) − sin(MIN_TILT) of a disk
/// rim's or torus's axis, γ₃ of a paraboloid (its bowl facing the table), 1 for the others.
fn support_margin(w: &Watch, x: &State) -> f64 {
    let gamma = attitude_of(x).inverse_transform_vector(&Vector3::z());
    match w.surface {
        SurfaceKind::DiskRim | SurfaceKind::Torus => gamma.x.hypot(gamma.y) - MIN_TILT.sin(),
        SurfaceKind::Paraboloid => gamma.z,
        _ => 1.0,
    }
}

/// `x` with a slip of [`SEED_OVER_STICK`] times the stick speed started against the
/// friction rolling needs there (Coulomb's law needs a direction, and at the switch the slip
/// is zero), the velocities then scaled by √(T/T') so that the kinetic energy T, and so the
/// energy, is what it was: seeding never adds energy. A held spin stays zero (the scaling
/// keeps it).
fn seeded<D: ContactDynamics + ?Sized>(body: &D, w: &Watch, held: bool, x: State) -> State {
    let rolling = ContactMode {
        phase: Phase::Rolling,
        spin_held: held,
    };
    let f = reaction(body, w, rolling, &x).friction;
    let dir = -f / f.norm().max(f64::MIN_POSITIVE);
    let seed = SEED_OVER_STICK * stick_speed(body, w, &x);
    let mut y = x;
    y[layout::VELOCITY] += seed * dir.x;
    y[layout::VELOCITY + 1] += seed * dir.y;
    keep_kinetic(body, w, (Phase::Rolling, &x), (Phase::Sliding, y))
}

/// `y` (in `to`) with its velocities scaled by √(T/T′), so that its kinetic energy T′ is
/// the kinetic energy T of `x` (in `from`), and with the attitude unchanged, its energy:
/// a state changed by a switch's seed so adds no energy.
pub(crate) fn keep_kinetic<D: ContactDynamics + ?Sized>(
    body: &D,
    w: &Watch,
    (from, x): (Phase, &State),
    (to, mut y): (Phase, State),
) -> State {
    // The potential energy depends on the attitude alone, which the seed leaves.
    let potential = w.mass * w.gravity * body.contact(x).height;
    let before = body.energy(from, x) - potential;
    let after = body.energy(to, &y) - potential;
    if before > 0.0 && after > 0.0 {
        let s = (before / after).sqrt();
        for k in [layout::VELOCITY, layout::VELOCITY + 1] {
            y[k] *= s;
        }
        for k in 0..3 {
            y[layout::OMEGA + k] *= s;
        }
    }
    y
}

/// Goes on sliding from `x` (seeded) at `t`, left from `from` (a held spin staying held) —
/// or halts where the sliding equations cannot take the state: N would have to jump below
/// zero, or Painlevé's paradox.
fn enter_sliding<D: ContactDynamics + ?Sized>(
    body: &D,
    w: &Watch,
    t: f64,
    x: State,
    from: ContactMode,
) -> ContactAction {
    let to = ContactMode {
        phase: Phase::Sliding,
        spin_held: from.spin_held,
    };
    let d = denominator(body, w, to.spin_held, &x);
    let after = reaction(body, w, to, &x).normal;
    if d <= 0.0 {
        return Action::Halt(ContactOutcome::Painleve {
            t,
            state: x,
            denominator: d,
            normal: after,
        });
    }
    if after < 0.0 {
        return Action::Halt(ContactOutcome::NormalForceJump {
            t,
            state: x,
            phase: from.phase,
            before: reaction(body, w, from, &x).normal,
            after,
        });
    }
    Action::Switch {
        mode: to,
        state: x,
        fresh: false,
    }
}

/// The slip of a stick–slip body has stopped at `x`: a plastic tangential impulse brings
/// the contact point to rest; the body rolls on if rolling needs no more than μN, and
/// otherwise slides again against the friction rolling needs. A held spin stays held if the
/// impulse leaves it below δ_ω (it is then set back to zero, never adding energy); an
/// impulse that turns it further frees it, for the `spin` witness to follow.
fn stick<D: ContactDynamics + ?Sized>(
    body: &D,
    w: &Watch,
    t: f64,
    x: State,
    held: bool,
) -> ContactAction {
    let mut rolled = impulse_to_rest(body, w, x);
    let mut mode = ContactMode::free(Phase::Rolling);
    if held && pivot::spin_margin(body, w, &rolled) <= 0.0 {
        rolled = pivot::spin_zeroed(body, w, Phase::Rolling, &rolled);
        mode = ContactMode::held(Phase::Rolling);
    }
    let r = reaction(body, w, mode, &rolled);
    if r.normal >= 0.0 && r.friction.norm() <= w.mu.unwrap_or(0.0) * r.normal {
        return Action::Switch {
            mode,
            state: rolled,
            fresh: false,
        };
    }
    let from = ContactMode {
        phase: Phase::Sliding,
        spin_held: mode.spin_held,
    };
    enter_sliding(body, w, t, seeded(body, w, mode.spin_held, rolled), from)
}

/// `x` after the impulse P = −K⁻¹u at the contact point that brings it to rest:
/// Δv = P/M, Δω = I⁻¹(r × RᵀP), with K = 1/M − [r]ₓ I⁻¹ [r]ₓ in space axes. The energy
/// changes by −½ uᵀK⁻¹u ≤ 0.
pub(crate) fn impulse_to_rest<D: ContactDynamics + ?Sized>(
    body: &D,
    w: &Watch,
    mut x: State,
) -> State {
    let q = attitude_of(&x);
    let c = body.contact(&x);
    let r_space = q.transform_vector(&c.body);
    let rot = q.to_rotation_matrix();
    let inv_space = rot.matrix() * w.inertia_inv * rot.matrix().transpose();
    let cross = r_space.cross_matrix();
    let k = Matrix3::identity() / w.mass - cross * inv_space * cross;
    let u = c.velocity;
    let Some(k_inv) = k.try_inverse() else {
        return x;
    };
    let p = -(k_inv * u);
    let dv = p / w.mass;
    let dw = w.inertia_inv * c.body.cross(&q.inverse_transform_vector(&p));
    x[layout::VELOCITY] += dv.x;
    x[layout::VELOCITY + 1] += dv.y;
    for k in 0..3 {
        x[layout::OMEGA + k] += dw[k];
    }
    x
}

/// The checks of a run's start that no hook can make: a state pulled onto the table, one
/// where Coulomb sliding's N has no value, a Coulomb sliding start without a slip.
///
/// # Errors
/// [`ContactError::NotPressed`], [`ContactError::Painleve`], [`ContactError::ZeroSlip`].
pub(crate) fn check_start<D: ContactDynamics + ?Sized>(
    sys: &ContactSystem<'_, D>,
    t: f64,
    x: &State,
) -> Result<(), ContactError> {
    let (body, w, phase) = (sys.body, &sys.watch, sys.phase);
    if phase == Phase::Sliding
        && let Some(mu) = w.mu.or(w.normal_viscous).or(w.pivoting.map(|_| 0.0))
    {
        let slip = slip(body, x).norm();
        let threshold = stick_speed(body, w, x);
        if w.mu.is_some() && slip <= threshold {
            return Err(ContactError::ZeroSlip { slip, threshold });
        }
        let d = denominator(body, w, false, x);
        if d <= 0.0 {
            return Err(ContactError::Painleve {
                t,
                mu,
                denominator: d,
                normal: body.reaction(phase, x).normal,
            });
        }
    }
    let normal = body.reaction(phase, x).normal;
    if normal < 0.0 {
        return Err(ContactError::NotPressed { phase, normal });
    }
    Ok(())
}
