//! The adaptive Taylor integrator against independent values: the Jacobi-elliptic closed form
//! of DETEST B5 and its 30-digit reference, the exact torque-free body, the closed-form flip
//! times 2K/λ as events, and cos t over a million steps. The coefficient recurrences here are
//! written by hand (Cauchy products), independent of the generated ones.
// Reference constants are quoted with all their published digits.
#![allow(clippy::excessive_precision)]

use std::f64::consts::PI;

use approx::assert_relative_eq;
use precess_core::exact::FreeBodyExact;
use precess_core::ode::{Event, OdeError, Run, Stepper};
use precess_core::taylor::{Taylor, TaylorConfig, TaylorSystem, solve, solve_dense};
use precess_testkit::systems::{B5, B5_Y20, FreeBody, Oscillator, b5_exact, max_diff};

/// Σ_{j=0}^{k} a_j b_{k−j}: the k-th coefficient of a product.
fn cauchy<const N: usize>(c: &[[f64; N]], a: usize, b: usize, k: usize) -> f64 {
    (0..=k).map(|j| c[j][a] * c[k - j][b]).sum()
}

/// y' = y², y(0) = 1: y = 1/(1 − t) blows up at t = 1.
struct BlowUp;
impl TaylorSystem<1> for BlowUp {
    fn max_order(&self) -> usize {
        30
    }
    type Workspace = ();
    fn coefficients_into(
        &self,
        _ws: &mut (),
        _t: f64,
        y: &[f64; 1],
        order: usize,
        c: &mut [[f64; 1]],
    ) {
        c[0] = *y;
        for k in 0..order {
            c[k + 1][0] = cauchy(c, 0, 0, k) / (k + 1) as f64;
        }
    }
}

#[test]
fn fixed_order_and_step_converge_at_the_order() {
    // Global error ∝ hᵖ: halving h divides it by 2ᵖ. On B5 to t = 4 against the closed form.
    let exact = b5_exact(4.0);
    for p in [3, 4, 6] {
        let err = |h: f64| {
            let s = solve(
                B5,
                0.0,
                [0.0, 1.0, 1.0],
                4.0,
                &[],
                TaylorConfig::fixed(p, h),
            )
            .unwrap();
            max_diff(&s.y, &exact)
        };
        let (e1, e2) = (err(0.1), err(0.05));
        let observed = (e1 / e2).log2();
        eprintln!("order {p}: errors {e1:.3e} {e2:.3e}, observed order {observed:.3}");
        assert!(
            (observed - p as f64).abs() < 0.3,
            "order {p}: observed {observed}"
        );
    }
}

#[test]
fn b5_to_t20_matches_the_reference_at_every_tolerance() {
    for (tol, bound) in [(1e-6, 1e-5), (1e-10, 1e-9), (1e-12, 1e-11), (1e-15, 1e-14)] {
        let cfg = TaylorConfig::with_tol(tol, tol);
        let s = solve(B5, 0.0, [0.0, 1.0, 1.0], 20.0, &[], cfg).unwrap();
        let e = max_diff(&s.y, &B5_Y20);
        eprintln!("B5 tol {tol:e}: error {e:.2e}, {:?}", s.stats);
        assert!(e <= bound, "tol {tol:e}: error {e:e}");
        // The closed form agrees with the published digits: both are references.
        assert!(max_diff(&b5_exact(20.0), &B5_Y20) <= 1e-15);
    }
}

#[test]
fn dense_output_is_the_step_polynomial_as_accurate_as_the_steps() {
    let times: Vec<f64> = (0..=200).map(|k| k as f64 * 0.1).collect();
    let mut out = vec![[0.0; 3]; times.len()];
    let cfg = TaylorConfig::with_tol(1e-15, 1e-15);
    let stats = solve_dense(B5, 0.0, [0.0, 1.0, 1.0], &times, &mut out, cfg).unwrap();
    let worst = times
        .iter()
        .zip(&out)
        .map(|(&t, y)| max_diff(y, &b5_exact(t)))
        .fold(0.0, f64::max);
    eprintln!("B5 dense output worst error {worst:.2e}, {stats:?}");
    assert!(worst <= 2e-14, "dense output error {worst:e}");
    // Far fewer steps than samples: the samples come from the polynomials.
    assert!(stats.steps < 100, "{stats:?}");
}

