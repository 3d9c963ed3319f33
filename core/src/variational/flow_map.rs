//! The linearised flow map: Φ(t) carries a small uncertainty of x₀ to x(t), so a Gaussian
//! with covariance P₀ becomes, to first order, one with covariance Φ P₀ Φᵀ.

use nalgebra::DMatrix;

use super::error::VariationalError;
use super::layout::{Layout, check_finite};

/// The linearised flow map x₀ + δx₀ ↦ x(t) + Φ(t) δx₀ of one run, read from its augmented
/// state at t.
///
/// ```
/// use nalgebra::DMatrix;
/// use precess_core::variational::{FlowMap, Layout};
/// // x' = A x with A = [[0, 1], [0, 0]]: Φ(t) = [[1, t], [0, 1]], stored column-major.
/// let layout = Layout { n: 2, tangents: 2, sensitivities: 0 };
/// let t = 2.0;
/// let y = [0.0, 0.0, 1.0, 0.0, t, 1.0];
/// let map = FlowMap::new(layout, &y)?;
/// let p0 = DMatrix::from_row_slice(2, 2, &[0.0, 0.0, 0.0, 1.0]); // velocity uncertain
/// let p = map.covariance(&p0)?;
/// assert_eq!(p[(0, 0)], t * t); // the position's variance grows as t²
/// # Ok::<(), precess_core::variational::VariationalError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct FlowMap {
    /// x(t).
    pub state: Vec<f64>,
    /// Φ(t) = ∂x(t)/∂x₀.
    pub transition: DMatrix<f64>,
}

impl FlowMap {
    /// Reads x and Φ from the augmented state `y` laid out as `layout`.
    ///
    /// # Errors
    /// [`VariationalError::NotFullTransition`] unless the layout carries all n tangent
    /// vectors, [`VariationalError::SizeMismatch`] if `y` is not the layout's length,
    /// [`VariationalError::NonFinite`] for a NaN or infinite entry.
    pub fn new(layout: Layout, y: &[f64]) -> Result<FlowMap, VariationalError> {
        if layout.tangents != layout.n {
            return Err(VariationalError::NotFullTransition {
                tangents: layout.tangents,
                n: layout.n,
            });
        }
        layout.check_size(y.len())?;
        check_finite(y)?;
        Ok(FlowMap {
            state: y[..layout.n].to_vec(),
            transition: layout.transition(y),
        })
    }

    /// Φ P₀ Φᵀ: the covariance at t of a state whose covariance at the start was `p0`.
    ///
    /// # Errors
    /// [`VariationalError::CovarianceShape`] unless `p0` is n × n,
    /// [`VariationalError::NonFinite`] for a NaN or infinite entry (row-major index),
    /// [`VariationalError::Overflow`] when the product overflows f64 (a finite Φ of 10²⁰⁰).
    pub fn covariance(&self, p0: &DMatrix<f64>) -> Result<DMatrix<f64>, VariationalError> {
        let n = self.state.len();
        if p0.nrows() != n || p0.ncols() != n {
            return Err(VariationalError::CovarianceShape {
                rows: p0.nrows(),
                cols: p0.ncols(),
                n,
            });
        }
        check_finite(p0.transpose().as_slice())?;
        let phi = &self.transition;
        let p = phi * p0 * phi.transpose();
        // Symmetric in exact arithmetic; averaging with the transpose removes the rounding.
        let p = (&p + p.transpose()) * 0.5;
        self.finite(p.transpose().as_slice())?;
        Ok(p)
    }

    /// x(t) + Φ δx₀: where a run started at x₀ + δx₀ is, to first order.
    ///
    /// # Errors
    /// [`VariationalError::InitialStateLength`] unless `dx0` is n long,
    /// [`VariationalError::NonFinite`] for a NaN or infinite entry,
    /// [`VariationalError::Overflow`] when x + Φ δx₀ overflows f64.
    pub fn apply(&self, dx0: &[f64]) -> Result<Vec<f64>, VariationalError> {
        let n = self.state.len();
        if dx0.len() != n {
            return Err(VariationalError::InitialStateLength {
                expected: n,
                got: dx0.len(),
            });
        }
        check_finite(dx0)?;
        let d = &self.transition * nalgebra::DVector::from_column_slice(dx0);
        let x: Vec<f64> = self
            .state
            .iter()
            .zip(d.iter())
            .map(|(x, d)| x + d)
            .collect();
        self.finite(&x)?;
        Ok(x)
    }

    /// Refuses a result that overflowed: the inputs were finite, so an infinite or NaN
    /// entry is the product's (NaN from ∞ − ∞ in a sum).
    fn finite(&self, values: &[f64]) -> Result<(), VariationalError> {
        check_finite(values).map_err(|e| match e {
            VariationalError::NonFinite { index, value } => VariationalError::Overflow {
                index,
                value,
                largest: self.transition.amax(),
            },
            other => other,
        })
    }
}
