//! The linear system ẋ = A x about a state, and the stability verdict its spectrum gives.

use nalgebra::{Complex, DMatrix};

use super::eigen::eigenvalues;
use super::error::{LinalgError, check_finite};
use super::jacobian::jacobian;
use crate::ode::System;

/// The default tolerance of the verdict, relative to ‖A‖ (Frobenius): a real part within
/// `NEUTRAL_TOLERANCE · max(‖A‖, 1)` of zero counts as on the imaginary axis.
///
/// It sits far above the QR iteration's rounding (a few ε‖A‖ for semisimple eigenvalues)
/// and the error of a Richardson Jacobian (≈ 1e-12), and below any growth rate worth
/// reporting. A defective eigenvalue (a k×k Jordan block) is computed only to
/// (ε‖A‖)^{1/k}: pass a looser tolerance to [`LinearSystem::stability_with`] for those.
pub const NEUTRAL_TOLERANCE: f64 = 1e-9;

/// What the spectrum of A says about the linear system ẋ = A x.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Stability {
    /// Some eigenvalue has a real part above the tolerance: perturbations grow like
    /// `e^{growth_rate·t}`.
    Unstable {
        /// The largest real part of an eigenvalue.
        growth_rate: f64,
    },
    /// No eigenvalue lies to the right of the imaginary axis and at least one lies on it
    /// (within the tolerance): neutral, oscillating or drifting perturbations.
    ///
    /// Linear stability only: a Jordan block on the axis (a cyclic coordinate's drift, for
    /// one) grows polynomially, and the nonlinear motion may still be unstable.
    LinearlyStable {
        /// The largest |Re λ| among the eigenvalues taken as on the axis (rounding only).
        max_abs_real: f64,
    },
    /// Every eigenvalue lies left of the axis: perturbations decay like `e^{−decay_rate·t}`.
    AsymptoticallyStable {
        /// The smallest |Re λ|.
        decay_rate: f64,
    },
}

/// The verdict for the eigenvalues `eig` of a matrix of Frobenius norm `norm`, taking real
/// parts within `tol · max(norm, 1)` of zero as on the axis.
pub(crate) fn classify(eig: &[Complex<f64>], norm: f64, tol: f64) -> Stability {
    let band = tol * norm.max(1.0);
    let max_re = eig.iter().map(|e| e.re).fold(f64::NEG_INFINITY, f64::max);
    if max_re > band {
        return Stability::Unstable {
            growth_rate: max_re,
        };
    }
    let on_axis = eig.iter().filter(|e| e.re.abs() <= band);
    match on_axis.map(|e| e.re.abs()).reduce(f64::max) {
        Some(max_abs_real) => Stability::LinearlyStable { max_abs_real },
        // Empty matrices land here too: no mode, nothing grows.
        None if eig.is_empty() => Stability::LinearlyStable { max_abs_real: 0.0 },
        None => Stability::AsymptoticallyStable {
            decay_rate: -max_re,
        },
    }
}

/// The linear system ẋ = A x: a linearisation about a state or a steady motion.
///
/// # Examples
///
/// Euler's equations about the intermediate axis: perturbations grow at
/// ω √((I2 − I1)(I3 − I2)/(I1 I3)).
///
/// ```
/// use approx::assert_relative_eq;
/// use precess_core::body::euler_rhs_diagonal;
/// use precess_core::linalg::{LinearSystem, Stability};
/// use precess_core::nalgebra::Vector3;
/// use precess_core::ode::FnSystem;
///
/// let (i, w) = (Vector3::new(1.0, 2.0, 3.0), 5.0);
/// let euler = FnSystem(move |_t: f64, y: &[f64; 3], d: &mut [f64; 3]| {
///     let dw = euler_rhs_diagonal(&i, &Vector3::from(*y), &Vector3::zeros());
///     d.copy_from_slice(dw.as_slice());
/// });
/// let lin = LinearSystem::from_system(&euler, 0.0, &[0.0, w, 0.0])?;
/// let Stability::Unstable { growth_rate } = lin.stability()? else { panic!() };
/// assert_relative_eq!(growth_rate, w * (1.0f64 * 1.0 / 3.0).sqrt(), max_relative = 1e-10);
/// # Ok::<(), precess_core::linalg::LinalgError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct LinearSystem {
    matrix: DMatrix<f64>,
}

impl LinearSystem {
    /// The system ẋ = A x for a given A.
    ///
    /// # Errors
    /// [`LinalgError::NotSquare`], [`LinalgError::NonFinite`].
    pub fn new(matrix: DMatrix<f64>) -> Result<Self, LinalgError> {
        let (rows, cols) = matrix.shape();
        if rows != cols {
            return Err(LinalgError::NotSquare { rows, cols });
        }
        check_finite("matrix entry", rows, |r, c| matrix[(r, c)], cols)?;
        Ok(LinearSystem { matrix })
    }

    /// The linearisation of an ODE system about `(t, y)`: A = ∂f/∂y by central differences
    /// with Richardson extrapolation (see [`jacobian`]).
    ///
    /// # Errors
    /// [`LinalgError::NonFinite`] if `y` or a value of f near it is not finite.
    pub fn from_system<S: System<N>, const N: usize>(
        system: &S,
        t: f64,
        y: &[f64; N],
    ) -> Result<Self, LinalgError> {
        let matrix = jacobian(
            |v, out| {
                let mut state = [0.0; N];
                state.copy_from_slice(v);
                let mut d = [0.0; N];
                system.rhs(t, &state, &mut d);
                out.copy_from_slice(&d);
            },
            y,
        )?;
        Ok(LinearSystem { matrix })
    }

    /// The matrix A.
    pub fn matrix(&self) -> &DMatrix<f64> {
        &self.matrix
    }

    /// The dimension of the state.
    pub fn dim(&self) -> usize {
        self.matrix.nrows()
    }

    /// The eigenvalues of A, as [`eigenvalues`] orders them.
    ///
    /// # Errors
    /// As [`eigenvalues`].
    pub fn eigenvalues(&self) -> Result<Vec<Complex<f64>>, LinalgError> {
        eigenvalues(&self.matrix)
    }

    /// The verdict with the default tolerance [`NEUTRAL_TOLERANCE`].
    ///
    /// # Errors
    /// As [`eigenvalues`].
    pub fn stability(&self) -> Result<Stability, LinalgError> {
        self.stability_with(NEUTRAL_TOLERANCE)
    }

    /// The verdict, taking real parts within `tol · max(‖A‖, 1)` of zero as on the axis.
    ///
    /// # Errors
    /// [`LinalgError::InvalidParameter`] unless `tol` is finite and > 0; as [`eigenvalues`].
    pub fn stability_with(&self, tol: f64) -> Result<Stability, LinalgError> {
        if !(tol.is_finite() && tol > 0.0) {
            return Err(LinalgError::InvalidParameter {
                name: "tolerance",
                value: tol,
            });
        }
        let eig = self.eigenvalues()?;
        Ok(classify(&eig, self.matrix.norm(), tol))
    }
}