#[test]
fn torque_free_bodies_to_t200_against_the_exact_flow() {
    let m0 = [0.0, 2.0, 0.01];
    // Both start next to the unstable intermediate axis, so rounding grows along the flow:
    // one ulp added to m3 at t = 100 moves m(200) by 7e-14 on the exact flow. At 1e-15 the
    // error is rounding, not truncation: with the same steps and only the step sizes
    // perturbed by 1e-10, thirteen runs spread over 3e-13 … 4.2e-12 on (3, 5, 7) and
    // 2.5e-13 … 9.4e-12 on (3, 5, 9), so the bound sits above that spread. Below it is the
    // extended mode's work (tests/taylor_extended.rs: ≤ 1e-15 on both).
    for (inertia, tol, bound) in [
        ([3.0, 5.0, 7.0], 1e-15, 2e-11),
        ([3.0, 5.0, 7.0], 1e-10, 1e-8),
        ([3.0, 5.0, 9.0], 1e-15, 2e-11),
        ([3.0, 5.0, 9.0], 1e-12, 1e-9),
    ] {
        let exact: [f64; 3] = FreeBodyExact::new(inertia, m0)
            .unwrap()
            .m_at(200.0)
            .unwrap()
            .into();
        let cfg = TaylorConfig::with_tol(tol, tol);
        let s = solve(FreeBody(inertia), 0.0, m0, 200.0, &[], cfg).unwrap();
        let e = max_diff(&s.y, &exact);
        eprintln!("I = {inertia:?} tol {tol:e}: error {e:.2e}, {:?}", s.stats);
        assert!(e <= bound, "I = {inertia:?} tol {tol:e}: error {e:e}");
    }
}

