//! The linearisation with inputs: ẋ = A x + B u about an operating point (x₀, u₀) where
//! the motion is an equilibrium or a steady motion, x and u the deviations from it.
//!
//! Two ways in. [`StateSpace::second_order`] takes what a derived scene gives exactly: the
//! Jacobian of q̈ (the derives emit ∂q̈/∂q and ∂q̈/∂q̇ as code: `MechanismDynamics::
//! acceleration_jacobian`, `TopDynamics::angle_jacobian`), the mass matrix M(q) and the map
//! Q = G u from the inputs to the generalised forces, so B = [0; M⁻¹ G] is exact too: inputs
//! enter M q̈ = f + G u linearly. [`StateSpace::from_fn`] differentiates any f(x, u) by
//! Richardson-extrapolated central differences ([`super::jacobian`]), the fallback for a
//! model built at run time without derived Jacobians.

use nalgebra::{Complex, DMatrix};
use thiserror::Error;

use super::eigen::eigenvalues;
use super::error::{LinalgError, check_finite};
use super::jacobian::jacobian;

/// The default tolerance on the residual at the operating point, relative to
/// max(1, the largest |entry| of A): what is left of ẋ there must be this small.
pub const OPERATING_POINT_TOLERANCE: f64 = 1e-9;

/// Why a state-space linearisation could not be formed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum StateSpaceError {
    /// The point is not an equilibrium or a steady motion: a component of ẋ (or of q̈)
    /// is not zero there.
    #[error(
        "not an operating point: {quantity}[{component}] = {residual:e} there \
         (allowed {allowed:e})"
    )]
    NotOperatingPoint {
        /// What was checked: "ẋ" or "q̈".
        quantity: &'static str,
        /// Which component is largest.
        component: usize,
        /// Its value.
        residual: f64,
        /// The tolerance it exceeded.
        allowed: f64,
    },
    /// A matrix or a vector does not have the size the others imply.
    #[error("{quantity} is {rows}×{cols}; expected {expected_rows}×{expected_cols}")]
    Shape {
        /// Which argument.
        quantity: &'static str,
        /// Its rows.
        rows: usize,
        /// Its columns.
        cols: usize,
        /// The rows expected.
        expected_rows: usize,
        /// The columns expected.
        expected_cols: usize,
    },
    /// A non-finite value, a singular mass matrix, a failed eigenvalue routine.
    #[error(transparent)]
    Linalg(#[from] LinalgError),
}

/// The linear system ẋ = A x + B u.
#[derive(Debug, Clone, PartialEq)]
pub struct StateSpace {
    /// A, n × n.
    pub a: DMatrix<f64>,
    /// B, n × m (m inputs).
    pub b: DMatrix<f64>,
}

/// What [`StateSpace::second_order`] needs of a second-order system M(q) q̈ = f(q, q̇) + G u
/// at an operating point, every matrix n × n but G (n × m).
#[derive(Debug, Clone, Copy)]
pub struct SecondOrder<'a> {
    /// q̈ at the point (with the operating inputs applied): zero for an equilibrium or a
    /// steady motion.
    pub accelerations: &'a [f64],
    /// ∂q̈/∂q there.
    pub by_q: &'a DMatrix<f64>,
    /// ∂q̈/∂q̇ there.
    pub by_qdot: &'a DMatrix<f64>,
    /// The mass matrix M(q).
    pub mass: &'a DMatrix<f64>,
    /// G: column j is the generalised force of a unit of input j (for a torque on a
    /// hinge, the unit vector of its coordinate).
    pub inputs: &'a DMatrix<f64>,
}

impl StateSpace {
    /// The system of given A and B.
    ///
    /// # Errors
    /// [`StateSpaceError::Shape`] unless A is square and B has its rows;
    /// [`LinalgError::NonFinite`].
    pub fn new(a: DMatrix<f64>, b: DMatrix<f64>) -> Result<StateSpace, StateSpaceError> {
        let n = a.nrows();
        shape("A", &a, n, n)?;
        shape("B", &b, n, b.ncols())?;
        check_finite("A entry", n, |r, c| a[(r, c)], n)?;
        check_finite("B entry", n, |r, c| b[(r, c)], b.ncols())?;
        Ok(StateSpace { a, b })
    }

