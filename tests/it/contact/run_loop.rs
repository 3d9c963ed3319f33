//! Contact runs in the one run loop, and the ways they used to give a wrong answer quietly:
//! each test here failed on the drivers that each scene had of its own.

use approx::assert_relative_eq;
use nalgebra::{UnitQuaternion, Vector3};
use precess::contact::{
    ContactDynamics, ContactError, ContactModel, ContactOutcome, ContactQuantities, ContactRun,
    Phase, STATE_LEN, layout,
};
use precess::ode::{AdaptiveConfig, Run, Stepper, StopReason};

use super::reference::{NumBody, NumLaw, NumSurface, model, offset_sphere, thin_disk};

/// A heavy eccentric sphere: M = 0.1 kg, radius 0.02 m, its centre of mass 6 mm below the
/// sphere's centre, I = (1.7, 1.7, 1.6)·10⁻⁵ kg m² about it.
fn eccentric_ball() -> NumBody {
    NumBody {
        mass: 0.1,
        center: [0.0, 0.0, -0.006],
        inertia: [[1.7e-5, 0.0, 0.0], [0.0, 1.7e-5, 0.0], [0.0, 0.0, 1.6e-5]],
        surface: NumSurface::Sphere {
            c: [0.0; 3],
            rho: 0.02,
        },
        gravity: 9.81,
    }
}

fn tol(t: f64) -> AdaptiveConfig {
    let mut cfg = AdaptiveConfig::with_tol(t, t);
    cfg.max_steps = 2_000_000;
    cfg
}

/// The state `q, ω` at rest horizontally (vx = vy = 0): a sliding start.
fn at_rest(q: UnitQuaternion<f64>, omega: Vector3<f64>) -> [f64; STATE_LEN] {
    let mut y = [0.0; STATE_LEN];
    let at = layout::QUATERNION;
    y[at..at + 4].copy_from_slice(&[q.w, q.i, q.j, q.k]);
    y[layout::OMEGA..layout::OMEGA + 3].copy_from_slice(omega.as_slice());
    y
}

/// Stick–slip whose slip never stops is Coulomb sliding: the ball set spinning at 1000 rad/s
/// about the vertical, its axis 0.05 rad from it, slides all the time (its slip never comes
/// near zero in 0.3 s), so the two laws integrate the same equations with the same steps at
/// every tolerance: the runs agree to rounding (the two models' programs are lowered from
/// different arenas, so their roundings differ in the last bits). The old "sticks" event (the slip against its
/// direction at the step's start) fired whenever the slip's direction turned more than 90°
/// within a step, put the velocity on rolling and seeded a new slip, recording nothing: the
/// energy rose (8.01499 J to 8.02599 J at tolerance 1e-7, where Coulomb sliding falls to
/// 8.01276 J).
#[test]
fn stick_slip_whose_slip_never_stops_is_coulomb_sliding() {
    let mu = 0.02;
    let ball = eccentric_ball();
    let stick_slip = model(&ball, NumLaw::StickSlip(mu));
    let coulomb = model(&ball, NumLaw::Coulomb(mu));
    let q = UnitQuaternion::from_euler_angles(0.05, 0.0, 0.0);
    let y0 = at_rest(q, q.inverse() * Vector3::new(0.0, 0.0, 1000.0));
    let e0 = coulomb.energy(Phase::Sliding, &y0);
    for tolerance in [1e-5, 1e-6, 1e-7, 1e-10] {
        let run_of = |m: &ContactModel| {
            let mut run = ContactRun::new(m, Phase::Sliding, 0.0, y0, tol(tolerance)).unwrap();
            let mut energies = Vec::new();
            for k in 1..=300 {
                let out = run.advance_to(1e-3 * k as f64).unwrap();
                assert!(matches!(out, ContactOutcome::Reached { .. }), "{out:?}");
                energies.push(m.energy(Phase::Sliding, run.y()));
            }
            (*run.y(), energies, run.switches().len())
        };
        let (y_s, e_s, switches) = run_of(&stick_slip);
        let (y_c, e_c, _) = run_of(&coulomb);
        assert_eq!(switches, 0, "tol {tolerance}: the slip never stops");
        let scale = y_c.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for (a, b) in y_s.iter().zip(&y_c) {
            assert!(
                (a - b).abs() <= 1e-10 * scale,
                "tol {tolerance}: {y_s:?} against {y_c:?}"
            );
        }
        for (a, b) in e_s.iter().zip(&e_c) {
            assert_relative_eq!(*a, *b, max_relative = 1e-12);
        }
        // Coulomb friction only takes energy out: never more than the tolerance back.
        let mut last = e0;
        for e in e_s {
            assert!(
                e <= last * (1.0 + 10.0 * tolerance),
                "tol {tolerance}: {e} after {last}"
            );
            last = last.min(e);
        }
        assert!(last < e0, "the friction dissipates");
    }
}

