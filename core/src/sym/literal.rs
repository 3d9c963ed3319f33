//! Exact numbers from decimal text and from `f64`.

use super::arena::{Arena, ExprId};
use super::error::SymError;
use super::rational::Rational;

/// Parses a Rust-style decimal literal exactly: `0.03` is 3/100, `1.5e-3` is 3/2000, and
/// `1.989e30` or `1e-300` are exact too (see [`Rational`] for how magnitudes are held).
///
/// Accepts digits with `_` separators, an optional fraction, an optional exponent, an optional
/// `f64`/`f32` suffix and a leading `-`. The value is exact; [`Rational::to_f64`] then gives
/// the `f64` the same literal denotes in Rust (rounded once), or ±∞ where Rust's literal
/// would overflow.
///
/// # Errors
/// [`SymError::InvalidLiteral`] for text that is not such a number;
/// [`SymError::LiteralOutOfRange`] for more than 38 significant digits, or a decimal exponent
/// beyond about ±4000 (far outside f64's range either way).
///
/// ```
/// use precess_core::sym::{parse_decimal, Rational};
/// assert_eq!(parse_decimal("0.03").unwrap(), Rational::new(3, 100).unwrap());
/// assert_eq!(parse_decimal("1.989e30").unwrap().to_f64(), 1.989e30);
/// assert_eq!(parse_decimal("1e400").unwrap().to_f64(), f64::INFINITY);
/// assert!(parse_decimal("1e99999").is_err());
/// ```
pub fn parse_decimal(text: &str) -> Result<Rational, SymError> {
    let invalid = || SymError::InvalidLiteral {
        literal: text.to_owned(),
    };
    let out_of_range = || SymError::LiteralOutOfRange {
        literal: text.to_owned(),
    };
    let cleaned: String = text.chars().filter(|&c| c != '_').collect();
    let body = cleaned
        .strip_suffix("f64")
        .or_else(|| cleaned.strip_suffix("f32"))
        .unwrap_or(&cleaned);
    let (negative, body) = match body.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, body),
    };
    let (mantissa, exponent) = match body.find(['e', 'E']) {
        Some(i) => (&body[..i], Some(&body[i + 1..])),
        None => (body, None),
    };
    let (int_part, frac_part) = match mantissa.split_once('.') {
        Some((i, f)) => (i, f),
        None => (mantissa, ""),
    };
    let digits_ok = |s: &str| s.chars().all(|c| c.is_ascii_digit());
    if int_part.is_empty() || !digits_ok(int_part) || !digits_ok(frac_part) {
        return Err(invalid());
    }
    let exp10: i64 = match exponent {
        None => 0,
        Some(e) => {
            let (sign, digits) = match e.strip_prefix('-') {
                Some(d) => (-1, d),
                None => (1, e.strip_prefix('+').unwrap_or(e)),
            };
            if digits.is_empty() || !digits_ok(digits) {
                return Err(invalid());
            }
            // More than 18 digits of exponent is out of range for any rational we hold.
            sign * digits.parse::<i64>().map_err(|_| out_of_range())?
        }
    };
    // The significant digits: leading zeros say nothing, trailing ones go to the exponent.
    let all = format!("{int_part}{frac_part}");
    let significant = all.trim_start_matches('0').trim_end_matches('0');
    if significant.is_empty() {
        return Ok(Rational::ZERO);
    }
    let trailing = all.len() - all.trim_end_matches('0').len();
    let mut num: u128 = 0;
    for c in significant.chars() {
        let d = u128::from(c as u8 - b'0');
        num = num
            .checked_mul(10)
            .and_then(|n| n.checked_add(d))
            .ok_or_else(out_of_range)?;
    }
    let exp10 = exp10
        .checked_sub(frac_part.len() as i64)
        .and_then(|e| e.checked_add(trailing as i64))
        .ok_or_else(out_of_range)?;
    Rational::from_decimal(negative, num, exp10).ok_or_else(out_of_range)
}

impl Arena {
    /// The exact constant a decimal literal denotes (see [`parse_decimal`]).
    ///
    /// # Errors
    /// As [`parse_decimal`].
    pub fn number(&mut self, text: &str) -> Result<ExprId, SymError> {
        let r = parse_decimal(text)?;
        Ok(self.constant(r))
    }

