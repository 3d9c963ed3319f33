//! Errors of the symbolic engine.

use thiserror::Error;

/// What can go wrong when building or transforming an expression.
///
/// Every variant carries what a user needs to find the cause; none is a bug report.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SymError {
    /// The divisor simplifies to zero, so the quotient has no value anywhere.
    #[error("division by an expression that is identically zero: {divisor}")]
    DivisionByZero {
        /// The divisor as written (before it simplified to zero).
        divisor: String,
    },
    /// `0^n` with a negative `n`.
    #[error("zero raised to the negative power {exponent}")]
    ZeroToNegativePower {
        /// The exponent.
        exponent: i64,
    },
    /// The square root of a negative constant.
    #[error("square root of the negative constant {value}")]
    SqrtOfNegative {
        /// The constant under the root.
        value: f64,
    },
    /// A floating-point value that is NaN or infinite.
    #[error("non-finite number {value}: only finite values are allowed")]
    NonFinite {
        /// The offending value.
        value: f64,
    },
    /// A literal that is not a decimal number.
    #[error(
        "`{literal}` is not a decimal number (expected digits, an optional point and exponent)"
    )]
    InvalidLiteral {
        /// The text that failed to parse.
        literal: String,
    },
    /// A literal the engine cannot hold exactly: more than 38 significant digits, or a
    /// decimal exponent beyond about ±4000 (far outside the range of f64).
    #[error(
        "`{literal}` is out of range: at most 38 significant digits and a decimal exponent within about ±4000"
    )]
    LiteralOutOfRange {
        /// The text of the literal.
        literal: String,
    },
    /// An exponent whose product overflowed while powers were combined.
    #[error("integer exponent overflow combining {a} and {b}")]
    ExponentOverflow {
        /// First exponent.
        a: i64,
        /// Second exponent.
        b: i64,
    },
    /// An id made by another arena (or by a clone after the copy was taken).
    #[error("expression id {index} belongs to another arena")]
    ForeignExpression {
        /// The id's position in the arena that made it.
        index: usize,
    },
    /// An expansion that would pass the engine's term limit.
    #[error("expanding would produce about {terms} terms, past the limit of {limit}")]
    ExpansionTooLarge {
        /// The number of terms the expansion would have (saturated at `usize::MAX`).
        terms: usize,
        /// The limit, [`MAX_EXPANDED_TERMS`](super::MAX_EXPANDED_TERMS).
        limit: usize,
    },
    /// An abbreviation whose definition depends on time or a coordinate.
    #[error("the abbreviation `{name}` would depend on `{symbol}`, which changes in time")]
    TimeDependentAbbreviation {
        /// The abbreviation's name.
        name: String,
        /// The time-dependent symbol in its definition.
        symbol: String,
    },
    /// A power too large to compute with (an exponent past what fits in memory).
    #[error("the power {exponent} of `{base}` is too large to {operation}")]
    PowerTooLarge {
        /// The base as text.
        base: String,
        /// The exponent.
        exponent: i64,
        /// What could not be done with it.
        operation: &'static str,
    },
    /// A real power `x^r` the engine cannot give a value: a non-integer power of a negative
    /// constant (`x^r` with a non-integer `r` is taken of a positive base), a negative power of
    /// zero, or an integer exponent past `i64`.
    #[error("the power {exponent} of the constant {base} is undefined")]
    RealPowerUndefined {
        /// The base as text.
        base: String,
        /// The exponent as text.
        exponent: String,
    },
}
