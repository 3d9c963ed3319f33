//! The linearised bicycle in the canonical form of Meijaard et al. (2007, eq. 5.2):
//! M q̈ + v C₁ q̇ + (g K₀ + v² K₂) q = T, q = (φ, δ), T = (T_φ, T_δ) the roll and steer
//! torques; its state matrices, its eigenvalues against the forward speed v, and the weave
//! and capsize speeds that bound its self-stable range.

use crate::linalg::{
    CROSSING_TOLERANCE, Crossing, CrossingError, LinalgError, eigenvalues, find_crossing,
    spectral_abscissa,
};
use crate::nalgebra::{Complex, Matrix2, Matrix4, Matrix4x2};

/// The four matrices of the linearised lateral equations and g.
///
/// # Examples
///
/// A bicycle given by its matrices (here those of Meijaard et al. 2007, eq. 5.3–5.6):
///
/// ```
/// use approx::assert_relative_eq;
/// use precess::models::bicycle::Canonical;
/// use precess::nalgebra::Matrix2;
///
/// let lin = Canonical::new(
///     Matrix2::new(80.81722, 2.31941332208709, 2.31941332208709, 0.29784188199686),
///     Matrix2::new(0.0, 33.86641391492494, -0.85035641456978, 1.68540397397560),
///     Matrix2::new(-80.95, -2.59951685249872, -2.59951685249872, -0.80329488458618),
///     Matrix2::new(0.0, 76.59734589573222, 0.0, 2.65431523794604),
///     9.81,
/// )?;
/// let capsize = lin.stability_crossing(5.5, 7.0)?;
/// assert_relative_eq!(capsize.parameter, 6.02426201538837, max_relative = 1e-11);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Canonical {
    /// The mass matrix M \[kg m²\].
    pub m: Matrix2<f64>,
    /// C₁, the matrix of the velocity terms per unit speed (gyroscopic and
    /// damping-like) \[kg m\].
    pub c1: Matrix2<f64>,
    /// K₀, the gravity stiffness per unit g \[kg m\].
    pub k0: Matrix2<f64>,
    /// K₂, the stiffness per unit v² \[kg\].
    pub k2: Matrix2<f64>,
    /// Gravity g \[m/s²\].
    pub g: f64,
}

impl Canonical {
    /// The linear bicycle of the given matrices.
    ///
    /// # Errors
    /// [`LinalgError::NonFinite`] for a NaN or infinite entry or g;
    /// [`LinalgError::InvalidParameter`] if M is singular (`name` "det M").
    pub fn new(
        m: Matrix2<f64>,
        c1: Matrix2<f64>,
        k0: Matrix2<f64>,
        k2: Matrix2<f64>,
        g: f64,
    ) -> Result<Canonical, LinalgError> {
        for (quantity, x) in [("M", &m), ("C1", &c1), ("K0", &k0), ("K2", &k2)] {
            if let Some((k, value)) = x.iter().enumerate().find(|(_, v)| !v.is_finite()) {
                return Err(LinalgError::NonFinite {
                    quantity,
                    row: k % 2,
                    col: k / 2,
                    value: *value,
                });
            }
        }
        if !g.is_finite() {
            return Err(LinalgError::NonFinite {
                quantity: "g",
                row: 0,
                col: 0,
                value: g,
            });
        }
        let det = m.determinant();
        if det.abs() <= f64::EPSILON * m.norm_squared() {
            return Err(LinalgError::InvalidParameter {
                name: "det M",
                value: det,
            });
        }
        Ok(Canonical { m, c1, k0, k2, g })
    }