    /// The linearisation of M(q) q̈ = f(q, q̇) + G u about a point where q̈ = 0, in
    /// x = (δq, δq̇): A = ((0, I), (∂q̈/∂q, ∂q̈/∂q̇)), B = ((0), (M⁻¹ G)). Exact when the
    /// Jacobian is (the derived ones are): no differencing here.
    ///
    /// A point with q̇ ≠ 0 is a steady motion; A is then the motion's own linearisation
    /// when the equations do not depend on the coordinates that advance (cyclic ones).
    ///
    /// # Errors
    /// [`StateSpaceError::NotOperatingPoint`] naming the largest |q̈_i| if it exceeds
    /// [`OPERATING_POINT_TOLERANCE`] · max(1, max |∂q̈/∂(q, q̇)|);
    /// [`StateSpaceError::Shape`]; [`LinalgError::NonFinite`]; [`LinalgError::InvalidParameter`]
    /// ("mass matrix determinant") if M is singular.
    ///
    /// # Examples
    ///
    /// The pendulum m l² θ̈ = −m g l sin θ + τ hanging (θ = 0) and inverted (θ = π), with
    /// the torque τ as input: eigenvalues ±i√(g/l) and ±√(g/l), B = (0, 1/(m l²)).
    ///
    /// ```
    /// use approx::assert_relative_eq;
    /// use precess_core::linalg::{SecondOrder, StateSpace};
    /// use precess_core::nalgebra::DMatrix;
    ///
    /// let (m, l, g) = (2.0, 0.5, 9.81);
    /// let mass = DMatrix::from_element(1, 1, m * l * l);
    /// let inputs = DMatrix::from_element(1, 1, 1.0);
    /// for (theta, sign) in [(0.0_f64, -1.0), (std::f64::consts::PI, 1.0)] {
    ///     let by_q = DMatrix::from_element(1, 1, -g / l * theta.cos());
    ///     let by_qdot = DMatrix::zeros(1, 1);
    ///     let lin = StateSpace::second_order(&SecondOrder {
    ///         accelerations: &[-g / l * theta.sin()],
    ///         by_q: &by_q,
    ///         by_qdot: &by_qdot,
    ///         mass: &mass,
    ///         inputs: &inputs,
    ///     })?;
    ///     let eig = lin.eigenvalues()?;
    ///     let w2 = eig[0].re * eig[0].re - eig[0].im * eig[0].im;
    ///     assert_relative_eq!(w2, sign * g / l, max_relative = 1e-14);
    ///     assert_relative_eq!(lin.b[(1, 0)], 1.0 / (m * l * l), max_relative = 1e-15);
    /// }
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn second_order(s: &SecondOrder<'_>) -> Result<StateSpace, StateSpaceError> {
        let n = s.accelerations.len();
        shape("∂q̈/∂q", s.by_q, n, n)?;
        shape("∂q̈/∂q̇", s.by_qdot, n, n)?;
        shape("mass matrix", s.mass, n, n)?;
        let m = s.inputs.ncols();
        shape("input map G", s.inputs, n, m)?;
        check_finite("q̈", n, |r, _| s.accelerations[r], 1)?;
        check_finite("mass matrix entry", n, |r, c| s.mass[(r, c)], n)?;
        check_finite("input map entry", n, |r, c| s.inputs[(r, c)], m)?;
        let a = DMatrix::from_fn(2 * n, 2 * n, |r, c| match (r < n, c < n) {
            (true, _) => f64::from(u8::from(c == r + n)),
            (false, true) => s.by_q[(r - n, c)],
            (false, false) => s.by_qdot[(r - n, c - n)],
        });
        check_finite("Jacobian entry", 2 * n, |r, c| a[(r, c)], 2 * n)?;
        check_residual("q̈", s.accelerations, &a)?;
        let lu = s.mass.clone().lu();
        let Some(m_inv_g) = lu.solve(s.inputs) else {
            return Err(LinalgError::InvalidParameter {
                name: "mass matrix determinant",
                value: lu.determinant(),
            }
            .into());
        };
        let b = DMatrix::from_fn(
            2 * n,
            m,
            |r, c| if r < n { 0.0 } else { m_inv_g[(r - n, c)] },
        );
        StateSpace::new(a, b)
    }

