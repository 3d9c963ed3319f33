//! Jacobi elliptic functions and K against closed forms, series and published values, for
//! m_c from 1 down to 1e-15. Constants are copied here; nothing is read from disk.
// Reference constants are quoted with all their published digits.
#![allow(clippy::excessive_precision)]

use precess_core::exact::carlson::{ellip_f, ellip_f_sc, ellip_pi, rf, rj};
use precess_core::exact::{ExactError, Jacobi, ellip_k, sncndn};

const MCS: [f64; 12] = [
    1.0, 0.9, 0.5, 0.49, 0.1, 1e-3, 1e-6, 1e-9, 1e-12, 1e-14, 1e-15, 0.0,
];

/// K(1/2) = Γ(1/4)² / (4√π).
const K_HALF: f64 = 1.854_074_677_301_371_918_433_850_347_195_260;
/// K(0.51) from DETEST B5 (period 4K = 7.4505632093).
const K_051: f64 = 1.862_640_802_332_738_552;
/// B5: (sn, cn, dn)(t | m = 0.51) at t = 12 and t = 20, 30-digit references.
const B5_Y12: [f64; 3] = [
    -0.705_397_809_522_571_74,
    -0.708_811_632_467_158_09,
    0.863_846_690_370_222_10,
];
const B5_Y20: [f64; 3] = [
    -0.939_657_079_872_920_396_19,
    -0.342_117_775_400_074_906_53,
    0.741_412_659_619_995_300_78,
];

#[test]
fn identities_hold_across_parameters_and_arguments() {
    let mut worst = [0.0f64; 2];
    for mc in MCS {
        let j = Jacobi::new(mc).unwrap();
        for i in -300..=300 {
            let u = i as f64 * 0.1 + 0.013;
            let (sn, cn, dn) = j.sncndn(u);
            let e1 = (sn * sn + cn * cn - 1.0).abs();
            let e2 = (dn * dn + (1.0 - mc) * sn * sn - 1.0).abs();
            worst = [worst[0].max(e1), worst[1].max(e2)];
            assert!(e1 <= 6e-16, "sn²+cn²−1 = {e1:e} at u={u}, mc={mc}");
            assert!(e2 <= 6e-16, "dn²+k²sn²−1 = {e2:e} at u={u}, mc={mc}");
            assert!(dn > 0.0 || mc == 0.0);
        }
    }
    eprintln!("worst identity residuals {:e} {:e}", worst[0], worst[1]);
}

#[test]
fn derivatives_match_finite_differences() {
    let h = 1e-3;
    for mc in MCS {
        let j = Jacobi::new(mc).unwrap();
        let m = 1.0 - mc;
        for i in 0..40 {
            let u = -7.0 + 0.37 * i as f64;
            let f = |x: f64| j.sncndn(x);
            let d = |g: fn((f64, f64, f64)) -> f64| {
                (8.0 * (g(f(u + h)) - g(f(u - h))) - (g(f(u + 2.0 * h)) - g(f(u - 2.0 * h))))
                    / (12.0 * h)
            };
            let (sn, cn, dn) = f(u);
            let tol = 1e-10;
            assert!((d(|t| t.0) - cn * dn).abs() <= tol, "sn' at {u}, {mc}");
            assert!((d(|t| t.1) + sn * dn).abs() <= tol, "cn' at {u}, {mc}");
            assert!((d(|t| t.2) + m * sn * cn).abs() <= tol, "dn' at {u}, {mc}");
        }
    }
}

#[test]
fn complete_integral_published_and_asymptotic() {
    assert!((ellip_k(0.5).unwrap() - K_HALF).abs() <= 2.3e-16, "K(1/2)");
    assert!((ellip_k(0.49).unwrap() - K_051).abs() <= 2.3e-16, "K(0.51)");
    assert_eq!(ellip_k(1.0).unwrap(), core::f64::consts::FRAC_PI_2);
    assert_eq!(ellip_k(0.0).unwrap(), f64::INFINITY);
    // K = L + (m_c/4)(L − 1) + (9 m_c²/64)(L − 7/6) + O(m_c³ L), L = ln(4/√m_c) (A&S 17.3.26).
    for mc in [1e-6f64, 1e-9, 1e-12, 1e-15] {
        let l = (4.0 / mc.sqrt()).ln();
        let k = l + mc / 4.0 * (l - 1.0) + 9.0 * mc * mc / 64.0 * (l - 7.0 / 6.0);
        let e = (ellip_k(mc).unwrap() - k).abs() / k;
        assert!(e <= 2.3e-16, "K({mc}) relative error {e:e}");
    }
}

