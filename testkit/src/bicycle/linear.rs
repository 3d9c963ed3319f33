//! The linearised lateral equations M q̈ + v C₁ q̇ + (g K₀ + v² K₂) q = 0, q = (φ, δ): the
//! paper's printed values and tables, [`Whipple::linearise`] which recovers them from the
//! nonlinear model, the eigenvalues against the forward speed v, and the weave and capsize
//! speeds.

use precess::lagrange::LagrangeError;
use precess::linalg::{CrossingError, LinalgError, find_crossing};
use precess::models::bicycle::Canonical;
use precess::nalgebra::{Complex, Matrix2, Matrix4};

use super::Whipple;

/// The weave speed the paper gives (Table 2), m/s.
pub const WEAVE_SPEED: f64 = 4.29238253634111;
/// The capsize speed the paper gives (Table 2), m/s.
pub const CAPSIZE_SPEED: f64 = 6.02426201538837;
/// The weave pair's frequency at the weave speed, ±i 3.43503384866144 rad/s (Table 2).
pub const WEAVE_FREQUENCY: f64 = 3.43503384866144;
/// The eigenvalues at rest (Table 2): the two inverted-pendulum pairs ±3.13…, ±5.53….
pub const STANDSTILL: [f64; 4] = [
    3.13164324790656,
    -3.13164324790656,
    5.53094371765393,
    -5.53094371765393,
];

/// Table 2 of Meijaard et al. (2007): the eigenvalues at v = 1 … 10 m/s — the capsize mode (real), the
/// weave pair (re ± i im) and the castering mode (real).
pub const TABLE_2: [(f64, f64, f64, f64); 10] = [
    (
        -3.13423125066578,
        3.52696170990070,
        0.80774027519930,
        -7.11008014637442,
    ),
    (
        -3.07158645641514,
        2.68234517512745,
        1.68066296590675,
        -8.67387984831735,
    ),
    (
        -2.63366137253667,
        1.70675605663975,
        2.31582447384325,
        -10.3510146724592,
    ),
    (
        -1.42944427361326,
        0.41325331521125,
        3.07910818603206,
        -12.1586142657645,
    ),
    (
        -0.32286642900409,
        -0.77534188219585,
        4.46486771378823,
        -14.0783896927982,
    ),
    (
        -0.00406690076970,
        -1.52644486584142,
        5.87673060598709,
        -16.0853712309803,
    ),
    (
        0.10268170574766,
        -2.13875644258362,
        7.19525913329805,
        -18.15788466125262,
    ),
    (
        0.14327879765713,
        -2.69348683581097,
        8.46037971396931,
        -20.27940894394569,
    ),
    (
        0.15790184030917,
        -3.21675402252485,
        9.69377351531791,
        -22.43788559040858,
    ),
    (
        0.16105338653172,
        -3.72016840437287,
        10.90681139476287,
        -24.62459635017404,
    ),
];

/// The paper's four matrices and g.
#[derive(Clone, Debug, PartialEq)]
pub struct Linear {
    /// Mass matrix M.
    pub m: Matrix2<f64>,
    /// C₁, the velocity-proportional (gyroscopic and damping-like) matrix.
    pub c1: Matrix2<f64>,
    /// K₀, the gravity stiffness (per unit g).
    pub k0: Matrix2<f64>,
    /// K₂, the velocity-squared stiffness.
    pub k2: Matrix2<f64>,
    /// Gravity g.
    pub g: f64,
}

impl Linear {
    pub(super) fn zero() -> Linear {
        Linear {
            m: Matrix2::zeros(),
            c1: Matrix2::zeros(),
            k0: Matrix2::zeros(),
            k2: Matrix2::zeros(),
            g: 0.0,
        }
    }

    /// The values the paper prints (Table 2 and eq. 5.3–5.6 of Meijaard et al. 2007), to
    /// the fifteen digits given.
    pub fn published() -> Linear {
        Linear {
            m: Matrix2::new(
                80.81722,
                2.31941332208709,
                2.31941332208709,
                0.29784188199686,
            ),
            c1: Matrix2::new(0.0, 33.86641391492494, -0.85035641456978, 1.68540397397560),
            k0: Matrix2::new(
                -80.95,
                -2.59951685249872,
                -2.59951685249872,
                -0.80329488458618,
            ),
            k2: Matrix2::new(0.0, 76.59734589573222, 0.0, 2.65431523794604),
            g: 9.81,
        }
    }

    /// The library's form of the same matrices (`precess::models::bicycle::Canonical`),
    /// whose state matrix, eigenvalues and root finder these methods use.
    ///
    /// # Errors
    /// [`LinalgError`] for a non-finite entry or a singular M.
    pub fn canonical(&self) -> Result<Canonical, LinalgError> {
        Canonical::new(self.m, self.c1, self.k0, self.k2, self.g)
    }

    /// The state matrix of (φ, δ, φ̇, δ̇) at speed v, or `None` if M is singular.
    pub fn state_matrix(&self, v: f64) -> Option<Matrix4<f64>> {
        self.canonical().ok()?.state_matrix(v).ok()
    }

    /// The four eigenvalues at speed v, by decreasing real part.
    ///
    /// # Errors
    /// [`LinalgError`] for a singular M or from the eigenvalue routine.
    pub fn eigenvalues(&self, v: f64) -> Result<Vec<Complex<f64>>, LinalgError> {
        self.canonical()?.eigenvalues(v)
    }