    /// The exact binary value of a finite `f64` as a constant.
    ///
    /// Every finite `f64`, subnormals included, is held exactly.
    ///
    /// # Errors
    /// [`SymError::NonFinite`] for NaN or ±∞.
    pub fn float(&mut self, x: f64) -> Result<ExprId, SymError> {
        let r = Rational::from_f64(x).ok_or(SymError::NonFinite { value: x })?;
        Ok(self.constant(r))
    }
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;

    /// Rust's own reading of the literal, the reference: rustc parses float literals to
    /// the correctly rounded value.
    fn rust(text: &str) -> f64 {
        text.replace('_', "").parse::<f64>().unwrap_or(f64::NAN)
    }

    fn ours(text: &str) -> f64 {
        parse_decimal(text).map_or(f64::NAN, Rational::to_f64)
    }

    #[test]
    fn rounds_like_rust_at_the_edges() {
        let cases = [
            // The literal of issue 9, 1 ulp off when rounded twice.
            "0.63886388081737347487",
            // Halfway between 2⁵³ and 2⁵³ + 2, and between 2⁵³ + 2 and 2⁵³ + 4: ties to even.
            "9007199254740993",
            "9007199254740995",
            "9007199254740993.0000000000000000001",
            // Around the smallest normal, and the subnormal range.
            "2.2250738585072011e-308",
            "2.2250738585072012e-308",
            "2.2250738585072014e-308",
            "4.9406564584124654e-324",
            "1e-310",
            "1.5e-323",
            // Just below and just above half the smallest subnormal (the exact tie is a
            // 751-digit literal; `magnitude` tests it).
            "2.4703282292062327e-324",
            "2.4703282292062328e-324",
            "2.47e-324",
            // The largest finite, the last literal that rounds to it, and the first to ∞.
            "1.7976931348623157e308",
            "1.7976931348623158e308",
            "1.7976931348623159e308",
            "1e309",
            "-1.5e-5",
            "1_000.000_1",
        ];
        for text in cases {
            let (want, got) = (rust(text), ours(text));
            assert_eq!(got.to_bits(), want.to_bits(), "{text}: {got:e} vs {want:e}");
        }
    }

    #[test]
    fn out_of_range_is_reported_not_wrapped() {
        // 40 significant digits, and an exponent far beyond any f64.
        let long = "1.234567890123456789012345678901234567890001";
        assert!(matches!(
            parse_decimal(long),
            Err(SymError::LiteralOutOfRange { .. })
        ));
        assert!(matches!(
            parse_decimal("1e5000"),
            Err(SymError::LiteralOutOfRange { .. })
        ));
        assert!(matches!(
            parse_decimal("1e-99999999999999999999"),
            Err(SymError::LiteralOutOfRange { .. })
        ));
        // Trailing zeros are not significant: 40 digits, but 1e39.
        assert_eq!(ours("1000000000000000000000000000000000000000"), 1e39);
        assert!(matches!(
            parse_decimal("1.2.3"),
            Err(SymError::InvalidLiteral { .. })
        ));
        // An exact zero has no sign (Rust's `-0.0` is the negation of the literal `0.0`).
        assert_eq!(parse_decimal("-0.000e-5"), Ok(Rational::ZERO));
    }

    /// A decimal literal of 1–25 significant digits with the point anywhere in them and an
    /// exponent from below the subnormals to beyond the largest finite f64.
    fn literal() -> impl Strategy<Value = String> {
        (
            1usize..=25,
            any::<u128>(),
            any::<usize>(),
            -350i64..=315,
            any::<bool>(),
        )
            .prop_map(|(len, bits, point, exp, negative)| {
                // `len` digits, the first nonzero: exactly `len` significant ones (bar
                // trailing zeros).
                let lead = (bits % 9 + 1).to_string();
                let rest = format!("{:024}", (bits / 9) % 10u128.pow(24));
                let digits = format!("{lead}{}", &rest[25 - len..]);
                let point = point % (len + 1);
                let int = if point == 0 { "0" } else { &digits[..point] };
                let sign = if negative { "-" } else { "" };
                format!("{sign}{int}.{}e{exp}", &digits[point..])
            })
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 100_000, failure_persistence: None, ..ProptestConfig::default() })]

        /// 10⁵ random literals over the whole range agree with Rust to the bit.
        #[test]
        fn every_literal_rounds_like_rust(text in literal()) {
            prop_assert_eq!(ours(&text).to_bits(), rust(&text).to_bits(), "{}", text);
        }
    }
}