/// A thin disk released at rest 0.3 rad from standing falls towards its face. Without
/// friction its centre falls straight down and the normal force stays positive, so it
/// reaches its face: the support map of its rim fails there (the contact point is no longer
/// one point), and the run stops with `Unsupported` at the last attitude it could place.
/// Rolling (and stick–slip with much friction) it is thrown off the table before it lies
/// down: N reaches zero. The old run checked flatness only at its start: the disk passed
/// through the table and bounced back.
#[test]
fn a_disk_falling_flat_never_passes_through_the_table() {
    let disk = thin_disk();
    // Standing: the disk's axis (description z) horizontal; tilted 0.3 rad towards flat.
    let q = UnitQuaternion::from_euler_angles(core::f64::consts::FRAC_PI_2 - 0.3, 0.0, 0.0);
    for law in [
        NumLaw::Frictionless,
        NumLaw::Rolling { cr: None, cs: None },
        NumLaw::StickSlip(0.8),
    ] {
        let m = model(&disk, law);
        let phase = m.law().first_phase();
        let y0 = m.rolling_state([0.0, 0.0], &q, &Vector3::zeros()).unwrap();
        let mut run = ContactRun::new(&m, phase, 0.0, y0, tol(1e-10)).unwrap();
        let e0 = m.energy(phase, &y0);
        let out = run.advance_to(2.0).unwrap();
        let (t, state) = match (law, out) {
            (
                NumLaw::Frictionless,
                ContactOutcome::Unsupported {
                    t, state, margin, ..
                },
            ) => {
                assert!(margin >= 0.0, "{margin}");
                (t, state)
            }
            (NumLaw::Frictionless, _) => panic!("{out:?}"),
            (
                _,
                ContactOutcome::LiftOff { t, state } | ContactOutcome::Unsupported { t, state, .. },
            ) => (t, state),
            _ => panic!("{law:?}: {out:?}"),
        };
        assert!(t > 0.1 && t < 1.0, "{law:?}: t = {t}");
        // The state it stopped at still stands on its rim, above the table, with N ≥ 0.
        assert!(m.check_state(run.phase(), &state).is_ok());
        assert!(m.contact(&state).height > 0.0);
        assert!(m.reaction(run.phase(), &state).normal >= -1e-9);
        // Its energy to the tolerance on the way down, where no law dissipates; stick–slip
        // may slip and lose some, never gain.
        let e = m.energy(run.phase(), &state);
        let slipped = !run.switches().is_empty();
        assert!(
            (e - e0) / e0 < 1e-7 && (slipped || (e - e0) / e0 > -1e-7),
            "{law:?}: energy {e0} → {e} at {t}, switches {:?}",
            run.switches()
                .iter()
                .map(|s| (s.t, s.from, s.to))
                .collect::<Vec<_>>()
        );
        // Asked again, the same outcome.
        assert_eq!(run.advance_to(2.0).unwrap(), out);
    }
}

