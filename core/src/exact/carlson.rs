//! Carlson's symmetric elliptic integrals R_F, R_J and the incomplete integrals F and Π
//! built on them (Carlson, Numer. Algorithms 10, 1995; DLMF §19.36).
//!
//! The duplication theorem shrinks the spread of the arguments by 4 per step; a fifth-order
//! Taylor tail then gives full double precision.

use super::elliptic::Jacobi;
use super::error::{ExactError, finite};

/// R_F(x, y, z) = ½ ∫₀^∞ dt / √((t+x)(t+y)(t+z)), for x, y, z ≥ 0 with at most one zero.
///
/// ```
/// // R_F(1, 2, 0) = 1.3110287771461 (Carlson 1995, test values).
/// let v = precess_core::exact::carlson::rf(1.0, 2.0, 0.0)?;
/// approx::assert_relative_eq!(v, 1.311_028_777_146_059_9, max_relative = 1e-15);
/// # Ok::<(), precess_core::exact::ExactError>(())
/// ```
///
/// # Errors
/// [`ExactError::CarlsonDomain`] for a negative argument or two zeros;
/// [`ExactError::NonFinite`] for NaN or ∞.
pub fn rf(x: f64, y: f64, z: f64) -> Result<f64, ExactError> {
    for v in [x, y, z] {
        finite("rf argument", v)?;
    }
    let zeros = [x, y, z].iter().filter(|&&v| v == 0.0).count();
    if x < 0.0 || y < 0.0 || z < 0.0 || zeros > 1 {
        return Err(ExactError::CarlsonDomain { x, y, z });
    }
    let (mut x, mut y, mut z) = (x, y, z);
    let mut a = (x + y + z) / 3.0;
    let mut q =
        (3.0 * f64::EPSILON).powf(-1.0 / 6.0) * (a - x).abs().max((a - y).abs()).max((a - z).abs());
    while q >= a.abs() {
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let lam = sx * sy + sx * sz + sy * sz;
        x = 0.25 * (x + lam);
        y = 0.25 * (y + lam);
        z = 0.25 * (z + lam);
        a = 0.25 * (a + lam);
        q *= 0.25;
    }
    // (A₀ − x₀)/(4ⁿ Aₙ) equals (Aₙ − xₙ)/Aₙ: the deviations shrink with the duplication.
    let xm = (a - x) / a;
    let ym = (a - y) / a;
    let zm = -xm - ym;
    let e2 = xm * ym - zm * zm;
    let e3 = xm * ym * zm;
    Ok((1.0 - e2 / 10.0 + e3 / 14.0 + e2 * e2 / 24.0 - 3.0 * e2 * e3 / 44.0) / a.sqrt())
}