/// AGM(a, b), for K(m) = π / (2 AGM(1, √(1 − m))).
fn agm(mut a: f64, mut b: f64) -> f64 {
    while (a - b).abs() > 1e-16 * a {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    a
}

#[test]
fn flips_near_the_separatrix_are_events_2k_over_lambda_apart() {
    // I = (3, 5, 9), m(0) = (0, 2, 0.01): m2 = A2 sn(λt + K) vanishes at K/λ + j·2K/λ.
    let (i, m) = ([3.0, 5.0, 9.0], [0.0f64, 2.0, 0.01]);
    let d1 = m[1] * m[1] * (i[1] - i[0]) / i[1] + m[2] * m[2] * (i[2] - i[0]) / i[2];
    let d2 = m[2] * m[2] * (i[2] - i[1]) / i[2] - m[0] * m[0] * (i[1] - i[0]) / i[0];
    let mc = d2 * (i[2] - i[0]) / (d1 * (i[2] - i[1]));
    let k = PI / (2.0 * agm(1.0, mc.sqrt()));
    let lambda = ((i[2] - i[1]) * d1 / (i[0] * i[1] * i[2])).sqrt();
    assert_relative_eq!(k, 6.42927630198503, max_relative = 1e-13);
    let (first, interval) = (k / lambda, 2.0 * k / lambda);
    let t_end = first + 6.5 * interval;
    let mut ode = Taylor::new(FreeBody(i), 0.0, m, TaylorConfig::with_tol(1e-15, 1e-15)).unwrap();
    let out = Run::new(&mut ode, t_end)
        .sample_none()
        .event(Event::new("omega2"), |_t, m| m[1] / 5.0)
        .integrate()
        .unwrap();
    assert_eq!(out.events.len(), 7);
    for (j, hit) in out.events.iter().enumerate() {
        let expected = first + j as f64 * interval;
        eprintln!(
            "flip {j}: {} vs {expected}, relative {:.1e}",
            hit.t,
            (hit.t - expected).abs() / expected
        );
        assert_relative_eq!(hit.t, expected, max_relative = 1e-12);
        assert!(
            hit.state[1].abs() <= 1e-13,
            "m2 at the flip {}",
            hit.state[1]
        );
    }
}

#[test]
fn a_terminal_event_stops_the_run_on_its_root() {
    // x = cos t first falls through 0 at π/2; the run ends there and restarts cleanly.
    let mut ode = Taylor::new(
        Oscillator,
        0.0,
        [1.0, 0.0],
        TaylorConfig::with_tol(1e-14, 1e-14),
    )
    .unwrap();
    let out = Run::new(&mut ode, 10.0)
        .sample_every(0.5)
        .event(Event::new("x").falling().terminal(), |_t, y| y[0])
        .integrate()
        .unwrap();
    assert_relative_eq!(out.t, PI / 2.0, max_relative = 1e-15);
    assert_relative_eq!(out.state[1], -1.0, max_relative = 1e-15);
    for (t, y) in out.trajectory.times().iter().zip(out.trajectory.states()) {
        assert!((y[0] - t.cos()).abs() <= 1e-14, "x({t}) = {}", y[0]);
    }
    // Continuing from the event: the next falling zero is at 5π/2.
    let out = Run::new(&mut ode, 10.0)
        .sample_none()
        .event(Event::new("x").falling(), |_t, y| y[0])
        .integrate()
        .unwrap();
    assert_eq!(out.events.len(), 1);
    assert_relative_eq!(out.events[0].t, 2.5 * PI, max_relative = 1e-14);
}

#[test]
fn a_million_steps_keep_the_error_at_rounding_level() {
    // cos t to t = 10⁴ in 10⁶ steps of 0.01 at order 14: the truncation is ~1e-40 per step,
    // so what remains is rounding. Measured: 4.9e-15 with the compensated sums; 1.2e-13 with
    // the state summed plainly, and 1.6e-7 with the time summed plainly (the steps' sum is
    // then not the time the solution is compared at).
    let cfg = TaylorConfig {
        order: Some(14),
        fixed_step: Some(0.01),
        max_steps: 2_000_000,
        ..TaylorConfig::default()
    };
    let t_end = 1e4;
    let mut ode = Taylor::new(Oscillator, 0.0, [1.0, 0.0], cfg).unwrap();
    ode.advance_to(t_end).unwrap();
    let y = ode.y();
    let e = (y[0] - t_end.cos()).abs().max((y[1] + t_end.sin()).abs());
    let energy = (y[0] * y[0] + y[1] * y[1] - 1.0).abs();
    eprintln!(
        "oscillator, {} steps: error {e:.2e}, energy {energy:.2e}",
        ode.stats().steps
    );
    assert!(ode.stats().steps >= 1_000_000);
    assert!(e <= 2e-14, "error {e:e}");
    assert!(energy <= 1e-14, "energy error {energy:e}");
}

#[test]
fn bad_input_and_failures_are_typed_errors() {
    let y0 = [0.0, 1.0, 1.0];
    let bad = |cfg: TaylorConfig| Taylor::new(B5, 0.0, y0, cfg).err();
    assert!(matches!(
        bad(TaylorConfig::with_tol(0.0, 1e-9)),
        Some(OdeError::InvalidTolerance { .. })
    ));
    assert!(matches!(
        bad(TaylorConfig::fixed(1, 0.1)),
        Some(OdeError::InvalidParameter { name: "order", .. })
    ));
    assert!(matches!(
        bad(TaylorConfig::fixed(4, -0.1)),
        Some(OdeError::InvalidStep { .. })
    ));
    assert!(matches!(
        Taylor::new(B5, f64::NAN, y0, TaylorConfig::default()).err(),
        Some(OdeError::NonFiniteTime { .. })
    ));
    assert!(matches!(
        Taylor::new(B5, 0.0, [0.0, f64::INFINITY, 1.0], TaylorConfig::default()).err(),
        Some(OdeError::NonFiniteInitialState { index: 1, .. })
    ));
    assert!(matches!(
        solve(B5, 1.0, y0, 0.0, &[], TaylorConfig::default()).err(),
        Some(OdeError::EndBeforeStart { .. })
    ));
    assert!(matches!(
        solve(B5, 0.0, y0, 2.0, &[1.5, 1.0], TaylorConfig::default()).err(),
        Some(OdeError::StopBeforeCurrent { .. })
    ));
    let few = TaylorConfig {
        max_steps: 3,
        ..TaylorConfig::with_tol(1e-12, 1e-12)
    };
    assert!(matches!(
        solve(B5, 0.0, y0, 20.0, &[], few).err(),
        Some(OdeError::MaxStepsExceeded { max_steps: 3, .. })
    ));
    // y' = y² blows up at t = 1: the steps shrink with the distance to the pole until they
    // no longer change t (or the state overflows), and the error says where.
    let err = solve(
        BlowUp,
        0.0,
        [1.0],
        2.0,
        &[],
        TaylorConfig {
            max_steps: 1_000_000,
            ..TaylorConfig::with_tol(1e-12, 1e-12)
        },
    )
    .unwrap_err();
    match err {
        OdeError::StepSizeUnderflow { t, .. } | OdeError::NonFiniteState { t } => {
            assert!((t - 1.0).abs() < 1e-6, "failed at t = {t}");
        }
        other => panic!("unexpected {other:?}"),
    }
    // The stepper refuses to step backwards and dense output outside the last step.
    let mut ode = Taylor::new(B5, 0.0, y0, TaylorConfig::default()).unwrap();
    ode.step(1.0).unwrap();
    assert!(matches!(
        ode.step(-1.0),
        Err(OdeError::StopBeforeCurrent { .. })
    ));
    assert!(matches!(
        ode.state_at(ode.t() + 1.0),
        Err(OdeError::OutsideLastStep { .. })
    ));
}

/// The oscillator with one coefficient replaced by a bad value: `(order, value)`.
struct Poisoned(usize, f64);
impl TaylorSystem<2> for Poisoned {
    fn max_order(&self) -> usize {
        40
    }
    type Workspace = ();
    fn coefficients_into(
        &self,
        ws: &mut (),
        t: f64,
        y: &[f64; 2],
        order: usize,
        c: &mut [[f64; 2]],
    ) {
        Oscillator.coefficients_into(ws, t, y, order, c);
        if let Some(ck) = c.get_mut(self.0) {
            ck[1] = self.1;
        }
    }
}

#[test]
fn a_non_finite_coefficient_at_any_order_is_reported() {
    // tol 1e-10: order 13. The step reads the last two rows for its size; every row reaches
    // the new state through the sum. Either way the error is NonFiniteState, nothing moves.
    for cfg in [
        TaylorConfig::with_tol(1e-10, 1e-10),
        TaylorConfig::fixed(13, 0.1),
    ] {
        for k in 1..=13 {
            for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                let mut ode = Taylor::new(Poisoned(k, bad), 0.0, [1.0, 0.0], cfg).unwrap();
                let err = ode.step(1.0).unwrap_err();
                assert!(
                    matches!(err, OdeError::NonFiniteState { t } if t == 0.0),
                    "c_{k} = {bad}, {cfg:?}: {err:?}"
                );
                assert_eq!((ode.t(), *ode.y()), (0.0, [1.0, 0.0]));
            }
        }
    }
}
