//! Convergence orders (the numerical check of the tableaux), dense output, stop times,
//! statistics and typed errors of the time-stepping layer.

use precess_core::ode::{
    Adaptive, AdaptiveConfig, Dop853, Dop853Pair, Dopri5, Dopri5Pair, EmbeddedPair,
    FixedStepConfig, FnSystem, OdeError, Rk4, System, Vern9Pair, solve, solve_dense,
};
use precess_testkit::systems::{B5, b5_exact, max_diff};

/// n fixed steps of the pair's propagated solution (no control).
fn fixed<P: EmbeddedPair>(h: f64, n: usize) -> [f64; 3] {
    let (mut y, mut t) = ([0.0, 1.0, 1.0], 0.0);
    let mut k = [[0.0; 3]; 21];
    for _ in 0..n {
        B5.rhs(t, &y, &mut k[0]);
        let mut yn = [0.0; 3];
        P::try_step(&B5, (t, h, f64::INFINITY), &y, &mut k, &mut yn, (1.0, 1.0));
        y = yn;
        t += h;
    }
    y
}

fn observed_order(e1: f64, e2: f64) -> f64 {
    (e1 / e2).log2()
}

#[test]
fn convergence_orders_match_the_tableaux() {
    let t = 4.0;
    let ex = b5_exact(t);
    let e =
        |h: f64, f: &dyn Fn(f64, usize) -> [f64; 3]| max_diff(&f(h, (t / h).round() as usize), &ex);
    let p5 = observed_order(e(0.1, &fixed::<Dopri5Pair>), e(0.05, &fixed::<Dopri5Pair>));
    let p8 = observed_order(e(0.4, &fixed::<Dop853Pair>), e(0.2, &fixed::<Dop853Pair>));
    let rk = |h: f64, n: usize| {
        let mut r = Rk4::new(B5, 0.0, [0.0, 1.0, 1.0], FixedStepConfig::with_step(h)).unwrap();
        r.advance_to(h * n as f64).unwrap();
        *r.y()
    };
    let p4 = observed_order(e(0.1, &rk), e(0.05, &rk));
    let p9 = observed_order(e(0.5, &fixed::<Vern9Pair>), e(0.25, &fixed::<Vern9Pair>));
    eprintln!("observed orders: RK4 {p4:.2}, DOPRI5 {p5:.2}, DOP853 {p8:.2}, Vern9 {p9:.2}");
    assert!((8.6..9.8).contains(&p9), "Vern9 order {p9}");
    assert!((3.8..4.3).contains(&p4), "RK4 order {p4}");
    assert!((4.7..5.5).contains(&p5), "DOPRI5 order {p5}");
    assert!((7.6..8.8).contains(&p8), "DOP853 order {p8}");
}

/// Dense output over one step of size h: local error O(h⁵) for DOPRI5 (order 4 interpolant),
/// O(h⁸) for DOP853 (order 7) and O(h⁹) for Vern9 (order 8).
#[test]
fn dense_output_orders() {
    fn mid_error<P: EmbeddedPair>(h: f64) -> f64 {
        let cfg = AdaptiveConfig {
            h0: Some(h),
            h_max: h,
            ..AdaptiveConfig::with_tol(1e3, 1e3)
        };
        let mut ode: Adaptive<_, P, 3> = Adaptive::new(B5, 0.0, [0.0, 1.0, 1.0], cfg).unwrap();
        ode.step(10.0).unwrap();
        assert_eq!(ode.t(), h);
        max_diff(&ode.dense_at(0.37 * h).unwrap(), &b5_exact(0.37 * h))
    }
    let q5 = observed_order(mid_error::<Dopri5Pair>(0.2), mid_error::<Dopri5Pair>(0.1));
    let q8 = observed_order(mid_error::<Dop853Pair>(0.8), mid_error::<Dop853Pair>(0.4));
    let q9 = observed_order(mid_error::<Vern9Pair>(1.0), mid_error::<Vern9Pair>(0.5));
    eprintln!("dense local orders: DOPRI5 {q5:.2}, DOP853 {q8:.2}, Vern9 {q9:.2}");
    assert!((8.4..9.8).contains(&q9), "Vern9 dense {q9}");
    assert!((4.6..5.6).contains(&q5), "DOPRI5 dense {q5}");
    assert!((7.5..8.8).contains(&q8), "DOP853 dense {q8}");
}