/// R_J(x, y, z, p) = 3/2 ∫₀^∞ dt / ((t+p) √((t+x)(t+y)(t+z))), for x, y, z ≥ 0
/// (at most one zero) and p > 0.
///
/// ```
/// // R_J(0, 1, 2, 3) = 0.77688623778582 (Carlson 1995, test values).
/// let v = precess_core::exact::carlson::rj(0.0, 1.0, 2.0, 3.0)?;
/// approx::assert_relative_eq!(v, 0.776_886_237_785_82, max_relative = 1e-13);
/// # Ok::<(), precess_core::exact::ExactError>(())
/// ```
///
/// # Errors
/// [`ExactError::CarlsonDomain`] outside the domain; [`ExactError::NonFinite`] for NaN or ∞.
pub fn rj(x: f64, y: f64, z: f64, p: f64) -> Result<f64, ExactError> {
    for v in [x, y, z, p] {
        finite("rj argument", v)?;
    }
    let zeros = [x, y, z].iter().filter(|&&v| v == 0.0).count();
    if x < 0.0 || y < 0.0 || z < 0.0 || zeros > 1 || p <= 0.0 {
        return Err(ExactError::CarlsonDomain { x, y, z });
    }
    let (mut x, mut y, mut z, mut p) = (x, y, z, p);
    let mut a = (x + y + z + 2.0 * p) / 5.0;
    let delta = (p - x) * (p - y) * (p - z);
    let mut q = (0.25 * f64::EPSILON).powf(-1.0 / 6.0)
        * (a - x)
            .abs()
            .max((a - y).abs())
            .max((a - z).abs())
            .max((a - p).abs());
    let (mut sum, mut pow4) = (0.0, 1.0);
    while q >= a.abs() {
        let (sx, sy, sz, sp) = (x.sqrt(), y.sqrt(), z.sqrt(), p.sqrt());
        let lam = sx * sy + sx * sz + sy * sz;
        let d = (sp + sx) * (sp + sy) * (sp + sz);
        let e = delta * pow4 * pow4 * pow4 / (d * d);
        sum += pow4 / d * rc1(e)?;
        x = 0.25 * (x + lam);
        y = 0.25 * (y + lam);
        z = 0.25 * (z + lam);
        p = 0.25 * (p + lam);
        a = 0.25 * (a + lam);
        q *= 0.25;
        pow4 *= 0.25;
    }
    let xm = (a - x) / a;
    let ym = (a - y) / a;
    let zm = (a - z) / a;
    let pm = -(xm + ym + zm) / 2.0;
    let e2 = xm * ym + xm * zm + ym * zm - 3.0 * pm * pm;
    let e3 = xm * ym * zm + 2.0 * e2 * pm + 4.0 * pm * pm * pm;
    let e4 = (2.0 * xm * ym * zm + e2 * pm + 3.0 * pm * pm * pm) * pm;
    let e5 = xm * ym * zm * pm * pm;
    let series = 1.0 - 3.0 * e2 / 14.0 + e3 / 6.0 + 9.0 * e2 * e2 / 88.0
        - 3.0 * e4 / 22.0
        - 9.0 * e2 * e3 / 52.0
        + 3.0 * e5 / 26.0;
    Ok(pow4 * series / (a * a.sqrt()) + 6.0 * sum)
}

/// R_C(1, 1 + e) = R_F(1, 1+e, 1+e) in closed form: atan(√e)/√e for e > 0, atanh for e < 0.
fn rc1(e: f64) -> Result<f64, ExactError> {
    if e.abs() < 1e-3 {
        // Series keeps the digits that the closed forms lose as e → 0.
        return Ok(
            1.0 - e / 3.0 + e * e / 5.0 - e * e * e / 7.0 + e.powi(4) / 9.0 - e.powi(5) / 11.0,
        );
    }
    if e > 0.0 {
        let s = e.sqrt();
        Ok(s.atan() / s)
    } else if e > -1.0 {
        let s = (-e).sqrt();
        Ok(s.atanh() / s)
    } else {
        Err(ExactError::CarlsonDomain {
            x: 1.0,
            y: 1.0 + e,
            z: 1.0 + e,
        })
    }
}

/// Splits φ = jπ + φ_r with |φ_r| ≤ π/2; returns (j, sin φ_r, cos φ_r ≥ 0).
fn reduce_amplitude(phi: f64) -> (f64, f64, f64) {
    let j = (phi / core::f64::consts::PI).round();
    let r = phi - j * core::f64::consts::PI;
    let (s, c) = r.sin_cos();
    (j, s, c.abs())
}

/// Incomplete integral of the first kind F(φ | m) = ∫₀^φ dθ / √(1 − m sin²θ), from m_c.
///
/// Uses 1 − m sin²φ = cos²φ + m_c sin²φ, which has no cancellation near m = 1; for any real
/// φ through F(φ + jπ) = F(φ) + 2jK.
///
/// ```
/// // F(φ | 0) = φ.
/// let f = precess_core::exact::carlson::ellip_f(0.7, 1.0)?;
/// approx::assert_relative_eq!(f, 0.7, max_relative = 1e-15);
/// # Ok::<(), precess_core::exact::ExactError>(())
/// ```
///
/// # Errors
/// [`ExactError::ParameterOutOfRange`], [`ExactError::NonFinite`]; |φ| ≥ π/2 needs m_c > 0.
pub fn ellip_f(phi: f64, mc: f64) -> Result<f64, ExactError> {
    finite("phi", phi)?;
    let jac = Jacobi::new(mc)?;
    let (j, s, c) = reduce_amplitude(phi);
    let base = if s == 0.0 {
        0.0
    } else {
        s * rf(c * c, c * c + mc * s * s, 1.0)?
    };
    if j == 0.0 {
        Ok(base)
    } else {
        Ok(2.0 * j * jac.k() + base)
    }
}

