//! The derived bicycle linearised about the upright straight run: the lateral equations in
//! the canonical form of Meijaard et al. (2007), M q̈ + v C₁ q̇ + (g K₀ + v² K₂) q = 0 with
//! q = (φ, δ), recovered from the nonlinear rolling equations alone.

use thiserror::Error;

use super::Bicycle;
use super::canonical::Canonical;
use crate::linalg::LinalgError;
use crate::mechanism::MechanismError;
use crate::mechanism::rolling::RollingDynamics;
use crate::nalgebra::{Matrix2, Matrix3};

/// The largest relative step of the central differences in the angles (h, h/2, h/4 are
/// taken and extrapolated twice by Richardson: truncation O(h⁶) ≈ 1e-12, rounding about
/// ε·|u̇|/h where u̇ vanishes at the upright run).
pub const ANGLE_STEP: f64 = 1e-2;

/// The largest lateral acceleration \[rad/s²\] allowed at the reference state of the
/// linearisation: the upright straight run must be a steady motion (it is for every
/// bicycle symmetric about its mid-plane, which the fields cannot break).
pub const STEADY_TOLERANCE: f64 = 1e-9;

/// Why the bicycle could not be linearised.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum BicycleLinearisationError {
    /// The nonlinear model refused a state: a parameter out of range, the front wheel not
    /// put on the ground, a singular projection.
    #[error(transparent)]
    Mechanism(#[from] MechanismError),
    /// A matrix was not finite, or the eigenvalue routine failed.
    #[error(transparent)]
    Linalg(#[from] LinalgError),
    /// The reduced mass matrix's lateral block is singular (a massless front assembly).
    #[error("the lateral mass matrix is singular: det M = {determinant:e}")]
    SingularMass {
        /// det M.
        determinant: f64,
    },
    /// The upright straight run at this speed is not a steady motion: the lateral
    /// accelerations there are not zero.
    #[error(
        "the upright run at v = {speed} m/s is not steady: |(φ̈, δ̈)| = {residual:e} rad/s² \
         (allowed {allowed:e})"
    )]
    NotSteady {
        /// The forward speed.
        speed: f64,
        /// The largest |φ̈|, |δ̈| there.
        residual: f64,
        /// `STEADY_TOLERANCE`.
        allowed: f64,
    },
}

impl Bicycle {
    /// \[φ̈, δ̈\] on the constraints at roll φ, steer δ and their rates `x`, the rear wheel
    /// turning at −v / r_R, the pitch put back on the floor first.
    fn lateral(&self, x: [f64; 4], v: f64) -> Result<[f64; 2], MechanismError> {
        let mut q = [0.0; 8];
        q[Bicycle::PHI] = x[0];
        q[Bicycle::DELTA] = x[1];
        self.close_contacts(&mut q)?;
        let (_, ud) = self.derivative(0.0, &q, &[x[2], x[3], -v / self.r_r])?;
        Ok([ud[0], ud[1]])
    }

    /// ∂\[φ̈, δ̈\]/∂x_j at the upright run at speed v. For a rate (j ≥ 2) one central
    /// difference of step 1, which is exact: at fixed q the accelerations are a quadratic
    /// form in the speeds (u̇ = K(q)⁻¹ Sᵀ (f − M s), f and s quadratic in q̇ = S u), so the
    /// difference quotient of a quadratic is its derivative. For an angle, central
    /// differences extrapolated twice by Richardson, since the derive emits no Jacobian for
    /// rolling mechanisms.
    fn lateral_column(&self, j: usize, v: f64) -> Result<[f64; 2], MechanismError> {
        let central = |h: f64| -> Result<[f64; 2], MechanismError> {
            let (mut xp, mut xm) = ([0.0; 4], [0.0; 4]);
            xp[j] = h;
            xm[j] = -h;
            let (p, m) = (self.lateral(xp, v)?, self.lateral(xm, v)?);
            Ok([(p[0] - m[0]) / (2.0 * h), (p[1] - m[1]) / (2.0 * h)])
        };
        if j >= 2 {
            return central(1.0);
        }
        let h = ANGLE_STEP;
        let d = [central(h)?, central(h / 2.0)?, central(h / 4.0)?];
        Ok([0, 1].map(|i| {
            let r1 = (4.0 * d[1][i] - d[0][i]) / 3.0;
            let r2 = (4.0 * d[2][i] - d[1][i]) / 3.0;
            (16.0 * r2 - r1) / 15.0
        }))
    }