#[test]
fn solve_dense_samples_match_the_exact_solution() {
    let times: Vec<f64> = (0..=40).map(|i| 0.5 * i as f64).collect();
    let mut out = vec![[0.0; 3]; times.len()];
    let stats = solve_dense::<Dop853Pair, _, 3>(
        B5,
        0.0,
        [0.0, 1.0, 1.0],
        &times,
        &mut out,
        AdaptiveConfig::with_tol(1e-12, 1e-12),
    )
    .unwrap();
    for (t, y) in times.iter().zip(&out) {
        assert!(max_diff(y, &b5_exact(*t)) <= 1e-10, "t = {t}");
    }
    assert!(stats.steps < 200 && stats.rhs_evals > 12 * stats.steps);
    let stats = solve_dense::<Vern9Pair, _, 3>(
        B5,
        0.0,
        [0.0, 1.0, 1.0],
        &times,
        &mut out,
        AdaptiveConfig::with_tol(1e-12, 1e-12),
    )
    .unwrap();
    let worst = times
        .iter()
        .zip(&out)
        .map(|(t, y)| max_diff(y, &b5_exact(*t)))
        .fold(0.0, f64::max);
    assert!(worst <= 1e-10, "Vern9 dense output error {worst:e}");
    assert!(stats.steps < 200);
}

#[test]
fn statistics_count_work() {
    let s = solve::<Dopri5Pair, _, 3>(
        B5,
        0.0,
        [0.0, 1.0, 1.0],
        20.0,
        &[],
        AdaptiveConfig::with_tol(1e-8, 1e-8),
    )
    .unwrap();
    let st = s.stats;
    // 1 initial f, 1 for the starting step guess, 6 per attempt (FSAL).
    assert_eq!(st.rhs_evals, 2 + 6 * (st.steps + st.rejections));
    let mut ode = Dop853::new(
        B5,
        0.0,
        [0.0, 1.0, 1.0],
        AdaptiveConfig::with_tol(1e-10, 1e-10),
    )
    .unwrap();
    ode.advance_to(20.0).unwrap();
    let st = ode.stats();
    assert_eq!(st.rhs_evals, 2 + 12 * st.steps + 11 * st.rejections);
    let s = solve::<Vern9Pair, _, 3>(
        B5,
        0.0,
        [0.0, 1.0, 1.0],
        20.0,
        &[],
        AdaptiveConfig::with_tol(1e-10, 1e-10),
    )
    .unwrap();
    assert_eq!(
        s.stats.rhs_evals,
        2 + 16 * s.stats.steps + 15 * s.stats.rejections
    );
}

#[test]
fn switching_rhs_is_exact_with_stops_and_not_without() {
    // y' = 1 on [0, 1), 0 afterwards, y(0) = 0: y(2) = 1 exactly.
    let f =
        FnSystem(|t: f64, _y: &[f64; 1], d: &mut [f64; 1]| d[0] = if t < 1.0 { 1.0 } else { 0.0 });
    let cfg = AdaptiveConfig::with_tol(1e-10, 1e-10);
    let with = solve::<Dop853Pair, _, 1>(&f, 0.0, [0.0], 2.0, &[1.0], cfg).unwrap();
    assert!((with.y[0] - 1.0).abs() <= 1e-14, "{}", with.y[0]);
    let with5 = solve::<Dopri5Pair, _, 1>(&f, 0.0, [0.0], 2.0, &[1.0], cfg).unwrap();
    assert!((with5.y[0] - 1.0).abs() <= 1e-14, "{}", with5.y[0]);
    // RK4 lands on the stop with its last stage just before it, then restarts from it.
    let mut rk = Rk4::new(&f, 0.0, [0.0], FixedStepConfig::with_step(0.1)).unwrap();
    rk.advance_to(1.0).unwrap();
    rk.advance_to(2.0).unwrap();
    assert!((rk.y()[0] - 1.0).abs() <= 1e-14, "RK4 {}", rk.y()[0]);
    let without = solve::<Dop853Pair, _, 1>(&f, 0.0, [0.0], 2.0, &[], cfg).unwrap();
    assert!(
        (without.y[0] - 1.0).abs() > 1e-14,
        "stepping over the switch should lose digits"
    );
}

