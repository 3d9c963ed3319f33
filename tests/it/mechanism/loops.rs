//! A four-bar declared with `closes = ..` on `#[derive(Mechanism)]` (the crank-rocker
//! `precess::models::FourBar`: crank a = 1, coupler b = 3, rocker c = 2.5, ground d = 3,
//! θ₂ the coupler's angle relative to the crank): its rocker against
//! Freudenstein's equation solved in closed form (the testkit's `linkages`) at many crank
//! angles (the loop residual and the energy over 10⁴ crank turns are in the optimised crate
//! `long-runs`), the pin force (the multipliers) against Newton–Euler of the links, and a
//! triple rocker whose crank passes its dead point (the dependent coordinates change there
//! instead of the run stopping or stepping through it).

use std::f64::consts::TAU;

use precess::mechanism::loops::{LoopDynamics, LoopHalt};
use precess::models::FourBar;
use precess::ode::{AdaptiveConfig, Stepper};
use precess::prelude::*;
use precess_testkit::linkages::freudenstein;

const G: f64 = 9.81;

/// The triple rocker a = 2, b = 1.5, c = 2, d = 3 (not Grashof: s + l = 4.5 > p + q = 4),
/// whose crank swings at most to cos θ₁ = (a² + d² − (b + c)²)/(2ad) = 1/16.
#[derive(Mechanism)]
#[mechanism(gravity = [0.0, -9.81, 0.0])]
#[body(crank, joint = revolute(axis = z), q = theta1,
       parts(rod(mass = 0.5, length = 2.0, axis = x, at = [1.0, 0.0, 0.0])))]
#[body(coupler, parent = crank, joint = revolute(axis = z, at = [2.0, 0.0, 0.0]), q = theta2,
       parts(rod(mass = 1.5, length = 1.5, axis = x, at = [0.75, 0.0, 0.0])),
       closes = rocker(at = [1.5, 0.0, 0.0], to = [2.0, 0.0, 0.0]))]
#[body(rocker, joint = revolute(axis = z, at = [3.0, 0.0, 0.0]), q = theta3,
       parts(rod(mass = 1.2, length = 2.0, axis = x, at = [1.0, 0.0, 0.0])))]
struct TripleRocker;

/// The state [q, q̇] on the loop at crank angle θ₁ and crank rate ω (Freudenstein's
/// positions, the other rates from the closure).
fn start<T: LoopDynamics<3, 2, 1>>(
    model: &T,
    links: [f64; 4],
    theta1: f64,
    branch: f64,
    omega: f64,
) -> [f64; 6] {
    let (coupler, rocker) = freudenstein(links, theta1, branch);
    let q = [theta1, coupler - theta1, rocker];
    let qd = model
        .rates_from(&q, [0], [omega])
        .expect("the crank is free here");
    [q[0], q[1], q[2], qd[0], qd[1], qd[2]]
}

fn halves(y: &[f64; 6]) -> ([f64; 3], [f64; 3]) {
    ([y[0], y[1], y[2]], [y[3], y[4], y[5]])
}

#[test]
fn the_derived_closure_holds_at_freudenstein_s_positions() {
    let links = [1.0, 3.0, 2.5, 3.0];
    assert_eq!(FourBar::CLOSURE_ROWS, ["coupler.x", "coupler.y"]);
    for k in 0..64 {
        let theta1 = TAU * f64::from(k) / 64.0;
        for branch in [1.0, -1.0] {
            let (coupler, rocker) = freudenstein(links, theta1, branch);
            let q = [theta1, coupler - theta1, rocker];
            assert!(
                FourBar.residual(&q) < 1e-14,
                "θ₁ = {theta1}: {}",
                FourBar.residual(&q)
            );
        }
    }
}