/// A long rod sliding with much friction (μ = 2) at 45°: the normal force of Coulomb
/// sliding has no consistent value (Painlevé's paradox). The start is refused with the
/// paradox named; the old run returned a lift-off carrying N = −375.6 N.
#[test]
fn a_rod_in_painleve_s_configuration_is_named_not_lifted_off() {
    let rod = NumBody {
        mass: 0.1,
        center: [0.0; 3],
        inertia: rod_inertia(0.1, [0.5, 0.02, 0.02]),
        surface: NumSurface::Ellipsoid {
            c: [0.0; 3],
            axes: [0.5, 0.02, 0.02],
        },
        gravity: 9.81,
    };
    let m = model(&rod, NumLaw::Coulomb(2.0));
    // Its +x end down, sliding towards −x: D = 1 + k cos²θ − k μ sin θ cos θ with
    // k = M a²/I = 5 for a solid ellipsoid, −1.5 at θ = 45°, μ = 2.
    let q = UnitQuaternion::from_euler_angles(0.0, -core::f64::consts::FRAC_PI_4, 0.0);
    let mut y0 = at_rest(q, Vector3::zeros());
    y0[layout::VELOCITY] = -1.0;
    let err = ContactRun::new(&m, Phase::Sliding, 0.0, y0, tol(1e-10)).unwrap_err();
    let ContactError::Painleve {
        denominator, mu, ..
    } = err
    else {
        panic!("{err:?}");
    };
    assert_relative_eq!(denominator, 1.0 + 2.5 - 5.0, max_relative = 1e-3);
    assert_eq!(mu, 2.0);
    // Under stick–slip with μ = 3 it starts rolling; whatever ends the run, no state it
    // returns has N < 0, and a lift-off is where N reached zero.
    let m = model(&rod, NumLaw::StickSlip(3.0));
    let y0 = m
        .rolling_state([0.0, 0.0], &q, &Vector3::new(0.0, 2.0, 0.0))
        .unwrap();
    if let Ok(mut run) = ContactRun::new(&m, Phase::Rolling, 0.0, y0, tol(1e-10)) {
        let out = run.advance_to(1.0).unwrap();
        assert_no_pull(&m, &run, &out);
    }
}

/// The inertia of a solid ellipsoid of mass `m` and semi-axes `a` about its centre.
fn rod_inertia(m: f64, a: [f64; 3]) -> [[f64; 3]; 3] {
    let [x, y, z] = a.map(|v| v * v);
    [
        [m * (y + z) / 5.0, 0.0, 0.0],
        [0.0, m * (x + z) / 5.0, 0.0],
        [0.0, 0.0, m * (x + y) / 5.0],
    ]
}

/// No state a run returned (its transitions, its outcome) has N < 0; a lift-off has N = 0
/// to within 10⁻⁹ M g.
fn assert_no_pull(m: &ContactModel, run: &ContactRun<'_, ContactModel>, out: &ContactOutcome) {
    let scale = 1e-9 * m.values().mass * m.values().gravity;
    for s in run.switches() {
        assert!(m.reaction(s.from, &s.state).normal >= -scale, "{s:?}");
        assert!(m.reaction(s.to, &s.after).normal >= -scale, "{s:?}");
    }
    match *out {
        ContactOutcome::LiftOff { state, .. } => {
            let n = m.reaction(run.phase(), &state).normal;
            assert!(n.abs() <= scale, "lift-off with N = {n}");
        }
        ContactOutcome::NormalForceJump { before, after, .. } => {
            assert!(before >= 0.0 && after < 0.0, "{out:?}")
        }
        _ => {}
    }
    assert!(m.reaction(run.phase(), run.y()).normal >= -scale);
}

