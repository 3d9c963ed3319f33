//! Which friction law inverts a tippe top. The eccentric sphere of the contact tests (R = 2 cm,
//! the centre of mass a = 6 mm below the sphere's centre, M = 20 g, I₁ = 3.2e-6 and
//! I₃ = 2.9e-6 kg m²), spun at 150 rad/s with its stem 0.1 rad off the vertical and its centre
//! of mass at rest, so that its contact point slips, runs 20 s under two laws:
//!
//! - Coulomb stick–slip (μ = 0.3): friction −μN u/|u| takes the slip away in a few
//!   milliseconds; the contact then sticks, rolling holds within the cone, and the top rolls
//!   on near upright with its energy constant — rolling conserves it, and the inversion
//!   needs friction to do work, so it never turns over;
//! - F = −μ N u (μ = 0.3 s/m, Rauch-Wojciechowski; Cohen 1977): the friction fades with the
//!   slip but never sticks, keeps working on the slip the gyroscopic motion keeps making, and
//!   the top turns over, ending spinning on its stem with its centre of mass at R + a.
//!
//! docs/contact.md quotes the numbers this test prints.

use nalgebra::{UnitQuaternion, Vector3};
use precess::contact::{ContactDynamics, ContactModel, ContactOutcome, ContactRun, Phase};
use precess::ode::AdaptiveConfig;

use super::reference::{NumLaw, model, offset_sphere, state};

/// What a run of the top shows: when its axis passed the horizontal, where it ended.
struct Flip {
    horizontal: Option<f64>,
    gamma_end: f64,
    height_end: f64,
    energy: (f64, f64),
    phase: Phase,
    switches: usize,
    first_switch: Option<f64>,
}

fn spin_top(m: &ContactModel, t_end: f64) -> Flip {
    let q = UnitQuaternion::from_euler_angles(0.1, 0.0, 0.0);
    let y0 = state([0.0, 0.0], [0.0, 0.0], &q, &Vector3::new(0.0, 0.0, 150.0));
    let cfg = AdaptiveConfig::with_tol(1e-11, 1e-13);
    let mut run = ContactRun::new(m, Phase::Sliding, 0.0, y0, cfg).unwrap();
    let mut horizontal = None;
    for k in 1..=(t_end * 10.0) as usize {
        let t = 0.1 * k as f64;
        assert_eq!(run.advance_to(t).unwrap(), ContactOutcome::Reached { t });
        if horizontal.is_none() && m.contact(run.y()).gamma.z < 0.0 {
            horizontal = Some(t);
        }
    }
    let y = *run.y();
    let c = m.contact(&y);
    Flip {
        horizontal,
        gamma_end: c.gamma.z,
        height_end: c.height,
        energy: (m.energy(Phase::Sliding, &y0), m.energy(run.phase(), &y)),
        phase: run.phase(),
        switches: run.switches().len(),
        first_switch: run.switches().first().map(|s| s.t),
    }
}

#[test]
fn coulomb_stick_slip_locks_the_tippe_top_into_rolling_and_normal_viscous_friction_inverts_it() {
    let body = offset_sphere();
    let (radius, a) = (0.02, 0.006);
    let coulomb = spin_top(&model(&body, NumLaw::StickSlip(0.3)), 20.0);
    let viscous = spin_top(&model(&body, NumLaw::NormalViscous(0.3)), 20.0);
    for (name, f) in [
        ("Coulomb stick–slip μ = 0.3", &coulomb),
        ("F = −μ N u, μ = 0.3 s/m", &viscous),
    ] {
        println!(
            "tippe top, {name}: horizontal at {:?} s; at 20 s γ₃ = {}, height {} m ({:?}, {} switches, the first at {:?} s), E {} → {} J",
            f.horizontal,
            f.gamma_end,
            f.height_end,
            f.phase,
            f.switches,
            f.first_switch,
            f.energy.0,
            f.energy.1
        );
    }
    // Stick–slip: one stick, then rolling to the end, upright, at the rolling energy.
    assert_eq!(coulomb.phase, Phase::Rolling);
    assert!(
        coulomb.first_switch.is_some_and(|t| t < 0.1),
        "{:?}",
        coulomb.first_switch
    );
    assert!(coulomb.horizontal.is_none());
    assert!(coulomb.gamma_end > 0.99, "{}", coulomb.gamma_end);
    assert!(
        (coulomb.height_end - (radius - a)).abs() < 1e-4,
        "{}",
        coulomb.height_end
    );
    // F = −μ N u: turned over, the centre of mass at R + a.
    let t_flip = viscous.horizontal.expect("the top turned over");
    assert!(t_flip > 0.5 && t_flip < 15.0, "{t_flip}");
    assert!(viscous.gamma_end < -0.999, "{}", viscous.gamma_end);
    assert!(
        (viscous.height_end - (radius + a)).abs() < 1e-5,
        "{}",
        viscous.height_end
    );
}