/// F(φ | m) from the amplitude's sine and cosine, φ ∈ (−π, π]: no digits of a small cos φ
/// are lost to forming φ first (what inverting sn near u = K needs when m_c is tiny).
///
/// (s, c) need not be normalised; they are scaled to s² + c² = 1.
///
/// ```
/// use precess_core::exact::carlson::{ellip_f, ellip_f_sc};
/// let phi = 2.5f64;
/// let (s, c) = phi.sin_cos();
/// approx::assert_relative_eq!(ellip_f_sc(s, c, 0.3)?, ellip_f(phi, 0.3)?, max_relative = 1e-15);
/// # Ok::<(), precess_core::exact::ExactError>(())
/// ```
///
/// # Errors
/// [`ExactError::NonFinite`], [`ExactError::ParameterOutOfRange`], and
/// [`ExactError::CarlsonDomain`] for s = c = 0 or |φ| > π/2 with m_c = 0.
pub fn ellip_f_sc(s: f64, c: f64, mc: f64) -> Result<f64, ExactError> {
    finite("sin φ", s)?;
    finite("cos φ", c)?;
    let r = s.hypot(c);
    if r == 0.0 {
        return Err(ExactError::CarlsonDomain { x: s, y: c, z: mc });
    }
    let jac = Jacobi::new(mc)?;
    let (s, c) = (s / r, c / r);
    if s == 0.0 {
        return Ok(if c > 0.0 { 0.0 } else { 2.0 * jac.k() });
    }
    let base = s * rf(c * c, c * c + mc * s * s, 1.0)?;
    if c >= 0.0 {
        Ok(base)
    } else {
        // φ = ±π − φ_r: F(φ) = ±2K − F(φ_r).
        if mc == 0.0 {
            return Err(ExactError::CarlsonDomain { x: s, y: c, z: mc });
        }
        Ok(s.signum() * 2.0 * jac.k() - base)
    }
}

/// Incomplete integral of the third kind
/// Π(n; φ | m) = ∫₀^φ dθ / ((1 − n sin²θ) √(1 − m sin²θ)), from m_c, for n sin²φ < 1 on the
/// reduced amplitude and |φ| ≤ π/2 (the free-body attitude needs no more).
///
/// Π = s R_F(c², Δ², 1) + (n/3) s³ R_J(c², Δ², 1, 1 − n s²), s = sin φ, c = cos φ,
/// Δ² = c² + m_c s².
///
/// ```
/// // n = 0 reduces to F.
/// use precess_core::exact::carlson::{ellip_f, ellip_pi};
/// approx::assert_relative_eq!(ellip_pi(0.0, 1.0, 0.3)?, ellip_f(1.0, 0.3)?, max_relative = 1e-15);
/// # Ok::<(), precess_core::exact::ExactError>(())
/// ```
///
/// # Errors
/// [`ExactError::NonFinite`], [`ExactError::CarlsonDomain`] when 1 − n sin²φ ≤ 0 or
/// |φ| > π/2.
pub fn ellip_pi(n: f64, phi: f64, mc: f64) -> Result<f64, ExactError> {
    finite("phi", phi)?;
    finite("n", n)?;
    if !(0.0..=1.0).contains(&mc) {
        return Err(ExactError::ParameterOutOfRange { mc });
    }
    if phi.abs() > core::f64::consts::FRAC_PI_2 {
        return Err(ExactError::CarlsonDomain {
            x: phi,
            y: n,
            z: mc,
        });
    }
    let (s, c) = phi.sin_cos();
    if s == 0.0 {
        return Ok(0.0);
    }
    let (c2, d2) = (c * c, c * c + mc * s * s);
    let base = s * rf(c2, d2, 1.0)?;
    if n == 0.0 {
        return Ok(base);
    }
    Ok(base + n / 3.0 * s * s * s * rj(c2, d2, 1.0, 1.0 - n * s * s)?)
}
