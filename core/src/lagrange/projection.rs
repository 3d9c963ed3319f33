//! Maggi's projection evaluated in floating point: the reduced equations of a system under
//! m velocity constraints, formed at run time from numbers for M, f, A and Ȧq̇.
//!
//! [`EquationsOfMotion::constrain`](super::EquationsOfMotion::constrain) eliminates the
//! dependent speeds symbolically, which gives the smallest code for small constraint blocks
//! (the four-bar, the rolling disk). For a block of five rows with square roots in them (the
//! Whipple bicycle) the symbolic adjugate of A_D swells past gigabytes; there the symbolic
//! engine derives M(q), f(q, q̇), A(q) and Ȧq̇ exactly, and this file finishes the job with
//! an LU factorisation per evaluation:
//!
//! - A_D q̇_D = −A_I u gives S = [I; −A_D⁻¹ A_I] (q̇ = S u in the original order),
//! - A q̈ + Ȧq̇ = 0 gives q̈ = S u̇ + s with s_D = −A_D⁻¹ Ȧq̇, s_I = 0,
//! - Sᵀ (M q̈ − f) = 0 gives K u̇ = r with K = Sᵀ M S and r = Sᵀ (f − M s).
//!
//! Sizes are const generics (n coordinates, m constraints, k = n − m free speeds), so an
//! evaluation allocates nothing.

use nalgebra::{SMatrix, SVector};

use super::error::LagrangeError;

/// Which coordinates' rates are free (the state's speeds u = q̇_I) and which follow from
/// the constraints.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Partition<const M: usize, const K: usize> {
    /// The independent coordinates, in the state's order of speeds.
    pub independent: [usize; K],
    /// The dependent coordinates, one per constraint row.
    pub dependent: [usize; M],
}

/// The rates and the projection at one configuration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Projected<const N: usize, const K: usize> {
    /// q̇ = S u, every coordinate's rate.
    pub rates: [f64; N],
    /// S (n × k): q̇ = S u.
    pub projection: SMatrix<f64, N, K>,
}

impl<const M: usize, const K: usize> Partition<M, K> {
    /// The dependent block A_D and the independent block A_I of `a`.
    fn blocks<const N: usize>(
        &self,
        a: &SMatrix<f64, M, N>,
    ) -> (SMatrix<f64, M, M>, SMatrix<f64, M, K>) {
        (
            SMatrix::from_fn(|r, c| a[(r, self.dependent[c])]),
            SMatrix::from_fn(|r, c| a[(r, self.independent[c])]),
        )
    }

    /// s_D = −A_D⁻¹ Ȧq̇, the dependent accelerations at u̇ = 0.
    fn drift<const N: usize>(
        &self,
        a: &SMatrix<f64, M, N>,
        rate_terms: &SVector<f64, M>,
    ) -> Result<SVector<f64, M>, LagrangeError> {
        let (a_d, _) = self.blocks(a);
        solve(a_d, -rate_terms, Inverted::DependentBlock)
    }

    /// Every rate from the free speeds: solves A_D q̇_D = −A_I u.
    ///
    /// # Errors
    /// [`LagrangeError::SingularAtState`] where A_D is singular (a dependent choice that
    /// fails at this configuration) or the solve is not finite.
    ///
    /// ```
    /// use nalgebra::SMatrix;
    /// use precess_core::lagrange::Partition;
    /// // A wheel of radius r rolling along x: ẋ − r θ̇ = 0, x dependent, θ free.
    /// let r = 0.5;
    /// let a = SMatrix::<f64, 1, 2>::new(1.0, -r);
    /// let part = Partition { independent: [1], dependent: [0] };
    /// let p = part.rates(&a, &[2.0])?;
    /// assert_eq!(p.rates, [1.0, 2.0]);
    /// # Ok::<(), precess_core::lagrange::LagrangeError>(())
    /// ```
    pub fn rates<const N: usize>(
        &self,
        a: &SMatrix<f64, M, N>,
        u: &[f64; K],
    ) -> Result<Projected<N, K>, LagrangeError> {
        let (a_d, a_i) = self.blocks(a);
        let c = solve(a_d, -a_i, Inverted::DependentBlock)?;
        let mut s = SMatrix::<f64, N, K>::zeros();
        for (j, &i) in self.independent.iter().enumerate() {
            s[(i, j)] = 1.0;
        }
        for (r, &d) in self.dependent.iter().enumerate() {
            for j in 0..K {
                s[(d, j)] = c[(r, j)];
            }
        }
        let qd = s * SVector::<f64, K>::from_column_slice(u);
        let mut rates = [0.0; N];
        rates.copy_from_slice(qd.as_slice());
        Ok(Projected {
            rates,
            projection: s,
        })
    }

