//! The crank-rocker `precess::models::FourBar` (crank a = 1, coupler b = 3, rocker c = 2.5,
//! ground d = 3) over 10⁴ crank turns at rtol = atol = 1e-10: the rocker and the coupler
//! against Freudenstein's closed form, the loop residual and the energy.

use std::f64::consts::TAU;

use precess::mechanism::loops::LoopDynamics;
use precess::models::FourBar;
use precess::ode::{AdaptiveConfig, Stepper};
use precess_testkit::linkages::{freudenstein, wrap};

#[test]
fn the_rocker_follows_freudenstein_and_the_loop_stays_closed_over_ten_thousand_turns() {
    let links = [1.0, 3.0, 2.5, 3.0];
    // On the loop at θ₁ = 0.3 on the assembly branch +1, the crank turning at 6 rad/s.
    let theta1 = 0.3;
    let (coupler, rocker) = freudenstein(links, theta1, 1.0);
    let q0 = [theta1, coupler - theta1, rocker];
    let qd0 = FourBar
        .rates_from(&q0, [0], [6.0])
        .expect("the crank is free here");
    let e0 = FourBar.energy(&q0, &qd0);
    let y0 = [q0[0], q0[1], q0[2], qd0[0], qd0[1], qd0[2]];
    let cfg = AdaptiveConfig::with_tol(1e-10, 1e-10);
    let mut run = FourBar
        .closed_run(0.0, y0, cfg)
        .expect("starts on the loop");
    let (mut worst_phi, mut worst_rocker, mut worst_coupler, mut worst_energy) =
        (0.0_f64, 0.0_f64, 0.0_f64, 0.0_f64);
    let mut t = 0.0;
    // About 0.74 s a turn at this energy: sample every 5 s until 10⁴ turns.
    while run.state().x[0] - q0[0] < 1e4 * TAU {
        t += 5.0;
        run.advance_to(t)
            .expect("no halt on a Grashof crank-rocker");
        let x = run.state().x;
        let (q, qd) = ([x[0], x[1], x[2]], [x[3], x[4], x[5]]);
        worst_phi = worst_phi.max(FourBar.residual(&q));
        let (coupler, rocker) = freudenstein(links, q[0], 1.0);
        worst_rocker = worst_rocker.max(wrap(q[2], rocker).abs());
        worst_coupler = worst_coupler.max(wrap(q[0] + q[1], coupler).abs());
        worst_energy = worst_energy.max(((FourBar.energy(&q, &qd) - e0) / e0).abs());
    }
    let turns = (run.state().x[0] - q0[0]) / TAU;
    eprintln!(
        "{turns:.0} turns in {t} s ({} steps): max |φ| {worst_phi:e}, θ₃ off Freudenstein {worst_rocker:e}, coupler {worst_coupler:e}, energy {worst_energy:e}",
        run.inner().stats().steps
    );
    assert!(turns >= 1e4);
    assert!(worst_phi <= 1e-10, "{worst_phi:e}");
    assert!(
        worst_rocker <= 1e-10 && worst_coupler <= 1e-10,
        "{worst_rocker:e} {worst_coupler:e}"
    );
    assert!(worst_energy <= 1e-6, "{worst_energy:e}");
}