#[test]
fn closed_forms_at_quarter_and_half_period() {
    for mc in MCS.iter().copied().filter(|&m| m > 0.0) {
        let j = Jacobi::new(mc).unwrap();
        let kp = mc.sqrt();
        let (sn, cn, dn) = j.sncndn(j.k());
        assert!(
            (sn - 1.0).abs() <= 2.3e-16 && cn.abs() <= 1e-15,
            "at K, mc={mc}: {sn} {cn}"
        );
        assert!(
            (dn - kp).abs() <= 4e-16 * kp.max(1e-8),
            "dn(K) = {dn:e} vs √m_c = {kp:e}"
        );
        // sn(K/2) = 1/√(1+k'), cn(K/2) = √(k'/(1+k')), dn(K/2) = √k'.
        let (sn, cn, dn) = j.sncndn(0.5 * j.k());
        assert!(
            (sn - 1.0 / (1.0 + kp).sqrt()).abs() <= 4e-16,
            "sn(K/2), mc={mc}"
        );
        assert!(
            (cn - (kp / (1.0 + kp)).sqrt()).abs() <= 4e-16 * (1.0 + 1.0 / kp.sqrt()).min(1e3),
            "cn(K/2), mc={mc}"
        );
        assert!((dn - kp.sqrt()).abs() <= 4e-16, "dn(K/2), mc={mc}");
    }
}

#[test]
fn near_m_equal_one_series() {
    // A&S 16.15: first order in m_c about the hyperbolic limit; error O(m_c²).
    for mc in [1e-15f64, 1e-12] {
        let j = Jacobi::new(mc).unwrap();
        for u in [0.25f64, 0.5, 1.0, 2.0, 5.0] {
            let (sh, ch, th) = (u.sinh(), u.cosh(), u.tanh());
            let sech = 1.0 / ch;
            let s = th + mc / 4.0 * (sh * ch - u) * sech * sech;
            let c = sech - mc / 4.0 * (sh * ch - u) * th * sech;
            let d = sech + mc / 4.0 * (sh * ch + u) * th * sech;
            let (sn, cn, dn) = j.sncndn(u);
            assert!((sn - s).abs() <= 3e-16, "sn({u}|m_c={mc})");
            assert!(
                (cn - c).abs() <= 3e-16 * (1.0 + c.abs() * 4.0),
                "cn({u}|m_c={mc}): {cn:e} {c:e}"
            );
            assert!(
                (dn - d).abs() <= 3e-16 * (1.0 + d.abs() * 4.0),
                "dn({u}|m_c={mc})"
            );
        }
    }
}

#[test]
fn detest_b5_from_the_exact_solution() {
    let j = Jacobi::new(0.49).unwrap();
    for (t, y) in [(12.0, B5_Y12), (20.0, B5_Y20)] {
        let (sn, cn, dn) = j.sncndn(t);
        let e = (sn - y[0])
            .abs()
            .max((cn - y[1]).abs())
            .max((dn - y[2]).abs());
        eprintln!("exact B5 y({t}) error {e:e}");
        assert!(e <= 1e-14, "B5 at {t}: {e:e}");
    }
}

/// At t ≈ 10⁴ the phase must still be right to 1e-13: t = 20 + 4K n + δ with δ computed in
/// integer arithmetic from the 19-digit K, then y(t) = y(20) + δ y'(20).
#[test]
fn b5_phase_stays_exact_to_t_1e4() {
    const K_E18: i128 = 1_862_640_802_332_738_552;
    let j = Jacobi::new(0.49).unwrap();
    let mut worst = 0.0f64;
    for n in [1i128, 10, 100, 537, 1000, 1339] {
        let big = 4 * K_E18 * n; // 4Kn in units of 1e-18
        let t = 20.0 + big as f64 * 1e-18;
        let a = t - 20.0; // exact: both are multiples of ulp(t)
        let a_int = a.floor();
        let delta = (a_int - (big / 1_000_000_000_000_000_000) as f64) + (a - a_int)
            - (big % 1_000_000_000_000_000_000) as f64 * 1e-18;
        let (s, c, d) = (B5_Y20[0], B5_Y20[1], B5_Y20[2]);
        let reference = [
            s + delta * c * d,
            c - delta * s * d,
            d - delta * 0.51 * s * c,
        ];
        let (sn, cn, dn) = j.sncndn(t);
        let e = (sn - reference[0])
            .abs()
            .max((cn - reference[1]).abs())
            .max((dn - reference[2]).abs());
        worst = worst.max(e);
        assert!(e <= 1e-13, "t = {t}: error {e:e}, δ = {delta:e}");
    }
    eprintln!("B5 exact phase error up to t≈1e4: {worst:e}");
}