    /// The free speeds' accelerations u̇ from K u̇ = r, K = Sᵀ M S, r = Sᵀ (f − M s), with
    /// `projected` from [`Partition::rates`] at the same configuration and `rate_terms`
    /// Ȧq̇ evaluated at its rates.
    ///
    /// # Errors
    /// [`LagrangeError::SingularAtState`] where A_D is singular;
    /// [`LagrangeError::SingularReducedMass`] where K is.
    ///
    /// ```
    /// use nalgebra::{SMatrix, SVector};
    /// use precess_core::lagrange::Partition;
    /// // A uniform disk (mass m, radius r) rolling along x under a force F on its centre:
    /// // M = diag(m, m r²/2), f = (F, 0), ẋ = r θ̇, so (3/2) m r² θ̈ = F r.
    /// let (m, r, force) = (2.0, 0.5, 3.0);
    /// let a = SMatrix::<f64, 1, 2>::new(1.0, -r);
    /// let part = Partition { independent: [1], dependent: [0] };
    /// let p = part.rates(&a, &[0.0])?;
    /// let mass = SMatrix::<f64, 2, 2>::new(m, 0.0, 0.0, m * r * r / 2.0);
    /// let f = SVector::<f64, 2>::new(force, 0.0);
    /// let ud = part.accelerations(&mass, &f, &a, &SVector::zeros(), &p)?;
    /// assert!((ud[0] - force / (1.5 * m * r)).abs() < 1e-15);
    /// # Ok::<(), precess_core::lagrange::LagrangeError>(())
    /// ```
    pub fn accelerations<const N: usize>(
        &self,
        mass: &SMatrix<f64, N, N>,
        forcing: &SVector<f64, N>,
        a: &SMatrix<f64, M, N>,
        rate_terms: &SVector<f64, M>,
        projected: &Projected<N, K>,
    ) -> Result<[f64; K], LagrangeError> {
        let drift_d = self.drift(a, rate_terms)?;
        let mut drift = SVector::<f64, N>::zeros();
        for (r, &d) in self.dependent.iter().enumerate() {
            drift[d] = drift_d[r];
        }
        let s = &projected.projection;
        let k = s.transpose() * mass * s;
        let rhs = s.transpose() * (forcing - mass * drift);
        let ud = solve(k, rhs, Inverted::ReducedMass)?;
        let mut out = [0.0; K];
        out.copy_from_slice(ud.as_slice());
        Ok(out)
    }

    /// The multipliers λ of the constraints (A_Dᵀ λ = (M q̈ − f)_D, the dependent rows of
    /// the unreduced equations M q̈ = f + Aᵀ λ), the reactions that keep the constraints,
    /// with q̈ = S u̇ + s.
    ///
    /// # Errors
    /// [`LagrangeError::SingularAtState`] where A_D is singular.
    pub fn multipliers<const N: usize>(
        &self,
        mass: &SMatrix<f64, N, N>,
        forcing: &SVector<f64, N>,
        a: &SMatrix<f64, M, N>,
        accelerations: &SVector<f64, N>,
    ) -> Result<[f64; M], LagrangeError> {
        let (a_d, _) = self.blocks(a);
        let residual = mass * accelerations - forcing;
        let r_d = SVector::<f64, M>::from_fn(|r, _| residual[self.dependent[r]]);
        let lambda = solve(a_d.transpose(), r_d, Inverted::DependentBlock)?;
        let mut out = [0.0; M];
        out.copy_from_slice(lambda.as_slice());
        Ok(out)
    }