    /// The linearisation of ẋ = f(x, u) about (x₀, u₀) by central differences with
    /// Richardson extrapolation ([`super::jacobian`]: about 1e-12 relative for smooth f):
    /// the fallback for a model without derived Jacobians. `f(x, u, out)` writes ẋ.
    ///
    /// # Errors
    /// [`StateSpaceError::NotOperatingPoint`] naming the largest |ẋ_i| at (x₀, u₀) if it
    /// exceeds `tol` · max(1, max |A_ij|) (pass [`OPERATING_POINT_TOLERANCE`]);
    /// [`LinalgError::NonFinite`] for a non-finite x₀, u₀ or value of f;
    /// [`LinalgError::InvalidParameter`] unless `tol` is finite and > 0.
    ///
    /// # Examples
    ///
    /// A body spinning about its axis of largest moment, with a body-fixed couple τ as the
    /// input (I ω̇ = (I ω) × ω + τ): the wobble at ω₃ √((I₃ − I₁)(I₃ − I₂)/(I₁ I₂)), and
    /// B = [I⁻¹].
    ///
    /// ```
    /// use approx::assert_relative_eq;
    /// use precess_core::linalg::{OPERATING_POINT_TOLERANCE, StateSpace};
    ///
    /// let (i, w3) = ([1.0, 2.0, 3.0], 4.0);
    /// let euler = |w: &[f64], tau: &[f64], out: &mut [f64]| {
    ///     out[0] = ((i[1] - i[2]) * w[1] * w[2] + tau[0]) / i[0];
    ///     out[1] = ((i[2] - i[0]) * w[2] * w[0] + tau[1]) / i[1];
    ///     out[2] = ((i[0] - i[1]) * w[0] * w[1] + tau[2]) / i[2];
    /// };
    /// let lin = StateSpace::from_fn(euler, &[0.0, 0.0, w3], &[0.0; 3], OPERATING_POINT_TOLERANCE)?;
    /// let wobble = lin.eigenvalues()?.iter().map(|z| z.im).fold(0.0, f64::max);
    /// let want = w3 * ((i[2] - i[0]) * (i[2] - i[1]) / (i[0] * i[1])).sqrt();
    /// assert_relative_eq!(wobble, want, max_relative = 1e-11);
    /// assert_relative_eq!(lin.b[(2, 2)], 1.0 / 3.0, max_relative = 1e-11);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn from_fn(
        mut f: impl FnMut(&[f64], &[f64], &mut [f64]),
        x0: &[f64],
        u0: &[f64],
        tol: f64,
    ) -> Result<StateSpace, StateSpaceError> {
        if !(tol.is_finite() && tol > 0.0) {
            return Err(LinalgError::InvalidParameter {
                name: "operating-point tolerance",
                value: tol,
            }
            .into());
        }
        let (n, m) = (x0.len(), u0.len());
        check_finite("state", n, |r, _| x0[r], 1)?;
        check_finite("input", m, |r, _| u0[r], 1)?;
        // One Jacobian over z = (x, u) of the map z ↦ (f(x, u), 0).
        let z0: Vec<f64> = x0.iter().chain(u0).copied().collect();
        let full = jacobian(
            |z, out| {
                let (x, u) = z.split_at(n);
                f(x, u, &mut out[..n]);
                out[n..].fill(0.0);
            },
            &z0,
        )?;
        let a = full.view((0, 0), (n, n)).into_owned();
        let b = full.view((0, n), (n, m)).into_owned();
        let mut rate = vec![0.0; n];
        f(x0, u0, &mut rate);
        check_finite("ẋ at the operating point", n, |r, _| rate[r], 1)?;
        check_residual_with("ẋ", &rate, &a, tol)?;
        StateSpace::new(a, b)
    }

    /// The dimension of the state.
    pub fn states(&self) -> usize {
        self.a.nrows()
    }

    /// The number of inputs.
    pub fn inputs(&self) -> usize {
        self.b.ncols()
    }

    /// The eigenvalues of A, as [`super::eigenvalues`] orders them.
    ///
    /// # Errors
    /// As [`super::eigenvalues`].
    pub fn eigenvalues(&self) -> Result<Vec<Complex<f64>>, LinalgError> {
        eigenvalues(&self.a)
    }
}

fn shape(
    quantity: &'static str,
    m: &DMatrix<f64>,
    rows: usize,
    cols: usize,
) -> Result<(), StateSpaceError> {
    if m.shape() == (rows, cols) {
        Ok(())
    } else {
        Err(StateSpaceError::Shape {
            quantity,
            rows: m.nrows(),
            cols: m.ncols(),
            expected_rows: rows,
            expected_cols: cols,
        })
    }
}

fn check_residual(
    quantity: &'static str,
    residual: &[f64],
    a: &DMatrix<f64>,
) -> Result<(), StateSpaceError> {
    check_residual_with(quantity, residual, a, OPERATING_POINT_TOLERANCE)
}

/// Refuses a residual above `tol` · max(1, max |A_ij|): the scale of ẋ one unit away.
fn check_residual_with(
    quantity: &'static str,
    residual: &[f64],
    a: &DMatrix<f64>,
    tol: f64,
) -> Result<(), StateSpaceError> {
    let allowed = tol * a.amax().max(1.0);
    let worst = residual
        .iter()
        .enumerate()
        .max_by(|x, y| x.1.abs().total_cmp(&y.1.abs()));
    match worst {
        Some((component, &r)) if r.abs() > allowed => Err(StateSpaceError::NotOperatingPoint {
            quantity,
            component,
            residual: r,
            allowed,
        }),
        _ => Ok(()),
    }
}