#[test]
fn carlson_and_incomplete_integrals() {
    // Carlson (1995) test values.
    assert!((rf(1.0, 2.0, 0.0).unwrap() - 1.311_028_777_146_059_9).abs() <= 3e-16);
    assert!((rf(2.0, 3.0, 4.0).unwrap() - 0.584_082_841_677_15).abs() <= 1e-14);
    assert!((rj(0.0, 1.0, 2.0, 3.0).unwrap() - 0.776_886_237_785_82).abs() <= 1e-14);
    assert!((rj(2.0, 3.0, 4.0, 5.0).unwrap() - 0.142_975_796_671_57).abs() <= 1e-14);
    // F(π/2 | m) = K, F inverts sn.
    for mc in [0.9, 0.49, 1e-6, 1e-15] {
        let k = ellip_k(mc).unwrap();
        // The double nearest π/2 lies 6e-17 below it, where F' = 1/√m_c.
        let slack = 6.2e-17 / mc.sqrt();
        let f = ellip_f(core::f64::consts::FRAC_PI_2, mc).unwrap();
        assert!(
            (f - k).abs() <= 4e-16 * k + slack,
            "F(π/2) = {f} vs K = {k}, mc={mc}"
        );
        let j = Jacobi::new(mc).unwrap();
        for u in [0.1, 0.7, 1.3, 0.9 * k, 1.5 * k, -1.7 * k] {
            let (sn, cn, _) = j.sncndn(u);
            let back = ellip_f_sc(sn, cn, mc).unwrap();
            assert!(
                (back - u).abs() <= 1e-14 * k,
                "F(am(u)) = {back} vs {u}, mc={mc}"
            );
        }
    }
    // Π(n; φ|0) = atan(√(1−n) tan φ)/√(1−n) for n < 1.
    let (n, phi) = (0.3f64, 1.1f64);
    let s = (1.0 - n).sqrt();
    let closed = (s * phi.tan()).atan() / s;
    assert!((ellip_pi(n, phi, 1.0).unwrap() - closed).abs() <= 1e-15);
    // and with m = 1 (m_c = 0): n < 0 keeps the integrand bounded.
    assert!(ellip_pi(-0.5, 0.8, 0.0).is_ok());
}

#[test]
fn bad_parameters_are_typed_errors() {
    assert_eq!(
        Jacobi::new(-1e-3),
        Err(ExactError::ParameterOutOfRange { mc: -1e-3 })
    );
    assert!(matches!(
        Jacobi::new(f64::NAN),
        Err(ExactError::ParameterOutOfRange { .. })
    ));
    assert!(matches!(
        sncndn(f64::INFINITY, 0.5),
        Err(ExactError::NonFinite { .. })
    ));
    assert!(matches!(
        rf(-1.0, 1.0, 1.0),
        Err(ExactError::CarlsonDomain { .. })
    ));
    assert!(matches!(
        ellip_pi(2.0, 1.0, 0.5),
        Err(ExactError::CarlsonDomain { .. })
    ));
}

mod properties {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]

        /// Identities for log-uniform m_c in [1e-15, 1] and |u| ≤ 1000, and the addition
        /// of a real period 4K leaves sn, cn, dn unchanged.
        #[test]
        fn identities_and_periodicity(log_mc in -15.0f64..0.0, u in -1000.0f64..1000.0) {
            let mc = 10f64.powf(log_mc);
            let j = Jacobi::new(mc).unwrap();
            let (sn, cn, dn) = j.sncndn(u);
            prop_assert!((sn * sn + cn * cn - 1.0).abs() <= 6e-16);
            prop_assert!((dn * dn + (1.0 - mc) * sn * sn - 1.0).abs() <= 6e-16);
            prop_assert!(dn >= mc.sqrt() * (1.0 - 1e-12) && dn <= 1.0 + 1e-16);
            let (s2, c2, d2) = j.sncndn_dd(j.k_dd() * precess_core::exact::Dd::from(4.0) + precess_core::exact::Dd::from(u));
            let tol = 1e-15 * (1.0 + u.abs());
            prop_assert!((s2 - sn).abs() <= tol && (c2 - cn).abs() <= tol && (d2 - dn).abs() <= tol);
        }
    }
}