/// At exactly the friction threshold, with the friction rolling needs rising, the body
/// slips at once: rolling may not start a step outside its cone. The old start check used
/// a strict `>`, and an event that starts at exactly zero never counted: the body rolled
/// on with the friction 25 % outside the cone.
#[test]
fn at_exactly_the_friction_threshold_the_body_slips_at_once() {
    let ball = offset_sphere();
    let rolling = model(&ball, NumLaw::Rolling { cr: None, cs: None });
    // Rolling over with its centre of mass 0.3 rad ahead of the contact: the friction
    // rolling needs grows as it rolls on.
    let q = UnitQuaternion::from_euler_angles(0.3, 0.0, 0.0);
    let y0 = rolling
        .rolling_state([0.0; 2], &q, &Vector3::new(25.0, 0.0, 0.0))
        .unwrap();
    let ratio = |y: &[f64; STATE_LEN]| {
        let r = rolling.reaction(Phase::Rolling, y);
        r.friction.norm() / r.normal
    };
    let mu = ratio(&y0);
    let mut probe = ContactRun::new(&rolling, Phase::Rolling, 0.0, y0, tol(1e-12)).unwrap();
    probe.advance_to(1e-4).unwrap();
    assert!(ratio(probe.y()) > mu, "the needed friction rises");
    let m = model(&ball, NumLaw::StickSlip(mu));
    let mut run = ContactRun::new(&m, Phase::Rolling, 0.0, y0, tol(1e-12)).unwrap();
    // The cone's margin is 0 to rounding at the start: below it, the body slides from the
    // start; at or above it, the first step finds it falling at once (here to exactly 0 at
    // 3.5e-27 s, where the loop acts).
    run.advance_to(1e-9).unwrap();
    let switch = run.switches()[0];
    assert_eq!((switch.from, switch.to), (Phase::Rolling, Phase::Sliding));
    assert!(switch.t < 1e-20, "the slip starts at t = {}", switch.t);
    assert_eq!(switch.witness, Some("friction cone"));
    // Through 10 ms, whenever it rolls, its friction stays in the cone.
    let out = Run::new(&mut run, 1e-2)
        .sample_every(1e-4)
        .quantity("cone", |_t, s| {
            let r = m.reaction(Phase::Rolling, &s.x);
            if s.mode.phase == Phase::Rolling {
                r.friction.norm() / (mu * r.normal)
            } else {
                0.0
            }
        })
        .integrate()
        .unwrap();
    for c in out.trajectory.column("cone").unwrap() {
        assert!(c <= 1.0 + 1e-9, "friction at {c} of the cone while rolling");
    }
}

/// Pure Coulomb sliding whose slip reaches zero stops there with an error naming the slip
/// and pointing to stick–slip. A uniform ball thrown without spin slides until
/// t = 2 v₀/(7 μ g); the old run took 10⁷ steps to end in `MaxStepsExceeded`.
#[test]
fn coulomb_sliding_whose_slip_stops_says_so_in_a_few_steps() {
    let (mass, rho, mu, g, v0) = (1.0, 0.1, 0.2, 9.81, 1.5);
    let i = 0.4 * mass * rho * rho;
    let ball = NumBody {
        mass,
        center: [0.0; 3],
        inertia: [[i, 0.0, 0.0], [0.0, i, 0.0], [0.0, 0.0, i]],
        surface: NumSurface::Sphere { c: [0.0; 3], rho },
        gravity: g,
    };
    let m = model(&ball, NumLaw::Coulomb(mu));
    let mut y0 = at_rest(UnitQuaternion::identity(), Vector3::zeros());
    y0[layout::VELOCITY] = v0;
    let mut run = ContactRun::new(&m, Phase::Sliding, 0.0, y0, tol(1e-12)).unwrap();
    let err = run.advance_to(1.0).unwrap_err();
    let ContactError::SlipStopped { t, slip, threshold } = err else {
        panic!("{err:?}");
    };
    let t_stop = 2.0 * v0 / (7.0 * mu * g);
    assert_relative_eq!(t, t_stop, max_relative = 1e-8);
    assert!(slip <= threshold * 1.000_001);
    assert!(err_text(&m).contains("stick"));
    assert!(run.stats().steps < 200, "{:?}", run.stats());
}