#[test]
fn bad_input_is_rejected_before_any_work() {
    let y0 = [0.0, 1.0, 1.0];
    let run = |t0: f64, y0: [f64; 3], t1: f64, cfg: AdaptiveConfig| {
        solve::<Dop853Pair, _, 3>(B5, t0, y0, t1, &[], cfg).map(|s| s.y)
    };
    let d = AdaptiveConfig::default();
    assert_eq!(
        run(0.0, y0, 1.0, AdaptiveConfig::with_tol(0.0, 1e-9)),
        Err(OdeError::InvalidTolerance {
            rtol: 0.0,
            atol: 1e-9
        })
    );
    assert!(matches!(
        run(0.0, y0, 1.0, AdaptiveConfig::with_tol(1e-6, -1.0)),
        Err(OdeError::InvalidTolerance { .. })
    ));
    assert!(matches!(
        run(0.0, y0, 1.0, AdaptiveConfig::with_tol(f64::NAN, 1e-9)),
        Err(OdeError::InvalidTolerance { .. })
    ));
    assert!(matches!(
        run(0.0, y0, 1.0, AdaptiveConfig { h0: Some(0.0), ..d }),
        Err(OdeError::InvalidStep { .. })
    ));
    assert!(matches!(
        run(
            0.0,
            y0,
            1.0,
            AdaptiveConfig {
                h0: Some(-1e-3),
                ..d
            }
        ),
        Err(OdeError::InvalidStep { .. })
    ));
    assert!(matches!(
        run(0.0, y0, 1.0, AdaptiveConfig { safety: 2.0, ..d }),
        Err(OdeError::InvalidParameter { name: "safety", .. })
    ));
    assert_eq!(
        run(1.0, y0, 0.0, d),
        Err(OdeError::EndBeforeStart {
            t_start: 1.0,
            t_end: 0.0
        })
    );
    assert!(matches!(
        run(0.0, [0.0, f64::NAN, 1.0], 1.0, d),
        Err(OdeError::NonFiniteInitialState { index: 1, .. })
    ));
    assert!(matches!(
        run(0.0, [f64::INFINITY, 0.0, 1.0], 1.0, d),
        Err(OdeError::NonFiniteInitialState { index: 0, .. })
    ));
    assert!(matches!(
        run(f64::NAN, y0, 1.0, d),
        Err(OdeError::NonFiniteTime { .. })
    ));
    assert!(matches!(
        solve::<Dop853Pair, _, 3>(B5, 0.0, y0, 2.0, &[1.5, 1.0], d),
        Err(OdeError::StopBeforeCurrent { stop: 1.0, .. })
    ));
    assert!(matches!(
        Rk4::new(B5, 0.0, y0, FixedStepConfig::with_step(0.0)),
        Err(OdeError::InvalidStep { .. })
    ));
    assert!(matches!(
        Rk4::new(B5, 0.0, y0, FixedStepConfig::with_step(-0.1)),
        Err(OdeError::InvalidStep { .. })
    ));
    let mut rk = Rk4::new(B5, 0.0, y0, FixedStepConfig::with_step(1e-3)).unwrap();
    assert!(matches!(
        rk.advance_to(1e300),
        Err(OdeError::TooManySteps { .. })
    ));
    assert!(matches!(
        rk.advance_to(f64::INFINITY),
        Err(OdeError::NonFiniteTime { .. })
    ));
    assert_eq!(rk.stats().steps, 0, "refused before any work");
    let mut ode = Dopri5::new(B5, 0.0, y0, d).unwrap();
    assert!(matches!(
        ode.advance_to(f64::INFINITY),
        Err(OdeError::NonFiniteTime { .. })
    ));
    ode.advance_to(1.0).unwrap();
    assert_eq!(
        ode.advance_to(0.5),
        Err(OdeError::StopBeforeCurrent { stop: 0.5, t: 1.0 })
    );
    assert!(matches!(
        ode.dense_at(2.0),
        Err(OdeError::OutsideLastStep { .. })
    ));
}

