//! A slider-crank declared with `closes = ..` (`precess::models::SliderCrank`: crank
//! r = 0.5 about the origin, connecting rod l = 1.5 pinned to a slider on the x axis): the
//! slider against x = r cos θ + √(l² − r² sin² θ) at many crank angles and along a run, the
//! loop residual and the energy over the run, the pin force against Newton–Euler of the
//! links; and a four-bar of fields whose sides cannot close, refused at run time by name.

use precess::mechanism::MechanismError;
use precess::mechanism::loops::LoopDynamics;
use precess::models::SliderCrank;
use precess::ode::{AdaptiveConfig, Stepper};
use precess::prelude::*;
use precess_testkit::linkages::slider_crank_pin_force;

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
const G: f64 = 9.81;
/// Crank, rod and slider \[kg\].
const MASSES: [f64; 3] = [0.4, 0.9, 2.0];

/// The slider's closed form for the crank at θ.
fn slider(theta: f64) -> f64 {
    R * theta.cos() + (L * L - R * R * theta.sin().powi(2)).sqrt()
}

/// dx/dθ of [`slider`].
fn slider_slope(theta: f64) -> f64 {
    let s = theta.sin();
    -R * s - R * R * s * theta.cos() / (L * L - R * R * s * s).sqrt()
}

/// The rod's angle relative to the crank, from sin(θ + β) = −(r/l) sin θ, cos(θ + β) > 0.
fn rod(theta: f64) -> f64 {
    (-(R / L) * theta.sin()).asin() - theta
}

#[test]
fn the_slider_sits_on_the_closed_form_at_every_crank_angle() {
    assert_eq!(SliderCrank::CLOSURE_ROWS, ["rod.x", "rod.y"]);
    let (mut at_closed_form, mut after_newton, mut slider_off, mut rate_off) =
        (0.0_f64, 0.0_f64, 0.0_f64, 0.0_f64);
    for k in 0..720 {
        let theta = -std::f64::consts::PI + std::f64::consts::TAU * (f64::from(k) + 0.5) / 720.0;
        // The closed form's positions satisfy the derived rows.
        let exact = [theta, rod(theta), slider(theta)];
        at_closed_form = at_closed_form.max(SliderCrank.residual(&exact));
        // A configuration off the loop, pulled back by Newton over the dependent
        // coordinates the pivoting chose (the crank among them, at some angles): the slider
        // lands on x(θ) of wherever the crank ended, its rate on (dx/dθ) θ̇.
        let mut q = [theta, rod(theta) + 2e-3, slider(theta) - 3e-3];
        let mut qd = [3.0, -1.0, 0.5];
        SliderCrank
            .close_loop(&mut q, &mut qd)
            .expect("closes from nearby");
        after_newton = after_newton.max(SliderCrank.residual(&q));
        slider_off = slider_off.max((q[SliderCrank::X] - slider(q[0])).abs());
        rate_off = rate_off.max(
            (qd[SliderCrank::X] - slider_slope(q[0]) * qd[SliderCrank::THETA]).abs()
                / qd.iter().fold(1.0_f64, |m, v| m.max(v.abs())),
        );
    }
    eprintln!(
        "max |φ| at the closed form {at_closed_form:e}, after Newton {after_newton:e}; slider off x(θ) by {slider_off:e} m, ẋ off by {rate_off:e}"
    );
    assert!(at_closed_form < 1e-15, "{at_closed_form:e}");
    assert!(after_newton <= 1e-14, "{after_newton:e}");
    assert!(slider_off < 1e-12, "{slider_off:e}");
    assert!(rate_off < 1e-12, "{rate_off:e}");
}

#[test]
fn the_pin_force_balances_the_slider_and_the_crank_with_its_rod() {
    // Newton–Euler on the two sides of the cut, λ the force on the rod at B = (x, 0): the
    // slider (its guide takes y) m_s ẍ = −λ_x; the crank and the rod turn about the origin
    // under their weights and λ at B (the pivot's force has no moment there),
    // d/dt L_O = Σ weights' moments + x λ_y.
    for (theta, omega) in [(0.4, 5.0), (2.0, -3.0), (3.5, 0.0), (5.5, 8.0)] {
        let q = [theta, rod(theta), slider(theta)];
        let qd = SliderCrank
            .rates_from(&q, [SliderCrank::THETA], [omega])
            .expect("free crank");
        let qdd = SliderCrank.accelerations(0.0, &q, &qd).expect("regular");
        let l = SliderCrank.multipliers(0.0, &q, &qd).expect("regular");
        let (fx, fy) = slider_crank_pin_force([R, L], MASSES, G, (&q, &qd, &qdd));
        // The slider's balance m_s ẍ + λ_x, and the moments' x (λ_y − λ_y of Newton–Euler).
        let slider_balance = l[0] - fx;
        let moments = q[2] * (fy - l[1]);
        let scale = (MASSES[2] * G).max(l[0].abs() + l[1].abs());
        eprintln!("θ = {theta}: λ = {l:?}, slider {slider_balance:e}, crank and rod {moments:e}");
        assert!(
            slider_balance.abs() < 1e-12 * scale,
            "slider: {slider_balance:e} (λ = {l:?})"
        );
        assert!(
            moments.abs() < 1e-12 * scale * (R + L),
            "crank and rod: {fy} against {}",
            l[1]
        );
    }
}

#[test]
fn the_slider_follows_the_closed_form_along_a_run() {
    let theta: f64 = 0.4;
    let q0 = [theta, rod(theta), slider(theta)];
    assert!(
        SliderCrank.residual(&q0) < 1e-15,
        "{}",
        SliderCrank.residual(&q0)
    );
    let qd0 = SliderCrank
        .rates_from(&q0, [SliderCrank::THETA], [5.0])
        .expect("free crank");
    // ẋ = dx/dθ θ̇.
    let dx = slider_slope(theta);
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
    let (mut worst, mut energy, mut phi) = (0.0_f64, 0.0_f64, 0.0_f64);
    for k in 1..=500 {
        run.advance_to(f64::from(k) * 0.02).expect("runs");
        let y = run.state().x;
        worst = worst.max((y[2] - slider(y[0])).abs());
        phi = phi.max(SliderCrank.residual(&[y[0], y[1], y[2]]));
        energy =
            energy.max((SliderCrank.energy(&[y[0], y[1], y[2]], &[y[3], y[4], y[5]]) - e0).abs());
    }
    let turns = (run.state().x[0] - theta) / std::f64::consts::TAU;
    eprintln!(
        "{turns:.1} crank turns: slider off the closed form by {worst:e} m, max |φ| {phi:e} m, energy {energy:e} J"
    );
    assert!(turns.abs() > 3.0);
    assert!(worst < 1e-12, "{worst:e}");
    assert!(phi <= 1e-13, "{phi:e}");
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
