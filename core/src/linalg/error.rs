//! Typed errors of the dense linear algebra.

use thiserror::Error;

/// Why a matrix routine could not give an answer.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum LinalgError {
    /// The matrix is not square.
    #[error("the matrix is {rows}×{cols}; eigenvalues and linear systems need a square matrix")]
    NotSquare {
        /// Its rows.
        rows: usize,
        /// Its columns.
        cols: usize,
    },
    /// An entry of the matrix (or of the state a Jacobian is taken at) is NaN or ±∞.
    #[error("non-finite {quantity} at index ({row}, {col}): {value}")]
    NonFinite {
        /// What holds the value: the matrix, the state, the right-hand side, the Jacobian.
        quantity: &'static str,
        /// Its row (the component for a vector).
        row: usize,
        /// Its column (0 for a vector).
        col: usize,
        /// The value.
        value: f64,
    },
    /// The QR iteration did not deflate within its cap (never seen on a finite matrix; the
    /// cap exists so the routine always returns).
    #[error(
        "the QR iteration did not converge within {iterations} iterations; \
         {unconverged} eigenvalues were left"
    )]
    NoConvergence {
        /// Iterations spent.
        iterations: usize,
        /// Eigenvalues still not found.
        unconverged: usize,
    },
    /// A tolerance or step must be finite and positive.
    #[error("{name} = {value} must be finite and > 0")]
    InvalidParameter {
        /// Which parameter.
        name: &'static str,
        /// Its value.
        value: f64,
    },
}

/// Rejects a non-finite entry, naming where it is.
pub(crate) fn check_finite(
    quantity: &'static str,
    rows: usize,
    entry: impl Fn(usize, usize) -> f64,
    cols: usize,
) -> Result<(), LinalgError> {
    for row in 0..rows {
        for col in 0..cols {
            let value = entry(row, col);
            if !value.is_finite() {
                return Err(LinalgError::NonFinite {
                    quantity,
                    row,
                    col,
                    value,
                });
            }
        }
    }
    Ok(())
}
