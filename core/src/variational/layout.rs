//! Where x, Φ and S sit in the flat augmented state.
//!
//! The state is `(x, Φ, S)`: first the n entries of x, then the m tangent vectors (the
//! columns of Φ, n × m), then the k sensitivities ∂x/∂p_j (the columns of S, n × k). Both
//! matrices are stored column by column — column-major — so each tangent vector and each
//! sensitivity is one contiguous slice: the re-orthonormalisation of Benettin's method works
//! on columns, and a user reading ∂x/∂p_j takes one slice.

use nalgebra::DMatrix;

use super::error::VariationalError;

/// The sizes of an augmented state: n state entries, m tangent vectors, k parameters.
///
/// ```
/// use precess_core::variational::Layout;
/// let layout = Layout { n: 2, tangents: 2, sensitivities: 1 };
/// assert_eq!(layout.len(), 2 + 4 + 2);
/// assert_eq!(layout.tangent(1), 4..6);     // Φ[:, 1]
/// assert_eq!(layout.sensitivity(0), 6..8); // ∂x/∂p₀
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Layout {
    /// Entries of the state x.
    pub n: usize,
    /// Tangent vectors m (columns of Φ); n for the full state transition matrix.
    pub tangents: usize,
    /// Parameters k whose sensitivities are carried.
    pub sensitivities: usize,
}

impl Layout {
    /// n + n·m + n·k, the length of the augmented state.
    pub fn len(&self) -> usize {
        // Saturating: a layout built by hand with absurd sizes is refused by the size
        // checks rather than overflowing.
        self.n.saturating_mul(
            self.tangents
                .saturating_add(self.sensitivities)
                .saturating_add(1),
        )
    }

    /// `true` only for an empty state.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The range of tangent vector `j` (column j of Φ) in the augmented state.
    pub fn tangent(&self, j: usize) -> core::ops::Range<usize> {
        let start = self.n.saturating_mul(j.saturating_add(1));
        start..start.saturating_add(self.n)
    }

    /// The range of ∂x/∂p_j (column j of S) in the augmented state.
    pub fn sensitivity(&self, j: usize) -> core::ops::Range<usize> {
        let start = self
            .n
            .saturating_mul(self.tangents.saturating_add(j).saturating_add(1));
        start..start.saturating_add(self.n)
    }

    /// Refuses a layout built by hand with more tangent vectors than state entries: n + 1
    /// vectors of ℝⁿ cannot be independent, and the (n + 1)-th column of "the identity"
    /// does not exist.
    ///
    /// # Errors
    /// [`VariationalError::TooManyTangents`].
    pub fn validate(&self) -> Result<(), VariationalError> {
        if self.tangents > self.n {
            return Err(VariationalError::TooManyTangents {
                tangents: self.tangents,
                state: self.n,
            });
        }
        Ok(())
    }

    /// Refuses a const-generic size that is not [`Layout::len`].
    ///
    /// # Errors
    /// [`VariationalError::SizeMismatch`].
    pub fn check_size(&self, got: usize) -> Result<(), VariationalError> {
        if got == self.len() {
            Ok(())
        } else {
            Err(VariationalError::SizeMismatch {
                expected: self.len(),
                got,
            })
        }
    }

    /// The augmented state at the start: x₀, Φ = the first m columns of the identity, S = 0.
    ///
    /// # Errors
    /// [`VariationalError::TooManyTangents`] past n ([`Layout::validate`]),
    /// [`VariationalError::SizeMismatch`] if `N` is not [`Layout::len`],
    /// [`VariationalError::InitialStateLength`] if `x0` is not n long,
    /// [`VariationalError::NonFinite`] for a NaN or infinite entry of `x0`.
    pub fn initial_state<const N: usize>(&self, x0: &[f64]) -> Result<[f64; N], VariationalError> {
        self.validate()?;
        self.check_size(N)?;
        if x0.len() != self.n {
            return Err(VariationalError::InitialStateLength {
                expected: self.n,
                got: x0.len(),
            });
        }
        check_finite(x0)?;
        let mut y = [0.0; N];
        y[..self.n].copy_from_slice(x0);
        for j in 0..self.tangents {
            y[self.tangent(j).start + j] = 1.0;
        }
        Ok(y)
    }

    /// Φ (n × m) read from an augmented state `y` (at least [`Layout::len`] long; a shorter
    /// one reads zeros where it ends).
    pub fn transition(&self, y: &[f64]) -> DMatrix<f64> {
        DMatrix::from_fn(self.n, self.tangents, |i, j| {
            y.get(self.tangent(j).start + i).copied().unwrap_or(0.0)
        })
    }

    /// S = ∂x/∂p (n × k) read from an augmented state `y`.
    pub fn sensitivities(&self, y: &[f64]) -> DMatrix<f64> {
        DMatrix::from_fn(self.n, self.sensitivities, |i, j| {
            y.get(self.sensitivity(j).start + i).copied().unwrap_or(0.0)
        })
    }
}

/// Refuses NaN and ±∞ in `values`.
///
/// # Errors
/// [`VariationalError::NonFinite`] naming the first.
pub(crate) fn check_finite(values: &[f64]) -> Result<(), VariationalError> {
    match values.iter().position(|v| !v.is_finite()) {
        Some(index) => Err(VariationalError::NonFinite {
            index,
            value: values[index],
        }),
        None => Ok(()),
    }
}
