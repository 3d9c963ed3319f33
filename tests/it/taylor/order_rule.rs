//! `OrderRule::MinimumWork` against Jorba and Zou's rule: each run against a closed form or
//! its invariants, and the higher order's fewer steps.
//!
//! - DETEST B5 to t = 20 against its Jacobi elliptic solution (`b5_exact`).
//! - The torque-free body I = (3, 5, 9) from m = (0, 2, 0.01) to t = 200 against
//!   `FreeBodyExact`.
//! - The heavy top in Euler–Poisson form (ω and the upward vertical γ in body axes, ω₃ = 150
//!   rad/s beside direction cosines of size 1, where each component's own scale makes
//!   Jorba and Zou's steps short) over 2 s: its energy, the vertical component of the angular
//!   momentum, |γ| and ω₃ are constants of the motion.

use precess::exact::FreeBodyExact;
use precess::taylor::{OrderRule, Taylor, TaylorConfig, TaylorSystem};
use precess_testkit::systems::{B5, B5_Y0, EulerPoissonTop, b5_exact};

precess::taylor_system! {
    /// ṁ = m × I⁻¹m for I = (3, 5, 9).
    #[derive(Clone, Copy)]
    struct FreeBody359;
    state [m1, m2, m3];
    taylor = 40;
    d/dt m1 = (1.0 / 9.0 - 1.0 / 5.0) * m2 * m3;
    d/dt m2 = (1.0 / 3.0 - 1.0 / 9.0) * m3 * m1;
    d/dt m3 = (1.0 / 5.0 - 1.0 / 3.0) * m1 * m2;
}

/// The symmetric heavy top's moments and M g l: r = (I1 − I3)/I1 = 0.75, s = Mgl/I1 = 25.
const I1: f64 = 0.02;
const I3: f64 = 0.005;
const MGL: f64 = 0.5;
const TOP: EulerPoissonTop = EulerPoissonTop {
    r: (I1 - I3) / I1,
    s: MGL / I1,
};

fn config(tol: f64, rule: OrderRule) -> TaylorConfig {
    TaylorConfig {
        order_rule: rule,
        ..TaylorConfig::with_tol(tol, tol)
    }
}

/// y(t_end) and the number of steps.
fn run<S: TaylorSystem<N>, const N: usize>(
    sys: S,
    y0: [f64; N],
    t_end: f64,
    cfg: TaylorConfig,
) -> ([f64; N], u64) {
    let mut ode = Taylor::new(sys, 0.0, y0, cfg).unwrap();
    ode.advance_to(t_end).unwrap();
    (*ode.y(), ode.stats().steps)
}

fn max_diff<const N: usize>(a: &[f64; N], b: &[f64; N]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

#[test]
fn minimum_work_is_the_default() {
    assert_eq!(TaylorConfig::default().order_rule, OrderRule::MinimumWork);
    assert_eq!(
        TaylorConfig::with_tol(1e-10, 1e-10).order_rule,
        OrderRule::MinimumWork
    );
}

#[test]
fn b5_meets_its_tolerance_in_three_fifths_of_the_steps() {
    let exact = b5_exact(20.0);
    for tol in [1e-8, 1e-10, 1e-12, 1e-14] {
        let (jz, jz_steps) = run(B5, B5_Y0, 20.0, config(tol, OrderRule::JorbaZou));
        let (mw, mw_steps) = run(B5, B5_Y0, 20.0, config(tol, OrderRule::MinimumWork));
        let (e_jz, e_mw) = (max_diff(&jz, &exact), max_diff(&mw, &exact));
        println!(
            "B5 tol {tol:e}: Jorba-Zou {jz_steps} steps, error {e_jz:.2e}; minimum work {mw_steps} steps, error {e_mw:.2e}"
        );
        // A global error over 20 s (about six half-periods) within a few tolerances.
        assert!(e_mw <= 50.0 * tol + 1e-15, "tol {tol:e}: error {e_mw:e}");
        assert!(
            5 * mw_steps <= 3 * jz_steps,
            "{mw_steps} against {jz_steps}"
        );
    }
}

#[test]
fn the_free_body_meets_the_exact_solution_in_three_fifths_of_the_steps() {
    let m0 = [0.0, 2.0, 0.01];
    let exact = FreeBodyExact::new([3.0, 5.0, 9.0], m0)
        .unwrap()
        .m_at(200.0)
        .unwrap();
    let exact = [exact[0], exact[1], exact[2]];
    for tol in [1e-10, 1e-12, 1e-14] {
        let (jz, jz_steps) = run(FreeBody359, m0, 200.0, config(tol, OrderRule::JorbaZou));
        let (mw, mw_steps) = run(FreeBody359, m0, 200.0, config(tol, OrderRule::MinimumWork));
        let (e_jz, e_mw) = (max_diff(&jz, &exact), max_diff(&mw, &exact));
        println!(
            "free body tol {tol:e}: Jorba-Zou {jz_steps} steps, error {e_jz:.2e}; minimum work {mw_steps} steps, error {e_mw:.2e}"
        );
        // 200 s are about 30 turns of the body: the local tolerance gathers over them (the
        // Jorba–Zou run's error is 6e-10 at 1e-10), and rounding floors it near 1e-11.
        assert!(e_mw <= 100.0 * tol + 5e-11, "tol {tol:e}: error {e_mw:e}");
        assert!(
            5 * mw_steps <= 3 * jz_steps,
            "{mw_steps} against {jz_steps}"
        );
    }
}

/// Energy, vertical angular momentum, |γ|² and ω₃ of the heavy top's state.
fn invariants(y: &[f64; 6]) -> [f64; 4] {
    let [w1, w2, w3, g1, g2, g3] = *y;
    let energy = 0.5 * (I1 * (w1 * w1 + w2 * w2) + I3 * w3 * w3) + MGL * g3;
    let vertical = I1 * (w1 * g1 + w2 * g2) + I3 * w3 * g3;
    [energy, vertical, g1 * g1 + g2 * g2 + g3 * g3, w3]
}

#[test]
fn the_heavy_top_keeps_its_invariants_in_half_the_steps() {
    let theta: f64 = 0.35;
    let y0 = [0.0, 0.0, 150.0, 0.0, theta.sin(), theta.cos()];
    let before = invariants(&y0);
    for tol in [1e-10, 1e-12, 1e-14] {
        let (jz, jz_steps) = run(TOP, y0, 2.0, config(tol, OrderRule::JorbaZou));
        let (mw, mw_steps) = run(TOP, y0, 2.0, config(tol, OrderRule::MinimumWork));
        let drift = |y: &[f64; 6]| {
            let after = invariants(y);
            before
                .iter()
                .zip(after)
                .map(|(b, a)| ((a - b) / b.abs().max(1e-300)).abs())
                .fold(0.0, f64::max)
        };
        println!(
            "heavy top tol {tol:e}: Jorba-Zou {jz_steps} steps, drift {:.2e}; minimum work {mw_steps} steps, drift {:.2e}",
            drift(&jz),
            drift(&mw)
        );
        assert!(
            drift(&mw) <= 100.0 * tol + 1e-13,
            "tol {tol:e}: drift {:e}",
            drift(&mw)
        );
        assert!(2 * mw_steps <= jz_steps, "{mw_steps} against {jz_steps}");
    }
}