#[test]
fn the_pin_force_balances_each_side_of_the_loop() {
    // Newton–Euler on the two sides of the cut: the rocker turns about D = (d, 0) under its
    // weight and −λ at B; the crank and coupler turn about A = 0 under their weights and λ
    // at B (the pivot force at A has no moment there). λ is the force on the coupler.
    let [a, b, c, d] = [1.0, 3.0, 2.5, 3.0];
    let [m1, m2, m3] = [0.5, 1.5, 1.2];
    for (k, omega) in [(0, 6.0), (1, -2.0), (2, 0.0), (3, 9.0)] {
        let theta1 = 0.3 + 1.7 * f64::from(k);
        let y = start(&FourBar, [a, b, c, d], theta1, 1.0, omega);
        let (q, qd) = halves(&y);
        let qdd = FourBar.accelerations(0.0, &q, &qd).expect("regular");
        let l = FourBar.multipliers(0.0, &q, &qd).expect("regular");
        let (t3, w3, a3) = (q[2], qd[2], qdd[2]);
        let bx = d + c * t3.cos();
        let by = c * t3.sin();
        // Rocker about D: (m₃ c²/3) θ̈₃ = −m₃ g (c/2) cos θ₃ − ((B − D) × λ)_z.
        let rocker = m3 * c * c / 3.0 * a3
            + m3 * G * c / 2.0 * t3.cos()
            + (c * t3.cos() * l[1] - c * t3.sin() * l[0]);
        // Crank and coupler about A: d/dt L_A = Σ weights' moments + (B × λ)_z.
        let (t1, w1, a1) = (q[0], qd[0], qdd[0]);
        let (psi, wp, ap) = (q[0] + q[1], qd[0] + qd[1], qdd[0] + qdd[1]);
        let r_g = [
            a * t1.cos() + b / 2.0 * psi.cos(),
            a * t1.sin() + b / 2.0 * psi.sin(),
        ];
        let acc_g = [
            a * (-a1 * t1.sin() - w1 * w1 * t1.cos())
                + b / 2.0 * (-ap * psi.sin() - wp * wp * psi.cos()),
            a * (a1 * t1.cos() - w1 * w1 * t1.sin())
                + b / 2.0 * (ap * psi.cos() - wp * wp * psi.sin()),
        ];
        let dl = m1 * a * a / 3.0 * a1
            + m2 * (r_g[0] * acc_g[1] - r_g[1] * acc_g[0])
            + m2 * b * b / 12.0 * ap;
        let moments = -m1 * G * a / 2.0 * t1.cos() - m2 * G * r_g[0] + (bx * l[1] - by * l[0]);
        let scale = (m3 * G * c).max(l[0].abs() + l[1].abs());
        assert!(
            rocker.abs() < 1e-12 * scale,
            "rocker: {rocker:e} (λ = {l:?}, θ̇₃ = {w3})"
        );
        assert!(
            (dl - moments).abs() < 1e-12 * scale,
            "crank and coupler: {dl} against {moments}"
        );
    }
}

#[test]
fn a_triple_rocker_s_crank_passes_its_dead_point_on_the_other_coordinates() {
    let links = [2.0, 1.5, 2.0, 3.0];
    // Crank at 60° swinging up at 4 rad/s, on the branch with the rocker near 105°.
    let theta1 = 60f64.to_radians();
    let branch = [1.0, -1.0]
        .into_iter()
        .min_by(|&x, &y| {
            let near = |b| (freudenstein(links, theta1, b).1 - 105f64.to_radians()).abs();
            near(x).total_cmp(&near(y))
        })
        .unwrap_or(1.0);
    let y0 = start(&TripleRocker, links, theta1, branch, 4.0);
    let (q0, qd0) = halves(&y0);
    let e0 = TripleRocker.energy(&q0, &qd0);
    let limit = (1.0f64 / 16.0).acos();
    let mut run = TripleRocker
        .closed_run(0.0, y0, AdaptiveConfig::with_tol(1e-12, 1e-12))
        .expect("starts");
    let (mut highest, mut reversed, mut worst_phi, mut worst_energy) =
        (0.0_f64, false, 0.0_f64, 0.0_f64);
    let mut crank_dependent = false;
    for k in 1..=2000 {
        run.advance_to(f64::from(k) * 1e-3)
            .expect("the run goes on");
        assert_eq!(run.halt(), None::<&LoopHalt>);
        let (q, qd) = halves(&run.state().x);
        highest = highest.max(q[0]);
        reversed |= qd[0] < 0.0;
        worst_phi = worst_phi.max(TripleRocker.residual(&q));
        worst_energy = worst_energy.max((TripleRocker.energy(&q, &qd) - e0).abs());
        crank_dependent |= TripleRocker
            .partition(&q)
            .expect("regular")
            .dependent
            .contains(&0);
    }
    eprintln!(
        "highest θ₁ {highest} (limit {limit}), max |φ| {worst_phi:e}, energy {worst_energy:e}"
    );
    // The crank rose to its limit, where the rows were solved for it instead, and came back.
    assert!(reversed && crank_dependent);
    assert!((highest - limit).abs() < 1e-6, "{highest} against {limit}");
    assert!(worst_phi <= 1e-10, "{worst_phi:e}");
    assert!(worst_energy <= 1e-8 * e0.abs().max(1.0), "{worst_energy:e}");
}
