//! Exact power-of-two scaling over the whole f64 range, subnormals included: what keeps the
//! squares and products of the exact solutions from overflowing or underflowing.

/// The exponent e with 2ᵉ ≤ |x| < 2ᵉ⁺¹, for finite non-zero x (subnormals included).
pub(crate) fn exponent(x: f64) -> i32 {
    let bits = x.abs().to_bits();
    let biased = (bits >> 52) as i32;
    if biased == 0 {
        let mantissa = bits & ((1u64 << 52) - 1);
        -1074 + (63 - mantissa.leading_zeros() as i32)
    } else {
        biased - 1023
    }
}

/// 2ᵉ for e ∈ [−1074, 1023].
pub(crate) fn pow2(e: i32) -> f64 {
    let e = e.clamp(-1074, 1023);
    if e >= -1022 {
        f64::from_bits(((e + 1023) as u64) << 52)
    } else {
        f64::from_bits(1u64 << (e + 1074))
    }
}

/// x · 2ᵉ for any e, in steps that cannot overflow or underflow before the last one.
pub(crate) fn ldexp(mut x: f64, mut e: i32) -> f64 {
    while e > 1000 {
        x *= pow2(1000);
        e -= 1000;
    }
    while e < -1000 {
        x *= pow2(-1000);
        e += 1000;
    }
    x * pow2(e)
}

/// The power of two at or below the largest magnitude in `v` (1 if all are zero): dividing
/// by it is exact and brings the largest into [1, 2).
pub(crate) fn pow2_scale(v: &[f64]) -> f64 {
    let mx = v.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    if mx > 0.0 && mx.is_finite() {
        pow2(exponent(mx))
    } else {
        1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exponents_and_powers_cover_subnormals() {
        for (x, e) in [
            (1.0, 0),
            (1.5, 0),
            (0.75, -1),
            (f64::MAX, 1023),
            (f64::MIN_POSITIVE, -1022),
            (5e-324, -1074),
            (3.0 * 5e-324, -1073),
        ] {
            assert_eq!(exponent(x), e, "{x:e}");
            assert_eq!(exponent(-x), e);
            assert!(pow2(e) <= x && x < 2.0 * pow2(e), "{x:e}");
        }
        assert_eq!(pow2_scale(&[1e-320, -3e-321, 0.0]), pow2(exponent(1e-320)));
        assert_eq!(pow2_scale(&[0.0, 0.0]), 1.0);
        assert_eq!(ldexp(1.5, -1100), 0.0);
        assert_eq!(ldexp(1.0, -1074), 5e-324);
        assert_eq!(ldexp(pow2(-1074), 2000), pow2(926));
    }
}
