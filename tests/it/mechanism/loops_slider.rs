//! A slider-crank declared with `closes = ..`: the slider against
//! x = r cos θ + √(l² − r² sin² θ) along a run, its energy; and a four-bar of fields whose
//! sides cannot close, refused at run time by name.

use precess::mechanism::MechanismError;
use precess::mechanism::loops::LoopDynamics;
use precess::ode::{AdaptiveConfig, Stepper};
use precess::prelude::*;

/// Crank r = 0.5 about the origin, connecting rod l = 1.5 pinned to a slider on the x axis.
#[derive(Mechanism)]
#[mechanism(gravity = [0.0, -9.81, 0.0])]
#[body(crank, joint = revolute(axis = z), q = theta,
       parts(rod(mass = 0.4, length = 0.5, axis = x, at = [0.25, 0.0, 0.0])))]
#[body(rod, parent = crank, joint = revolute(axis = z, at = [0.5, 0.0, 0.0]), q = beta,
       parts(rod(mass = 0.9, length = 1.5, axis = x, at = [0.75, 0.0, 0.0])),
       closes = slider(at = [1.5, 0.0, 0.0]))]
#[body(slider, joint = prismatic(axis = x), q = x, parts(particle(mass = 2.0)))]
struct SliderCrank;

/// A four-bar whose link lengths are fields.
#[derive(Mechanism)]
#[mechanism(gravity = [0.0, -9.81, 0.0])]
#[body(crank, joint = revolute(axis = z), q = theta1,
       parts(rod(mass = 0.5, length = a, axis = x, at = [0.5 * a, 0.0, 0.0])))]
#[body(coupler, parent = crank, joint = revolute(axis = z, at = [a, 0.0, 0.0]), q = theta2,
       parts(rod(mass = 1.5, length = b, axis = x, at = [0.5 * b, 0.0, 0.0])),
       closes = rocker(at = [b, 0.0, 0.0], to = [c, 0.0, 0.0]))]
#[body(rocker, joint = revolute(axis = z, at = [d, 0.0, 0.0]), q = theta3,
       parts(rod(mass = 1.2, length = c, axis = x, at = [0.5 * c, 0.0, 0.0])))]
struct Linkage {
    a: f64,
    b: f64,
    c: f64,
    d: f64,
}

const R: f64 = 0.5;
const L: f64 = 1.5;

/// The slider's closed form for the crank at θ.
fn slider(theta: f64) -> f64 {
    R * theta.cos() + (L * L - R * R * theta.sin().powi(2)).sqrt()
}

#[test]
fn the_slider_follows_the_closed_form_along_a_run() {
    let theta: f64 = 0.4;
    // The rod's angle relative to the crank, from sin(θ + β) = −(r/l) sin θ.
    let beta = (-(R / L) * theta.sin()).asin() - theta;
    let q0 = [theta, beta, slider(theta)];
    assert!(
        SliderCrank.residual(&q0) < 1e-15,
        "{}",
        SliderCrank.residual(&q0)
    );
    let qd0 = SliderCrank
        .rates_from(&q0, [SliderCrank::THETA], [5.0])
        .expect("free crank");
    // ẋ = dx/dθ θ̇.
    let dx = -R * theta.sin()
        - R * R * theta.sin() * theta.cos() / (L * L - R * R * theta.sin().powi(2)).sqrt();
    assert!(
        (qd0[SliderCrank::X] - 5.0 * dx).abs() < 1e-13,
        "{} against {}",
        qd0[2],
        5.0 * dx
    );
    let y0 = [q0[0], q0[1], q0[2], qd0[0], qd0[1], qd0[2]];
    let e0 = SliderCrank.energy(&q0, &qd0);
    let mut run = SliderCrank
        .closed_run(0.0, y0, AdaptiveConfig::with_tol(1e-11, 1e-11))
        .expect("starts");
    let (mut worst, mut energy) = (0.0_f64, 0.0_f64);
    for k in 1..=500 {
        run.advance_to(f64::from(k) * 0.02).expect("runs");
        let y = run.state().x;
        worst = worst.max((y[2] - slider(y[0])).abs());
        energy =
            energy.max((SliderCrank.energy(&[y[0], y[1], y[2]], &[y[3], y[4], y[5]]) - e0).abs());
    }
    let turns = (run.state().x[0] - theta) / std::f64::consts::TAU;
    eprintln!(
        "{turns:.1} crank turns: slider off the closed form by {worst:e} m, energy {energy:e} J"
    );
    assert!(turns.abs() > 3.0);
    assert!(worst < 1e-12, "{worst:e}");
    assert!(energy < 1e-8 * e0.abs(), "{energy:e}");
}

#[test]
fn field_lengths_that_cannot_close_are_refused_by_name() {
    let good = Linkage {
        a: 1.0,
        b: 3.0,
        c: 2.5,
        d: 3.0,
    };
    assert_eq!(good.check_parameters(), Ok(()));
    let long = Linkage { c: 8.0, ..good };
    let e = long.check_parameters();
    assert!(
        matches!(&e, Err(MechanismError::LoopCannotClose { closure, body, longest, others })
            if closure == "coupler" && body == "rocker" && *longest == 8.0 && *others == 7.0),
        "{e:?}"
    );
    let q = [0.3, 0.0, 1.0];
    assert!(matches!(
        long.accelerations(0.0, &q, &[0.0; 3]),
        Err(MechanismError::LoopCannotClose { .. })
    ));
    assert!(
        long.closed_run(0.0, [0.0; 6], AdaptiveConfig::default())
            .is_err()
    );
}
