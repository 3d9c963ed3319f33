//! Exact numbers from decimal text and from `f64`.

use super::arena::{Arena, ExprId};
use super::error::SymError;
use super::rational::Rational;

/// Parses a Rust-style decimal literal exactly: `0.03` is 3/100, `1.5e-3` is 3/2000.
///
/// Accepts digits with `_` separators, an optional fraction, an optional exponent, an optional
/// `f64`/`f32` suffix and a leading `-`.
///
/// # Errors
/// [`SymError::InvalidLiteral`] for text that is not such a number;
/// [`SymError::LiteralOutOfRange`] when the exact value does not fit 128-bit rationals.
///
/// ```
/// use precess_core::sym::{parse_decimal, Rational};
/// assert_eq!(parse_decimal("0.03").unwrap(), Rational::new(3, 100).unwrap());
/// assert!(parse_decimal("1e400").is_err());
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
    let mut exp10: i64 = match exponent {
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
    let mut num: i128 = 0;
    for c in int_part.chars().chain(frac_part.chars()) {
        let d = c as i128 - '0' as i128;
        num = num
            .checked_mul(10)
            .and_then(|n| n.checked_add(d))
            .ok_or_else(out_of_range)?;
    }
    exp10 -= frac_part.len() as i64;
    if num == 0 {
        return Ok(Rational::ZERO);
    }
    let ten = Rational::integer(10);
    let scale = ten.checked_pow(exp10).ok_or_else(out_of_range)?;
    let value = Rational::new(num, 1)
        .and_then(|n| n.checked_mul(scale))
        .ok_or_else(out_of_range)?;
    Ok(if negative { -value } else { value })
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
    /// # Errors
    /// [`SymError::NonFinite`] for NaN or ±∞; [`SymError::LiteralOutOfRange`] if the exact
    /// dyadic value needs more than 128 bits.
    pub fn float(&mut self, x: f64) -> Result<ExprId, SymError> {
        if !x.is_finite() {
            return Err(SymError::NonFinite { value: x });
        }
        let r = Rational::from_f64(x).ok_or_else(|| SymError::LiteralOutOfRange {
            literal: format!("{x:e}"),
        })?;
        Ok(self.constant(r))
    }
}