fn err_text(m: &ContactModel) -> String {
    let mut y0 = at_rest(UnitQuaternion::identity(), Vector3::zeros());
    y0[layout::VELOCITY] = 1.0;
    let mut run = ContactRun::new(m, Phase::Sliding, 0.0, y0, tol(1e-12)).unwrap();
    run.advance_to(1.0).unwrap_err().to_string()
}

/// Errors name their cause: a flat disk's rolling state is `FlatDisk`, a stick–slip body
/// started sliding without a slip is `ZeroSlip`.
#[test]
fn errors_name_their_cause() {
    let m = model(&thin_disk(), NumLaw::Rolling { cr: None, cs: None });
    let err = m
        .rolling_state(
            [0.0; 2],
            &UnitQuaternion::identity(),
            &Vector3::new(0.0, 0.0, 3.0),
        )
        .unwrap_err();
    assert!(matches!(err, ContactError::FlatDisk { .. }), "{err:?}");
    let m = model(&offset_sphere(), NumLaw::StickSlip(0.3));
    let y0 = at_rest(UnitQuaternion::identity(), Vector3::zeros());
    let err = ContactRun::new(&m, Phase::Sliding, 0.0, y0, tol(1e-10)).unwrap_err();
    assert!(matches!(err, ContactError::ZeroSlip { .. }), "{err:?}");
}

/// The normal force of Coulomb sliding is A/D with A free of μ (and D the denominator the
/// run watches): so N·D is the same for every μ at one state. Checked against the derived
/// equations at μ = 0.1, 0.7, 1.3.
#[test]
fn the_watched_denominator_is_the_normal_force_s() {
    let ball = eccentric_ball();
    let q = UnitQuaternion::from_euler_angles(0.4, -0.2, 0.3);
    let mut y = at_rest(q, Vector3::new(3.0, -7.0, 20.0));
    y[layout::VELOCITY] = 0.3;
    y[layout::VELOCITY + 1] = -0.1;
    let products: Vec<f64> = [0.1, 0.7, 1.3]
        .iter()
        .map(|&mu| {
            let m = model(&ball, NumLaw::Coulomb(mu));
            let n = m.reaction(Phase::Sliding, &y).normal;
            n * precess::contact::normal_denominator(&m, &y).unwrap()
        })
        .collect();
    assert_relative_eq!(products[0], products[1], max_relative = 1e-12);
    assert_relative_eq!(products[0], products[2], max_relative = 1e-12);
}

/// A contact run is a `Stepper`: a trajectory with its quantities (each sample under its
/// own phase), sampled on a grid, with a user event, from `Run`.
#[test]
fn a_contact_run_gives_a_trajectory_with_events() {
    let ball = offset_sphere();
    let m = model(&ball, NumLaw::StickSlip(0.15));
    let y0 = m
        .rolling_state(
            [0.0; 2],
            &UnitQuaternion::identity(),
            &Vector3::new(25.0, 0.0, 0.0),
        )
        .unwrap();
    let mut run = ContactRun::new(&m, Phase::Rolling, 0.0, y0, tol(1e-12)).unwrap();
    let out = Run::new(&mut run, 0.5)
        .sample_every(0.01)
        .quantities(ContactQuantities::new(&m, Phase::Rolling))
        .event(precess::ode::Event::new("x = 0.1"), |_t, s| s[0] - 0.1)
        .integrate()
        .unwrap();
    assert_eq!(out.stop, StopReason::End);
    assert_eq!(out.trajectory.len(), 51);
    // N as each sample's phase has it: positive all along.
    assert!(
        out.trajectory
            .column("normal")
            .unwrap()
            .iter()
            .all(|&n| n > 0.0)
    );
    // The state's CSV carries the phase.
    assert!(
        out.trajectory
            .to_csv()
            .lines()
            .next()
            .unwrap()
            .contains("phase")
    );
    // The event on x, located on the loop's own solution.
    for hit in &out.events {
        assert_relative_eq!(hit.state.x[0], 0.1, epsilon = 1e-10);
    }
    assert!(run.switches().len() >= 2);
    assert_eq!(Stepper::t(&run), 0.5);
}