    /// The state matrix A at speed v of ẋ = A x + B T, x = (φ, δ, φ̇, δ̇):
    /// A = ((0, I), (−M⁻¹ (g K₀ + v² K₂), −v M⁻¹ C₁)).
    ///
    /// # Errors
    /// [`LinalgError::NonFinite`] for a non-finite v.
    pub fn state_matrix(&self, v: f64) -> Result<Matrix4<f64>, LinalgError> {
        if !v.is_finite() {
            return Err(LinalgError::NonFinite {
                quantity: "forward speed",
                row: 0,
                col: 0,
                value: v,
            });
        }
        let m_inv = self.inverse_mass();
        let stiff = -(m_inv * (self.k0 * self.g + self.k2 * (v * v)));
        let damp = -(m_inv * self.c1 * v);
        let mut a = Matrix4::zeros();
        a[(0, 2)] = 1.0;
        a[(1, 3)] = 1.0;
        a.fixed_view_mut::<2, 2>(2, 0).copy_from(&stiff);
        a.fixed_view_mut::<2, 2>(2, 2).copy_from(&damp);
        Ok(a)
    }

    /// The input matrix B of ẋ = A x + B T for the torques T = (T_φ, T_δ) (a lean torque
    /// and the rider's steer torque): B = (0; M⁻¹), the same at every speed.
    pub fn input_matrix(&self) -> Matrix4x2<f64> {
        let mut b = Matrix4x2::zeros();
        b.fixed_view_mut::<2, 2>(2, 0)
            .copy_from(&self.inverse_mass());
        b
    }

    /// M⁻¹ (M is checked invertible when built).
    fn inverse_mass(&self) -> Matrix2<f64> {
        let (m, det) = (&self.m, self.m.determinant());
        Matrix2::new(m[(1, 1)], -m[(0, 1)], -m[(1, 0)], m[(0, 0)]) / det
    }

    /// The four eigenvalues at speed v, complex pairs adjacent, by decreasing real part.
    ///
    /// # Errors
    /// As [`Canonical::state_matrix`] and [`eigenvalues`].
    pub fn eigenvalues(&self, v: f64) -> Result<Vec<Complex<f64>>, LinalgError> {
        eigenvalues(&self.state_matrix(v)?)
    }

    /// The eigenvalues at each speed of `speeds` (a root-locus against v).
    ///
    /// # Errors
    /// As [`Canonical::eigenvalues`], at the first speed that fails.
    pub fn eigenvalues_against_speed(
        &self,
        speeds: impl IntoIterator<Item = f64>,
    ) -> Result<Vec<SpeedModes>, LinalgError> {
        speeds
            .into_iter()
            .map(|speed| {
                Ok(SpeedModes {
                    speed,
                    eigenvalues: self.eigenvalues(speed)?,
                })
            })
            .collect()
    }

    /// Where the largest real part of the eigenvalues crosses zero in the speed range
    /// \[lo, hi\], to [`CROSSING_TOLERANCE`]: the weave speed v_w for a range where only the
    /// weave pair crosses (the bicycle turns stable), the capsize speed v_c for one where
    /// only the capsize mode does (unstable again). See
    /// [`crate::linalg::stability_crossing`].
    ///
    /// # Errors
    /// [`CrossingError::NoCrossing`] if the bicycle is stable at both ends or unstable at
    /// both; [`CrossingError::InvalidBracket`]; [`CrossingError::Linalg`].
    pub fn stability_crossing(&self, lo: f64, hi: f64) -> Result<Crossing, CrossingError> {
        let linalg = |parameter| move |source| CrossingError::Linalg { parameter, source };
        find_crossing(
            |v| {
                let a = self.state_matrix(v).map_err(linalg(v))?;
                Ok(spectral_abscissa(&eigenvalues(&a).map_err(linalg(v))?))
            },
            lo,
            hi,
            CROSSING_TOLERANCE,
        )
    }
}

/// The eigenvalues at one forward speed.
#[derive(Clone, Debug, PartialEq)]
pub struct SpeedModes {
    /// The forward speed v \[m/s\].
    pub speed: f64,
    /// The eigenvalues there \[1/s\], by decreasing real part.
    pub eigenvalues: Vec<Complex<f64>>,
}
