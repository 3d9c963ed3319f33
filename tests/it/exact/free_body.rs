//! The exact torque-free angular momentum against quoted references (GNI body; the
//! I = (3, 5, 9) near-separatrix case) and against DOP853 at tight tolerance in every regime.
// Reference constants are quoted with all their published digits.
#![allow(clippy::excessive_precision)]

use precess_core::exact::{ExactError, FreeBodyExact, Regime, free_body_flow};
use precess_core::ode::{AdaptiveConfig, Dop853Pair, solve};
use precess_testkit::systems::{FreeBody, GNI_I, GNI_M1, GNI_M10};

const GNI_PERIOD: f64 = 10.731_465_234_882_8;
const GNI_H: f64 = 0.647_125_279_313_836;

fn gni_m0() -> [f64; 3] {
    [1.1f64.cos(), 0.0, 1.1f64.sin()]
}

fn dist(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

fn energy(i: &[f64; 3], m: &[f64; 3]) -> f64 {
    0.5 * (m[0] * m[0] / i[0] + m[1] * m[1] / i[1] + m[2] * m[2] / i[2])
}

#[test]
fn gni_body_against_30_digit_references() {
    let fb = FreeBodyExact::new(GNI_I, gni_m0()).unwrap();
    let (e1, e10) = (
        dist(&<[f64; 3]>::from(fb.m_at(1.0).unwrap()), &GNI_M1),
        dist(&<[f64; 3]>::from(fb.m_at(10.0).unwrap()), &GNI_M10),
    );
    eprintln!(
        "exact GNI m(1) error {e1:e}, m(10) error {e10:e}, period {}",
        fb.period()
    );
    assert!(e1 <= 1e-15 && e10 <= 1e-15, "{e1:e} {e10:e}");
    assert!(
        (fb.period() - GNI_PERIOD).abs() <= 2e-13,
        "period {}",
        fb.period()
    );
    assert!((energy(&GNI_I, &gni_m0()) - GNI_H).abs() <= 1e-15);
    assert_eq!(fb.regime(), Regime::AboutSmallest);
}

#[test]
fn near_separatrix_constants() {
    let fb = FreeBodyExact::new([3.0, 5.0, 9.0], [0.0, 2.0, 0.01]).unwrap();
    eprintln!(
        "(3,5,9): m_c {:e} K {} λ {} period {}",
        fb.mc(),
        fb.k(),
        fb.lambda(),
        fb.period()
    );
    assert_eq!(fb.regime(), Regime::AboutLargest);
    assert!(
        (fb.mc() - 4.166_493_06e-5).abs() <= 1e-13,
        "m_c {:e}",
        fb.mc()
    );
    assert!(
        (fb.k() - 6.429_276_301_985_03).abs() <= 1e-13,
        "K {}",
        fb.k()
    );
    assert!(
        (fb.lambda().abs() - 0.217_736_957_625_593).abs() <= 1e-15,
        "λ {}",
        fb.lambda()
    );
    assert!(
        (fb.period() - 118.110_887_046).abs() <= 1e-9,
        "period {}",
        fb.period()
    );
    assert!((2.0 * fb.k() / fb.lambda().abs() - 59.055_443_5).abs() <= 1e-7);
    // The linear growth rate about axis 2, σ = ω₂ √((I₂−I₁)(I₃−I₂)/(I₁I₃)), is λ's limit.
    let sigma = 2.0 / 5.0 * (2.0f64 * 4.0 / 27.0).sqrt();
    assert!((fb.lambda().abs() - sigma).abs() / sigma < 1e-4);
}

/// Every regime, both senses, unsorted and oddly permuted axes, against DOP853 at 1e-14.
#[test]
fn every_regime_agrees_with_dop853() {
    let cases: [([f64; 3], [f64; 3], Regime); 10] = [
        ([1.0, 2.0, 3.0], [0.3, -0.2, 1.0], Regime::AboutLargest),
        ([1.0, 2.0, 3.0], [1.0, 0.4, -0.3], Regime::AboutSmallest),
        ([3.0, 1.0, 2.0], [0.2, 1.0, -0.4], Regime::AboutSmallest),
        ([2.0, 3.0, 1.0], [-0.7, 0.5, 0.6], Regime::AboutSmallest),
        ([2.0, 3.0, 6.0], [1.0, 0.5, 1.0], Regime::Separatrix),
        ([2.0, 3.0, 6.0], [-1.0, -0.5, 1.0], Regime::Separatrix),
        ([3.0, 5.0, 9.0], [0.0, 2.0, 0.01], Regime::AboutLargest),
        ([1.0, 1.0, 2.0], [0.6, 0.3, 0.8], Regime::AboutLargest),
        ([1.0, 2.0, 2.0], [0.6, 0.3, 0.8], Regime::AboutSmallest),
        ([1.0, 2.0, 3.0], [0.0, 1.5, 0.0], Regime::Steady),
    ];
    let cfg = AdaptiveConfig::with_tol(1e-14, 1e-14);
    for (inertia, m0, regime) in cases {
        let fb = FreeBodyExact::new(inertia, m0).unwrap();
        assert_eq!(fb.regime(), regime, "{inertia:?} {m0:?}");
        for t_end in [0.7, 10.0, 40.0] {
            let s = solve::<Dop853Pair, _, 3>(FreeBody(inertia), 0.0, m0, t_end, &[], cfg).unwrap();
            let e = dist(&<[f64; 3]>::from(fb.m_at(t_end).unwrap()), &s.y);
            assert!(e <= 1e-11, "{inertia:?} {m0:?} t={t_end}: {e:e}");
        }
    }
}

#[test]
fn separatrix_tends_to_the_intermediate_axis() {
    // On D₂ = 0, m₂ → ±G and m₁, m₃ → 0 like sech.
    let (i, m0) = ([2.0, 3.0, 6.0], [1.0, 0.5, 1.0]);
    let g = (1.0f64 + 0.25 + 1.0).sqrt();
    let fb = FreeBodyExact::new(i, m0).unwrap();
    let late = <[f64; 3]>::from(fb.m_at(60.0).unwrap());
    let early = <[f64; 3]>::from(fb.m_at(-60.0).unwrap());
    assert!((late[1].abs() - g).abs() <= 1e-12 && (early[1].abs() - g).abs() <= 1e-12);
    assert!(late[1] * early[1] < 0.0, "the separatrix connects −G to +G");
}

/// Over t ≤ 10⁴ the invariants hold to round-off and the flow composes: φ_{a+b} = φ_b ∘ φ_a.
#[test]
fn long_times_keep_invariants_and_group_property() {
    for (i, m0) in [([3.0, 5.0, 9.0], [0.0, 2.0, 0.01]), (GNI_I, gni_m0())] {
        let fb = FreeBodyExact::new(i, m0).unwrap();
        let (g0, h0) = (m0.iter().map(|x| x * x).sum::<f64>(), energy(&i, &m0));
        for t in [1e2, 1e3, 5e3, 1e4] {
            let m = <[f64; 3]>::from(fb.m_at(t).unwrap());
            let g = m.iter().map(|x| x * x).sum::<f64>();
            assert!((g - g0).abs() <= 1e-14 * g0, "|m|² drift at {t}");
            assert!((energy(&i, &m) - h0).abs() <= 1e-14 * h0, "H drift at {t}");
            // Restarting from a rounded m(t/2) perturbs λ and K; near the separatrix
            // (m_c ≈ 4e-5) K is 1/(2m_c) times more sensitive, so that case gets more slack.
            let half: [f64; 3] =
                free_body_flow(i, <[f64; 3]>::from(fb.m_at(0.5 * t).unwrap()), 0.5 * t)
                    .unwrap()
                    .into();
            let tol = if fb.mc() < 1e-3 { 1e-10 } else { 1e-12 };
            eprintln!("group property at {t}: {:e}", dist(&half, &m));
            assert!(
                dist(&half, &m) <= tol,
                "group property at {t}: {:e}",
                dist(&half, &m)
            );
        }
    }
}

#[test]
fn bad_input_is_rejected_before_work() {
    assert_eq!(
        FreeBodyExact::new([1.0, 0.0, 2.0], [1.0, 0.0, 0.0]),
        Err(ExactError::InvalidInertia {
            inertia: [1.0, 0.0, 2.0]
        })
    );
    assert!(matches!(
        FreeBodyExact::new([1.0, -2.0, 2.0], [1.0; 3]),
        Err(ExactError::InvalidInertia { .. })
    ));
    assert!(matches!(
        FreeBodyExact::new([1.0, 2.0, f64::NAN], [1.0; 3]),
        Err(ExactError::InvalidInertia { .. })
    ));
    assert!(matches!(
        FreeBodyExact::new([1.0, 2.0, 3.0], [1.0, f64::NAN, 0.0]),
        Err(ExactError::NonFinite { .. })
    ));
    let fb = FreeBodyExact::new([1.0, 2.0, 3.0], [1.0, 0.1, 0.2]).unwrap();
    assert!(matches!(
        fb.m_at(f64::INFINITY),
        Err(ExactError::NonFinite { .. })
    ));
    assert!(matches!(
        fb.m_at(1e300),
        Err(ExactError::ArgumentTooLarge { .. })
    ));
}

mod properties {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// Random bodies and states: the exact solution agrees with DOP853 at t = 3 and keeps
        /// |m|² and H at t up to 1e3.
        #[test]
        fn random_bodies_agree_with_dop853(
            i in prop::array::uniform3(0.2f64..5.0),
            m0 in prop::array::uniform3(-2.0f64..2.0),
            t in 0.0f64..1e3,
        ) {
            prop_assume!(m0.iter().map(|x| x * x).sum::<f64>() > 1e-2);
            let fb = FreeBodyExact::new(i, m0).unwrap();
            let s = solve::<Dop853Pair, _, 3>(FreeBody(i), 0.0, m0, 3.0, &[], AdaptiveConfig::with_tol(1e-13, 1e-13)).unwrap();
            let g = m0.iter().map(|x| x * x).sum::<f64>().sqrt();
            prop_assert!(dist(&<[f64; 3]>::from(fb.m_at(3.0).unwrap()), &s.y) <= 1e-10 * g, "{:e}", dist(&<[f64; 3]>::from(fb.m_at(3.0).unwrap()), &s.y));
            let m = <[f64; 3]>::from(fb.m_at(t).unwrap());
            let (g2, g20) = (m.iter().map(|x| x * x).sum::<f64>(), g * g);
            prop_assert!((g2 - g20).abs() <= 1e-14 * g20);
            let h0 = energy(&i, &m0);
            prop_assert!((energy(&i, &m) - h0).abs() <= 1e-14 * h0);
        }
    }
}

mod no_nan {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(500))]

        /// Any f64 inputs: a typed error or finite m(t), never NaN.
        #[test]
        fn exact_returns_finite_or_typed_error(
            i in prop::array::uniform3(any::<f64>()),
            m0 in prop::array::uniform3(any::<f64>()),
            t in any::<f64>(),
        ) {
            if let Ok(fb) = FreeBodyExact::new(i, m0)
                && let Ok(m) = fb.m_at(t)
            {
                prop_assert!(m.iter().all(|v| v.is_finite()), "{i:?} {m0:?} {t}: {m:?}");
            }
        }

        /// Physically sized but arbitrary inputs always succeed and stay finite.
        #[test]
        fn moderate_inputs_always_succeed(
            i in prop::array::uniform3(1e-6f64..1e6),
            m0 in prop::array::uniform3(-1e6f64..1e6),
            t in -1e3f64..1e3,
        ) {
            let m = FreeBodyExact::new(i, m0).unwrap().m_at(t).unwrap();
            prop_assert!(m.iter().all(|v| v.is_finite()));
        }
    }
}