    /// The weave speed: where the real part of the oscillatory pair crosses zero in
    /// [lo, hi] (`linalg::find_crossing`, to rounding); `None` without a sign change (or
    /// where the eigenvalues fail).
    pub fn weave_speed(&self, lo: f64, hi: f64) -> Option<f64> {
        self.mode_crossing(lo, hi, |z| z.im.abs() > 1e-9)
    }

    /// The capsize speed: where the largest real eigenvalue (the capsize mode) crosses
    /// zero in [lo, hi]; `None` without a sign change.
    pub fn capsize_speed(&self, lo: f64, hi: f64) -> Option<f64> {
        self.mode_crossing(lo, hi, |z| z.im.abs() <= 1e-9)
    }

    /// Where the largest real part among the eigenvalues `mode` selects crosses zero.
    fn mode_crossing(&self, lo: f64, hi: f64, mode: impl Fn(&Complex<f64>) -> bool) -> Option<f64> {
        let lin = self.canonical().ok()?;
        let at = |v: f64| -> Result<f64, CrossingError> {
            let eig = lin.eigenvalues(v).map_err(|source| CrossingError::Linalg {
                parameter: v,
                source,
            })?;
            Ok(eig
                .iter()
                .filter(|z| mode(z))
                .map(|z| z.re)
                .fold(f64::NAN, f64::max))
        };
        find_crossing(at, lo, hi, 1e-15).ok().map(|c| c.parameter)
    }
}

impl Whipple {
    /// Lateral right-hand side r_(φ, δ) of the reduced equations on the constraint, at roll
    /// φ, steer δ, their rates, and speed v.
    fn lateral(&self, x: [f64; 4], v: f64) -> Result<[f64; 2], LagrangeError> {
        let mut q = [0.0; 8];
        q[3] = x[0];
        q[5] = x[1];
        self.close_front_contact(&mut q)?;
        let (_, r) = self.reduced(&q, &[x[2], x[3], -v / self.rear_radius])?;
        Ok([r[0], r[1]])
    }

    /// The linearised lateral equations about the upright straight run, in the paper's
    /// form M q̈ + v C₁ q̇ + (g K₀ + v² K₂) q = 0 with q = (φ, δ).
    ///
    /// r is r₀(q) + (a quadratic form in u): the gravity part, proportional to g, and the
    /// inertial part, exactly quadratic in the speeds. So K₀ = −∂r/∂q at v = 0 over g;
    /// K₂ = −(∂r/∂q at v = 1 minus at v = 0); C₁ = −∂r/∂q̇ at v = 1, where a central
    /// difference of a quadratic is exact (step 1). The position derivatives are central
    /// differences extrapolated twice by Richardson (steps 10⁻², ½·10⁻², ¼·10⁻²: error
    /// O(h⁶) ≈ 10⁻¹², rounding ≈ 10⁻¹⁶ · |r|/h since r vanishes at the upright), the pitch
    /// re-solved by Newton at every point.
    ///
    /// # Errors
    /// As [`Whipple::close_front_contact`] and [`Whipple::reduced`].
    pub fn linearise(&self) -> Result<Linear, LagrangeError> {
        let mut q = [0.0; 8];
        self.close_front_contact(&mut q)?;
        let (k, _) = self.reduced(&q, &[0.0, 0.0, 0.0])?;
        let mut lin = Linear {
            g: self.gravity,
            ..Linear::zero()
        };
        for i in 0..2 {
            for j in 0..2 {
                lin.m[(i, j)] = k[(i, j)];
            }
        }
        for j in 0..2 {
            let at_rest = self.position_derivative(j, 0.0)?;
            let moving = self.position_derivative(j, 1.0)?;
            let mut up = [0.0; 4];
            up[2 + j] = 1.0;
            let mut down = [0.0; 4];
            down[2 + j] = -1.0;
            let (rp, rm) = (self.lateral(up, 1.0)?, self.lateral(down, 1.0)?);
            for i in 0..2 {
                lin.k0[(i, j)] = -at_rest[i] / self.gravity;
                lin.k2[(i, j)] = -(moving[i] - at_rest[i]);
                lin.c1[(i, j)] = -(rp[i] - rm[i]) / 2.0;
            }
        }
        Ok(lin)
    }

    /// ∂r/∂(φ, δ)_j at the upright run at speed v, Richardson-extrapolated.
    fn position_derivative(&self, j: usize, v: f64) -> Result<[f64; 2], LagrangeError> {
        let central = |h: f64| -> Result<[f64; 2], LagrangeError> {
            let mut xp = [0.0; 4];
            xp[j] = h;
            let mut xm = [0.0; 4];
            xm[j] = -h;
            let (p, m) = (self.lateral(xp, v)?, self.lateral(xm, v)?);
            Ok([(p[0] - m[0]) / (2.0 * h), (p[1] - m[1]) / (2.0 * h)])
        };
        let h = 1e-2;
        let d = [central(h)?, central(h / 2.0)?, central(h / 4.0)?];
        let mut out = [0.0; 2];
        for (i, o) in out.iter_mut().enumerate() {
            let r1 = (4.0 * d[1][i] - d[0][i]) / 3.0;
            let r2 = (4.0 * d[2][i] - d[1][i]) / 3.0;
            *o = (16.0 * r2 - r1) / 15.0;
        }
        Ok(out)
    }
}
