//! The double-double functions against values computed to 300 bits with mpmath (quoted as
//! the double nearest the value and the double nearest the remainder) and against exact
//! identities.

use super::*;

/// |got − (hi + lo)| in units of the value, through double-double subtraction.
fn rel(got: Dd, hi: f64, lo: f64) -> f64 {
    ((got - Dd { hi, lo }).to_f64() / hi).abs()
}

#[test]
fn sine_and_cosine_match_mpmath() {
    // (x, sin x, cos x) with sin and cos as (hi, lo).
    type Case = (f64, (f64, f64), (f64, f64));
    let cases: [Case; 3] = [
        (
            1.0,
            (0.8414709848078965, 1.776845092935536e-18),
            (0.5403023058681398, -4.760954612604417e-17),
        ),
        (
            100.0,
            (-0.5063656411097588, -3.050947053792115e-18),
            (0.8623188722876839, 4.334809858136501e-17),
        ),
        (
            -7.5,
            (-0.9379999767747389, 3.928541021503273e-17),
            (f64::NAN, 0.0),
        ),
    ];
    for (x, (sh, sl), (ch, cl)) in cases {
        let (s, c) = Dd::from(x).sin_cos();
        assert!(rel(s, sh, sl) < 4e-32, "sin {x}: {:e}", rel(s, sh, sl));
        if !ch.is_nan() {
            assert!(rel(c, ch, cl) < 4e-32, "cos {x}: {:e}", rel(c, ch, cl));
        }
    }
    // 10⁶ rad: the reduction by π/2 in three doubles keeps every digit.
    let (s, _) = Dd::from(1e6).sin_cos();
    let e = rel(s, -0.34999350217129294, -1.5952848809323968e-17);
    assert!(e < 1e-31, "sin 1e6: {e:e}");
}

#[test]
fn sine_and_cosine_satisfy_the_identities() {
    let pi = Dd {
        hi: std::f64::consts::PI,
        lo: 1.2246467991473532e-16,
    };
    let (s6, c6) = pi.div_f64(6.0).sin_cos();
    assert!((s6 - Dd::from(0.5)).to_f64().abs() < 2e-32);
    let (_, c3) = pi.div_f64(3.0).sin_cos();
    assert!((c3 - Dd::from(0.5)).to_f64().abs() < 2e-32);
    // cos(π/6) = √3/2.
    assert!((c6 - Dd::from(3.0).sqrt().div_f64(2.0)).to_f64().abs() < 4e-32);
    // sin² + cos² = 1 over a spread of arguments, every quadrant and sign.
    for i in -400..400 {
        let x = Dd::from(i as f64 * 0.0371) + Dd::from(1e-19 * i as f64);
        let (s, c) = x.sin_cos();
        let one = Dd::dot([(s, s), (c, c)]) - Dd::from(1.0);
        assert!(
            one.to_f64().abs() < 2e-31,
            "x = {}: {:e}",
            x.hi,
            one.to_f64()
        );
        // And the double functions agree to an ulp.
        assert!((s.to_f64() - x.hi.sin()).abs() < 3e-16);
    }
}

#[test]
fn exponential_and_logarithm_match_mpmath() {
    let e = Dd::from(1.0).exp();
    assert!(rel(e, std::f64::consts::E, 1.4456468917292502e-16) < 1e-31);
    let small = Dd::from(-20.25).exp();
    assert!(rel(small, 1.6052280551856116e-09, -3.657643988865463e-26) < 1e-31);
    let l = Dd::from(10.0).ln();
    assert!(rel(l, std::f64::consts::LN_10, -2.1707562233822494e-16) < 1e-31);
    assert_eq!(Dd::from(0.0).ln().hi, f64::NEG_INFINITY);
    assert!(Dd::from(-1.0).ln().hi.is_nan());
    assert_eq!(Dd::from(800.0).exp().hi, f64::INFINITY);
}

#[test]
fn real_powers_match_mpmath() {
    // Rational exponents, taken as the rational the double rounds.
    let cases = [
        (2.0, 1.0 / 3.0, 1.2599210498948732, -2.589933375300507e-17),
        (10.0, 1.5, 31.622776601683793, 7.566535620287155e-16),
        (3.0, 0.1, 1.1161231740339044, 5.94627166270108e-17),
        (0.7, -5.0 / 7.0, 1.2901620325312395, 6.36879639330826e-17),
        (1e-3, -2.5, 31622776.60168379, -5.254187441096229e-11),
        // Not a rational with a small denominator: exp(r ln x).
        (
            2.5,
            0.123456789123,
            1.1197688853645502,
            7.233279261080663e-17,
        ),
    ];
    for (x, r, hi, lo) in cases {
        let got = Dd::from(x).powf(r);
        assert!(rel(got, hi, lo) < 2e-31, "{x}^{r}: {:e}", rel(got, hi, lo));
    }
    assert_eq!(rational(1.5), Some((3, 2)));
    assert_eq!(rational(-5.0 / 7.0), Some((-5, 7)));
    assert_eq!(rational(0.123456789123), None);
    assert!(Dd::from(-2.0).powf(0.5).hi.is_nan());
    assert_eq!(Dd::from(0.0).powf(1.5).hi, 0.0);
}
