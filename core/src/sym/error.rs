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
}
