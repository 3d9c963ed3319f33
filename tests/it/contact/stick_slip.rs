//! Stick–slip: an eccentric sphere rolling over and over needs a friction that swings with
//! its centre of mass; with a small μ it slips where that friction leaves the cone μ N, and
//! rolls again where the slip stops. The switches sit where the law says, and the energy
//! never rises.

use nalgebra::{UnitQuaternion, Vector3};
use precess::contact::{ContactDynamics, ContactOutcome, ContactRun, Phase};
use precess::ode::AdaptiveConfig;

use super::reference::{NumLaw, model, offset_sphere};

#[test]
fn an_eccentric_sphere_slips_and_sticks_where_the_cone_says() {
    let mu = 0.15;
    let m = model(&offset_sphere(), NumLaw::StickSlip(mu));
    let y0 = m
        .rolling_state(
            [0.0, 0.0],
            &UnitQuaternion::identity(),
            &Vector3::new(25.0, 0.0, 0.0),
        )
        .unwrap();
    // At the start, rolling holds (the centre of mass is straight below the sphere's centre).
    let r0 = m.reaction(Phase::Rolling, &y0);
    assert!(r0.friction.norm() < mu * r0.normal);
    let cfg = AdaptiveConfig::with_tol(1e-12, 1e-14);
    let mut run = ContactRun::new(&m, Phase::Rolling, 0.0, y0, cfg).unwrap();
    let mut energy = m.energy(Phase::Rolling, &y0);
    let mut rise: f64 = 0.0;
    for k in 1..=200 {
        let out = run.advance_to(0.005 * k as f64).unwrap();
        assert!(matches!(out, ContactOutcome::Reached { .. }), "{out:?}");
        let e = m.energy(run.phase(), run.y());
        rise = rise.max(e - energy);
        energy = e;
    }
    let switches = run.switches();
    println!(
        "eccentric sphere, μ = {mu}: {} steps, {} rhs, {} event evaluations",
        run.stats().steps,
        run.stats().rhs_evals,
        run.event_evaluations()
    );
    println!(
        "eccentric sphere, μ = {mu}: {} switches, first at {:?}; largest energy rise {rise:e} J of {energy}",
        switches.len(),
        switches
            .iter()
            .take(4)
            .map(|s| (s.t, s.to))
            .collect::<Vec<_>>()
    );
    assert!(switches.len() >= 2, "{switches:?}");
    for s in switches {
        match s.to {
            Phase::Sliding => {
                // Rolling left the cone there: |F_t| = μ N.
                let r = m.reaction(Phase::Rolling, &s.state);
                let gap = (r.friction.norm() - mu * r.normal).abs() / r.normal;
                assert!(gap < 1e-8, "cone gap {gap:e} at {}", s.t);
            }
            Phase::Rolling => {
                // The slip had stopped: what is left of it is tiny.
                let u = m.contact(&s.state).velocity.norm();
                assert!(u < 1e-6, "slip {u:e} at {}", s.t);
            }
        }
    }
    // Coulomb friction only takes energy out; rolling keeps it.
    assert!(rise < 1e-12 * energy, "{rise:e}");
}

/// With little friction the eccentric sphere's slip stops and reverses where rolling could
/// not hold: the run carries on sliding through those instants, its energy falling.
#[test]
fn a_slip_that_stops_where_rolling_cannot_hold_slides_on() {
    let mu = 0.01;
    let m = model(&offset_sphere(), NumLaw::StickSlip(mu));
    let q = UnitQuaternion::from_euler_angles(0.8, 0.0, 0.0);
    let y0 = m
        .rolling_state([0.0, 0.0], &q, &Vector3::new(25.0, 0.0, 0.0))
        .unwrap();
    let cfg = AdaptiveConfig::with_tol(1e-12, 1e-14);
    let mut run = ContactRun::new(&m, Phase::Rolling, 0.0, y0, cfg).unwrap();
    let e0 = m.energy(Phase::Sliding, &y0);
    let out = run.advance_to(1.0).unwrap();
    let e1 = m.energy(run.phase(), run.y());
    println!(
        "eccentric sphere, μ = {mu}: {out:?} with {} switches, phase {:?}, energy {e0} → {e1}; \
         {} steps, {} rhs, {} event evaluations",
        run.switches().len(),
        run.phase(),
        run.stats().steps,
        run.stats().rhs_evals,
        run.event_evaluations()
    );
    assert_eq!(out, ContactOutcome::Reached { t: 1.0 });
    assert!(e1 < e0);
}

/// The first stick of an eccentric sphere that slides from the start, at a tolerance.
fn first_stick(tol: f64) -> (f64, u64) {
    let m = model(&offset_sphere(), NumLaw::StickSlip(0.12));
    let q = UnitQuaternion::from_euler_angles(0.525, 0.0, 0.0);
    let y0 = m
        .rolling_state([0.0, 0.0], &q, &Vector3::new(-1.0, -3.34, 6.36))
        .unwrap();
    // Rolling needs more than μN there: the body slides from the start.
    let cfg = AdaptiveConfig::with_tol(tol, tol);
    let mut run = ContactRun::new(&m, Phase::Rolling, 0.0, y0, cfg).unwrap();
    let out = run.advance_to(0.1).unwrap();
    assert!(matches!(out, ContactOutcome::Reached { .. }), "{out:?}");
    let stick = run
        .switches()
        .into_iter()
        .find(|s| s.to == Phase::Rolling)
        .map(|s| s.t)
        .expect("the slip stops");
    (stick, run.stats().steps)
}

/// A Coulomb slip the stepper cannot resolve is taken as stopped: at a loose tolerance the
/// slip once chattered about zero at the tolerance's size, the friction reversing from step
/// to step, and the body slid on for 0.019 s more than it does (10⁵ steps of 2·10⁻⁷ s)
/// before the slip fell below 10⁻⁹ of the velocity scale by chance.
#[test]
fn a_loose_tolerance_sticks_where_a_tight_one_does() {
    let (tight, _) = first_stick(1e-12);
    let (loose, steps) = first_stick(1.1e-7);
    println!("first stick: {tight} s at tol 1e-12, {loose} s in {steps} steps at tol 1.1e-7");
    assert!((loose - tight).abs() < 1e-5, "{loose} against {tight}");
    assert!(steps < 2_000, "{steps} steps");
}
