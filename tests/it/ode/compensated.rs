//! The numerical floor: compensated summation in RK4 and the free-body splitting against the
//! exact torque-free motion of the near-separatrix body I = (3, 5, 9), m(0) = (0, 2, 0.01),
//! to T = 200 (where round-off, amplified by the motion's sensitivity, used to stop every
//! fixed-step method near 1e-10 and made RK4 worse as h shrank).
//!
//! Each bound sits between the compensated error and the plain one (both measured in
//! `docs/performance.md`), and each test also runs the plain variant to show that it misses
//! the bound: the bounds guard the compensation, not a tolerance that always passes.

use nalgebra::{UnitQuaternion, Vector3};
use precess_core::exact::{FreeBodyAttitude, FreeBodyExact};
use precess_core::ode::{FixedStepConfig, Rk4, Stepper, System};
use precess_core::rigid::{BodyMomentum, FreeBodySplitting, SplittingOrder};

const I: [f64; 3] = [3.0, 5.0, 9.0];
const M0: [f64; 3] = [0.0, 2.0, 0.01];
const T: f64 = 200.0;

/// ṁ = m × (I⁻¹ m).
struct FreeBody;
impl System<3> for FreeBody {
    fn rhs(&self, _t: f64, m: &[f64; 3], d: &mut [f64; 3]) {
        let w = [m[0] / I[0], m[1] / I[1], m[2] / I[2]];
        d[0] = m[1] * w[2] - m[2] * w[1];
        d[1] = m[2] * w[0] - m[0] * w[2];
        d[2] = m[0] * w[1] - m[1] * w[0];
    }
}

fn exact_m(t: f64) -> Vector3<f64> {
    FreeBodyExact::new(I, M0).unwrap().m_at(t).unwrap()
}

fn rk4_error(h: f64, compensated: bool) -> f64 {
    let cfg = FixedStepConfig {
        compensated,
        ..FixedStepConfig::with_step(h)
    };
    let mut rk = Rk4::new(FreeBody, 0.0, M0, cfg).unwrap();
    rk.advance_to(T).unwrap();
    (Vector3::from(*rk.y()) - exact_m(T)).amax()
}

/// (error of m, angle between the attitudes) of a splitting run to T in steps of h.
fn split_errors(order: SplittingOrder, h: f64, compensated: bool) -> (f64, f64) {
    let s = FreeBodySplitting::new(I, order)
        .unwrap()
        .with_compensation(compensated);
    let mut y = BodyMomentum {
        q: UnitQuaternion::identity(),
        m: Vector3::from(M0),
    };
    s.integrate_to(&mut y, T, h).unwrap();
    let (q, _) = FreeBodyAttitude::new(I, UnitQuaternion::identity(), M0)
        .unwrap()
        .at(T)
        .unwrap();
    ((y.m - exact_m(T)).amax(), y.q.angle_to(&q))
}

#[test]
fn rk4_at_a_million_steps_is_at_the_rounding_level() {
    // h = 2e-4: 10⁶ steps. Measured 5.3e-14 compensated, 9.8e-10 plain.
    let compensated = rk4_error(2e-4, true);
    assert!(compensated < 2e-13, "compensated RK4 error {compensated:e}");
    let plain = rk4_error(2e-4, false);
    assert!(
        plain > 2e-13,
        "plain RK4 error {plain:e} (the bound guards nothing)"
    );
}

#[test]
fn rk4_error_falls_with_h_and_does_not_rise_with_the_step_count() {
    // Measured 3.9e-12, 1.1e-13, 8.9e-14 (plain: 1.1e-10, 3.4e-10, 6.1e-10: rising).
    let e: Vec<f64> = [1e-2, 3e-3, 1e-3]
        .iter()
        .map(|&h| rk4_error(h, true))
        .collect();
    assert!(e[0] < 1e-11 && e[1] < 3e-13 && e[2] < 3e-13, "{e:?}");
    assert!(e[1] < e[0] / 10.0, "{e:?}");
    let plain = rk4_error(1e-3, false);
    assert!(plain > 3e-13, "plain RK4 error {plain:e}");
}

#[test]
fn rk4_one_step_at_a_time_carries_the_compensation() {
    // Stepper::step keeps the low-order bits between calls, like advance_to.
    let mut rk = Rk4::new(FreeBody, 0.0, M0, FixedStepConfig::with_step(1e-3)).unwrap();
    while rk.t() < T {
        rk.step(T).unwrap();
    }
    assert_eq!(rk.t(), T);
    let e = (Vector3::from(*rk.y()) - exact_m(T)).amax();
    assert!(e < 3e-13, "RK4 step by step: {e:e}");
}

#[test]
fn order_four_splitting_reaches_below_1e_12() {
    // h = 1e-3 (2·10⁵ steps): measured 6.6e-13 (m) and 4.7e-13 (q) compensated, 2.0e-9 and
    // 1.4e-9 plain.
    let (m, q) = split_errors(SplittingOrder::Four, 1e-3, true);
    assert!(
        m < 2e-12 && q < 2e-12,
        "order 4 compensated: m {m:e}, q {q:e}"
    );
    let (m, _) = split_errors(SplittingOrder::Four, 1e-3, false);
    assert!(m > 2e-12, "order 4 plain: {m:e}");
}

#[test]
fn order_six_splitting_keeps_falling_with_h() {
    // Measured (compensated) 2.0e-12, 6.0e-13, 1.4e-13 at h = 0.03, 0.01, 0.001; plain
    // 5.8e-11, 3.1e-10, 1.3e-9 (rising).
    let e: Vec<f64> = [3e-2, 1e-2, 1e-3]
        .iter()
        .map(|&h| split_errors(SplittingOrder::Six, h, true).0)
        .collect();
    assert!(e[0] < 5e-12 && e[1] < 2e-12 && e[2] < 5e-13, "{e:?}");
    let (plain, _) = split_errors(SplittingOrder::Six, 1e-3, false);
    assert!(plain > 5e-13, "order 6 plain: {plain:e}");
}

#[test]
fn integrate_to_ends_with_a_partial_step_on_the_span() {
    // The GNI book's body, m(10) quoted to 30 digits; 0.03 does not divide 10.
    let (i, m0) = ([2.0, 1.0, 2.0 / 3.0], [1.1f64.cos(), 0.0, 1.1f64.sin()]);
    let m10 = Vector3::new(
        0.407_066_136_588_040_8,
        0.283_007_426_812_843_7,
        0.868_449_167_661_561_7,
    );
    let s = FreeBodySplitting::new(i, SplittingOrder::Six).unwrap();
    let mut y = BodyMomentum {
        q: UnitQuaternion::identity(),
        m: Vector3::from(m0),
    };
    let stats = s.integrate_to(&mut y, 10.0, 0.03).unwrap();
    assert_eq!(stats.steps, 334);
    // Order 6 at h = 0.03: the error is ~1e-11; a missing or doubled partial step of 0.01
    // would be off by |ṁ|·0.01 ≈ 3e-3.
    assert!((y.m - m10).amax() < 1e-9, "{}", (y.m - m10).amax());
    // A span that is a multiple of h takes no sliver step.
    let mut z = BodyMomentum {
        q: UnitQuaternion::identity(),
        m: Vector3::from(m0),
    };
    assert_eq!(s.integrate_to(&mut z, 10.0, 0.1).unwrap().steps, 100);
    assert!(s.integrate_to(&mut z, -1.0, 0.1).is_err());
    assert!(s.integrate_to(&mut z, f64::NAN, 0.1).is_err());
}
