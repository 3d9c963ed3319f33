//! The exact free-body solution at subnormal and tiny moments of inertia. A motion whose
//! rate fits in f64 is computed by exact power-of-two scaling: it must equal the same body
//! at unit scale with time and momentum scaled by the same powers of two (the equations
//! ṁ = m × I⁻¹m are invariant under m → 2ᵃm, I → 2ᵇI, t → 2ᵇ⁻ᵃt). A motion whose rate
//! |m|/I overflows is a typed error naming the inertia, where it was
//! `ArgumentTooLarge { u: NaN }` at the first evaluation.

use precess_core::exact::{ExactError, FreeBodyExact};
use proptest::prelude::*;

/// 2ᵉ, exactly, for e in the normal range.
fn pow2(e: i32) -> f64 {
    2f64.powi(e)
}

/// A body with moments and momentum of few significant bits, so that they stay exact when
/// scaled into the subnormal range.
const I: [f64; 3] = [2.0, 1.0, 0.75];
const M0: [f64; 3] = [0.375, 0.25, 0.875];

/// m(t) of the body scaled by I → 2^b I, m → 2^a m, against the unit body at t·2^(a−b).
fn scaled_against_unit(a: i32, b: i32, t: f64) {
    let unit = FreeBodyExact::new(I, M0).unwrap();
    // 2^b I in two exact steps, as 2^b alone is below the normal range.
    let inertia = I.map(|v| v * pow2(b / 2) * pow2(b - b / 2));
    let m0 = M0.map(|v| v * pow2(a / 2) * pow2(a - a / 2));
    let tiny = FreeBodyExact::new(inertia, m0).unwrap();
    let m = tiny.m_at(t).unwrap();
    let expected = unit.m_at(t * pow2(a - b)).unwrap();
    // A result in the subnormal range holds only the bits above 2⁻¹⁰⁷⁴: two of those, in
    // unit scale, on top of the solution's own 1e-14.
    let grid =
        2.0 * pow2((-1074 - a).min(0) / 2) * pow2((-1074 - a).min(0) - (-1074 - a).min(0) / 2);
    for k in 0..3 {
        let back = m[k] * pow2(-a / 2) * pow2(-(a - a / 2));
        assert!(
            (back - expected[k]).abs() <= 1e-14 + grid,
            "a = {a}, b = {b}, t = {t}: m[{k}] = {back} against {}",
            expected[k]
        );
    }
    assert_eq!(tiny.lambda(), unit.lambda() * pow2(a - b));
}

#[test]
fn subnormal_moments_with_a_rate_in_range_are_solved_by_scaling() {
    // Moments of 2⁻¹⁰⁴⁰ ≈ 1e-313 (subnormal) and |m| of 2⁻⁶⁰: λ ≈ 2⁹⁸⁰ ≈ 1e295.
    scaled_against_unit(-60, -1040, 3.0 * pow2(-980));
    // Both subnormal and alike: λ as at unit scale.
    scaled_against_unit(-1040, -1040, 3.0);
    // The smallest moments: 2⁻¹⁰⁷² (four ulps of the subnormals).
    scaled_against_unit(-100, -1072, 0.7 * pow2(-972));
}

#[test]
fn a_rate_beyond_f64_is_refused_by_name() {
    // |m| ≈ 1 about moments of 1e-310: λ ≈ 1e310.
    let inertia = [2e-310, 1e-310, 0.75e-310];
    let m0 = [1.1f64.cos(), 0.0, 1.1f64.sin()];
    let err = FreeBodyExact::new(inertia, m0).unwrap_err();
    assert_eq!(err, ExactError::RateOverflow { inertia, m0 });
    let message = err.to_string();
    assert!(
        message.contains("2e-310") && message.contains("too small"),
        "{message}"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Any powers of two that keep the rate in range: the scaled body moves as the unit one.
    #[test]
    fn scaling_by_powers_of_two_is_exact(
        b in -1072i32..-900,
        shift in -1000i32..1000,
        t in 0.0f64..20.0,
    ) {
        // a − b, the exponent of λ, stays within ±1000; a itself within the normal range
        // so that m0 stays exact.
        let a = (b + shift).clamp(-1000, 1000);
        scaled_against_unit(a, b, t * pow2(b - a));
    }
}