#[test]
fn blow_up_is_a_typed_error_not_nan() {
    // y' = y², y(0) = 1 blows up at t = 1.
    let f = FnSystem(|_t: f64, y: &[f64; 1], d: &mut [f64; 1]| d[0] = y[0] * y[0]);
    match solve::<Dop853Pair, _, 1>(f, 0.0, [1.0], 2.0, &[], AdaptiveConfig::default()) {
        // The numerical blow-up time is within the tolerance of the true one.
        Err(OdeError::StepSizeUnderflow { t, h }) => {
            assert!((t - 1.0).abs() < 1e-5 && h > 0.0, "t = {t}")
        }
        Err(OdeError::NonFiniteState { t }) => assert!((t - 1.0).abs() < 1e-5, "t = {t}"),
        other => panic!("expected a typed failure near t = 1, got {other:?}"),
    }
    let cfg = AdaptiveConfig {
        max_steps: 10,
        ..AdaptiveConfig::with_tol(1e-12, 1e-12)
    };
    assert!(matches!(
        solve::<Dop853Pair, _, 3>(B5, 0.0, [0.0, 1.0, 1.0], 20.0, &[], cfg),
        Err(OdeError::MaxStepsExceeded { max_steps: 10, .. })
    ));
}

#[test]
fn rk4_stops_at_the_first_non_finite_step() {
    // y' = y², y(0) = 1 blows up at t = 1; asked to go to t = 1e4 (10⁷ steps), RK4 must stop
    // at the blow-up, not run out the span and report its start.
    let f = FnSystem(|_t: f64, y: &[f64; 1], d: &mut [f64; 1]| d[0] = y[0] * y[0]);
    let mut rk = Rk4::new(f, 0.0, [1.0], FixedStepConfig::with_step(1e-3)).unwrap();
    match rk.advance_to(1e4) {
        Err(OdeError::NonFiniteState { t }) => assert!((0.99..1.1).contains(&t), "t = {t}"),
        other => panic!("expected NonFiniteState near t = 1, got {other:?}"),
    }
    assert!(rk.stats().steps < 1_100, "{} steps", rk.stats().steps);
    // The integrator keeps the last finite state, at the start of the failed step.
    assert!(rk.y()[0].is_finite() && rk.y()[0] > 1e3);
    assert!((rk.t() - rk.stats().steps as f64 * 1e-3).abs() < 1e-9);
}

#[test]
fn fixed_step_limit_is_checked_before_any_work() {
    let cfg = FixedStepConfig {
        max_steps: 1_000,
        ..FixedStepConfig::with_step(1e-3)
    };
    let mut rk = Rk4::new(B5, 0.0, [0.0, 1.0, 1.0], cfg).unwrap();
    assert_eq!(
        rk.advance_to(2.0),
        Err(OdeError::TooManySteps {
            t: 0.0,
            t_stop: 2.0,
            h: 1e-3,
            steps: 2000.0,
            max_steps: 1_000
        })
    );
    assert_eq!(rk.stats().steps, 0, "refused before any work");
    // Exactly at the limit is allowed.
    rk.advance_to(1.0).unwrap();
    assert_eq!(rk.stats().steps, 1_000);
    // The documented default: 10⁸ steps per call, so h = 1e-3 to t = 1e6 (10⁹ steps) is
    // refused at once.
    let mut rk = Rk4::new(B5, 0.0, [0.0, 1.0, 1.0], FixedStepConfig::with_step(1e-3)).unwrap();
    assert!(matches!(
        rk.advance_to(1e6),
        Err(OdeError::TooManySteps {
            max_steps: 100_000_000,
            ..
        })
    ));
    let msg = rk.advance_to(1e6).unwrap_err().to_string();
    assert!(msg.contains("max_steps = 100000000"), "{msg}");
}

