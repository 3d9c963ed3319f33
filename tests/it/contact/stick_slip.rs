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