    /// The lower half of the lateral state matrix at speed v:
    /// (∂(φ̈, δ̈)/∂(φ, δ), ∂(φ̈, δ̈)/∂(φ̇, δ̇)).
    ///
    /// # Errors
    /// As [`Bicycle::canonical`].
    pub fn lateral_jacobian(
        &self,
        v: f64,
    ) -> Result<(Matrix2<f64>, Matrix2<f64>), BicycleLinearisationError> {
        if !v.is_finite() {
            return Err(MechanismError::NonFinite {
                quantity: "forward speed",
                values: vec![v],
            }
            .into());
        }
        let at_rest = self.lateral([0.0; 4], v)?;
        let residual = at_rest[0].abs().max(at_rest[1].abs());
        if residual.is_nan() || residual > STEADY_TOLERANCE {
            return Err(BicycleLinearisationError::NotSteady {
                speed: v,
                residual,
                allowed: STEADY_TOLERANCE,
            });
        }
        let c = [0, 1, 2, 3]
            .map(|j| self.lateral_column(j, v))
            .into_iter()
            .collect::<Result<Vec<_>, _>>()?;
        Ok((
            Matrix2::new(c[0][0], c[1][0], c[0][1], c[1][1]),
            Matrix2::new(c[2][0], c[3][0], c[2][1], c[3][1]),
        ))
    }

    /// The linearised lateral equations about the upright straight run in the canonical
    /// form of Meijaard et al. (2007, eq. 5.2): M q̈ + v C₁ q̇ + (g K₀ + v² K₂) q = 0,
    /// q = (φ, δ).
    ///
    /// M is the lateral block of the reduced mass matrix Sᵀ M S at the upright run (exact).
    /// With u̇ = M⁻¹ r, ∂u̇/∂q = −M⁻¹ (g K₀ + v² K₂) and ∂u̇/∂q̇ = −v M⁻¹ C₁ are exactly
    /// quadratic and linear in v, so the speeds 0 and 1 fix them:
    /// K₀ = −M ∂u̇/∂q|₀ / g, K₂ = −M (∂u̇/∂q|₁ − ∂u̇/∂q|₀), C₁ = −M ∂u̇/∂q̇|₁.
    /// The rate derivatives are exact; the angle derivatives are Richardson-extrapolated
    /// central differences (the derive emits no Jacobian for a rolling mechanism; about
    /// 1e-14 relative on the benchmark, docs/linearisation.md).
    ///
    /// # Errors
    /// [`BicycleLinearisationError::Mechanism`] for a parameter out of range or a state the
    /// projection cannot handle; [`BicycleLinearisationError::SingularMass`];
    /// [`BicycleLinearisationError::NotSteady`].
    ///
    /// # Examples
    ///
    /// ```
    /// use approx::assert_relative_eq;
    /// use precess::models::Bicycle;
    ///
    /// let lin = Bicycle::benchmark().canonical()?;
    /// // Meijaard et al. (2007), eq. 5.3: M₁₁ = 80.81722 kg m².
    /// assert_relative_eq!(lin.m[(0, 0)], 80.81722, max_relative = 1e-12);
    /// // The self-stable range: the weave speed, where the largest real part of an
    /// // eigenvalue crosses zero, 4.29238253634111 m/s (their Table 2).
    /// let weave = lin.stability_crossing(4.0, 5.0)?;
    /// assert_relative_eq!(weave.parameter, 4.29238253634111, max_relative = 1e-11);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn canonical(&self) -> Result<Canonical, BicycleLinearisationError> {
        let mut q = [0.0; 8];
        self.close_contacts(&mut q)?;
        let partition = self.partition();
        let (a, _) = self.constraint_rows(&q, &[0.0; 8]);
        let projected = partition
            .rates(&a, &[0.0; 3])
            .map_err(MechanismError::from)?;
        let (mass, _) = self.mass_forcing(0.0, &q, &[0.0; 8]);
        let s = projected.projection;
        let reduced: Matrix3<f64> = s.transpose() * mass * s;
        let m = Matrix2::new(
            reduced[(0, 0)],
            reduced[(0, 1)],
            reduced[(1, 0)],
            reduced[(1, 1)],
        );
        let determinant = m.determinant();
        if !(determinant.is_finite() && determinant.abs() > f64::EPSILON * m.norm_squared()) {
            return Err(BicycleLinearisationError::SingularMass { determinant });
        }
        let (p0, _) = self.lateral_jacobian(0.0)?;
        let (p1, d1) = self.lateral_jacobian(1.0)?;
        Ok(Canonical::new(
            m,
            -(m * d1),
            -(m * p0) / self.g,
            -(m * (p1 - p0)),
            self.g,
        )?)
    }
}