#[test]
fn non_finite_stop_times_are_named_as_such() {
    let y0 = [0.0, 1.0, 1.0];
    let mut rk = Rk4::new(B5, 0.0, y0, FixedStepConfig::default()).unwrap();
    let mut ode = Dopri5::new(B5, 0.0, y0, AdaptiveConfig::default()).unwrap();
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let named = |r: Result<(), OdeError>| matches!(r, Err(OdeError::NonFiniteTime { t }) if t.is_nan() == bad.is_nan());
        assert!(named(rk.advance_to(bad)), "Rk4::advance_to({bad})");
        assert!(named(ode.advance_to(bad)), "Adaptive::advance_to({bad})");
        assert!(named(ode.step(bad)), "Adaptive::step({bad})");
        assert!(
            named(ode.dense_at(bad).map(|_| ())),
            "Adaptive::dense_at({bad})"
        );
    }
    let msg = ode.advance_to(f64::NAN).unwrap_err().to_string();
    assert!(msg.contains("NaN is not finite"), "{msg}");
    assert!(!msg.contains("before"), "{msg}");
    assert_eq!((rk.stats().steps, ode.stats().steps), (0, 0));
}

mod no_nan {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(200))]

        /// Whatever the input (NaN, ±∞, subnormal, huge), the result is a typed error or a
        /// finite state, never NaN.
        #[test]
        fn solve_returns_finite_or_typed_error(
            y0 in prop::array::uniform3(any::<f64>()),
            rtol in any::<f64>(),
            t_end in any::<f64>(),
        ) {
            let cfg = AdaptiveConfig { max_steps: 2_000, ..AdaptiveConfig::with_tol(rtol, 1e-9) };
            if let Ok(s) = solve::<Dop853Pair, _, 3>(B5, 0.0, y0, t_end, &[], cfg) {
                prop_assert!(s.y.iter().all(|v| v.is_finite()), "{:?}", s.y);
            }
            if let Ok(mut r) = Rk4::new(B5, 0.0, y0, FixedStepConfig::with_step(0.5))
                && r.advance_to(t_end.clamp(0.0, 50.0)).is_ok()
            {
                prop_assert!(r.y().iter().all(|v| v.is_finite()), "{:?}", r.y());
            }
        }
    }
}

/// `reinitialise` is a fresh start with the old counters: from a state reached by steps of one
/// system, it continues exactly as a new driver from that state would (each pair, since the
/// FSAL stage of the old steps must not leak into the first new one).
#[test]
fn reinitialise_continues_as_a_new_driver_would() {
    fn check<P: EmbeddedPair>() {
        let cfg = AdaptiveConfig::with_tol(1e-10, 1e-12);
        let mut ode = Adaptive::<_, P, 3>::new(B5, 0.0, [0.0, 1.0, 1.0], cfg).unwrap();
        ode.advance_to(3.0).unwrap();
        let (t, y) = (ode.t(), [0.3, -0.2, 0.9]);
        ode.reinitialise(t, y).unwrap();
        ode.advance_to(8.0).unwrap();
        let mut fresh = Adaptive::<_, P, 3>::new(B5, t, y, cfg).unwrap();
        fresh.advance_to(8.0).unwrap();
        assert_eq!(ode.y(), fresh.y());
        assert!(ode.stats().steps > fresh.stats().steps);
        assert!(matches!(
            ode.reinitialise(t, [f64::NAN, 0.0, 0.0]),
            Err(OdeError::NonFiniteInitialState { .. })
        ));
        assert_eq!(ode.t(), 8.0);
    }
    check::<Dopri5Pair>();
    check::<Dop853Pair>();
    check::<Vern9Pair>();
}
