//! Adaptive pairs and RK4 against published reference values (30-digit constants copied
//! from the references; the tests never read them from disk).

use precess_core::ode::{
    AdaptiveConfig, Dp54, Dp853, FnSystem, OdeError, Rk4, Rk4Config, System, solve,
};

/// DETEST B5: y' = (y2 y3, −y1 y3, −0.51 y1 y2), y(0) = (0, 1, 1).
struct B5;
impl System<3> for B5 {
    fn rhs(&self, _t: f64, y: &[f64; 3], d: &mut [f64; 3]) {
        d[0] = y[1] * y[2];
        d[1] = -y[0] * y[2];
        d[2] = -0.51 * y[0] * y[1];
    }
}
const B5_Y20: [f64; 3] = [
    -0.939_657_079_872_920_396_19,
    -0.342_117_775_400_074_906_53,
    0.741_412_659_619_995_300_78,
];
const B5_Y12: [f64; 3] = [
    -0.705_397_809_522_571_74,
    -0.708_811_632_467_158_09,
    0.863_846_690_370_222_10,
];

fn max_err(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max)
}

#[test]
fn b5_dop853_tight_tolerance_hits_1e12() {
    let s = solve::<Dp853, _, 3>(B5, 0.0, [0.0, 1.0, 1.0], 20.0, &[], AdaptiveConfig::with_tol(1e-14, 1e-14))
        .unwrap();
    let e = max_err(&s.y, &B5_Y20);
    eprintln!("B5 DOP853 rtol=atol=1e-14: err {e:e}, stats {:?}", s.stats);
    assert!(e <= 1e-12, "B5 y(20) error {e:e}");
}

#[test]
fn b5_work_precision_print() {
    for tol in [1e-6, 1e-8, 1e-10, 1e-11, 1e-12, 1e-13] {
        let s = solve::<Dp853, _, 3>(B5, 0.0, [0.0, 1.0, 1.0], 20.0, &[], AdaptiveConfig::with_tol(tol, tol)).unwrap();
        let s5 = solve::<Dp54, _, 3>(B5, 0.0, [0.0, 1.0, 1.0], 20.0, &[], AdaptiveConfig::with_tol(tol, tol)).unwrap();
        eprintln!("tol {tol:e}: DOP853 err {:e} evals {} | DP5 err {:e} evals {}", max_err(&s.y, &B5_Y20), s.stats.rhs_evals, max_err(&s5.y, &B5_Y20), s5.stats.rhs_evals);
    }
}