    /// Every coordinate's acceleration q̈ = S u̇ + s.
    ///
    /// # Errors
    /// [`LagrangeError::SingularAtState`] where A_D is singular.
    pub fn full_accelerations<const N: usize>(
        &self,
        a: &SMatrix<f64, M, N>,
        rate_terms: &SVector<f64, M>,
        projected: &Projected<N, K>,
        free: &[f64; K],
    ) -> Result<SVector<f64, N>, LagrangeError> {
        let drift_d = self.drift(a, rate_terms)?;
        let mut q_ddot = projected.projection * SVector::<f64, K>::from_column_slice(free);
        for (r, &d) in self.dependent.iter().enumerate() {
            q_ddot[d] += drift_d[r];
        }
        Ok(q_ddot)
    }
}

/// The matrix a projection solves with, which names the error when it is singular.
#[derive(Clone, Copy)]
pub(crate) enum Inverted {
    /// A_D (or its transpose): [`LagrangeError::SingularAtState`].
    DependentBlock,
    /// K = Sᵀ M S: [`LagrangeError::SingularReducedMass`].
    ReducedMass,
}

/// Solves `a x = b` (see [`eliminate`]); where `a` is singular, the error of the matrix it
/// is, with the determinant and the Frobenius norm of `a` to judge it against.
///
/// # Errors
/// [`LagrangeError::SingularAtState`] or [`LagrangeError::SingularReducedMass`], by `inverted`.
pub(crate) fn solve<const R: usize, const C: usize>(
    a: SMatrix<f64, R, R>,
    b: SMatrix<f64, R, C>,
    inverted: Inverted,
) -> Result<SMatrix<f64, R, C>, LagrangeError> {
    eliminate(a, b).map_err(|determinant| {
        let scale = a.norm();
        match inverted {
            Inverted::DependentBlock => LagrangeError::SingularAtState { determinant, scale },
            Inverted::ReducedMass => LagrangeError::SingularReducedMass { determinant, scale },
        }
    })
}

/// Solves `a x = b` by Gaussian elimination with partial pivoting, for any fixed size (the
/// const-generic sizes rule out nalgebra's LU, whose bounds need typenum dimensions).
///
/// # Errors
/// The determinant of `a` (as far as the elimination got) when a pivot is zero or the
/// solution is not finite.
fn eliminate<const R: usize, const C: usize>(
    mut a: SMatrix<f64, R, R>,
    mut b: SMatrix<f64, R, C>,
) -> Result<SMatrix<f64, R, C>, f64> {
    let mut determinant = 1.0;
    for col in 0..R {
        let pivot = (col..R)
            .max_by(|&i, &j| a[(i, col)].abs().total_cmp(&a[(j, col)].abs()))
            .unwrap_or(col);
        let p = a[(pivot, col)];
        if p == 0.0 || !p.is_finite() {
            return Err(if p.is_finite() { 0.0 } else { f64::NAN });
        }
        if pivot != col {
            a.swap_rows(pivot, col);
            b.swap_rows(pivot, col);
            determinant = -determinant;
        }
        determinant *= p;
        for row in col + 1..R {
            let factor = a[(row, col)] / p;
            if factor == 0.0 {
                continue;
            }
            for k in col..R {
                a[(row, k)] -= factor * a[(col, k)];
            }
            for k in 0..C {
                b[(row, k)] -= factor * b[(col, k)];
            }
        }
    }
    for col in (0..R).rev() {
        for k in 0..C {
            let mut v = b[(col, k)];
            for j in col + 1..R {
                v -= a[(col, j)] * b[(j, k)];
            }
            b[(col, k)] = v / a[(col, col)];
        }
    }
    if b.iter().any(|v| !v.is_finite()) {
        return Err(determinant);
    }
    Ok(b)
}
