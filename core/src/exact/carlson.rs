//! Carlson's symmetric elliptic integrals R_F, R_J and the incomplete integrals F and Π
//! built on them (Carlson, Numer. Algorithms 10, 1995; DLMF §19.36).
//!
//! The duplication theorem shrinks the spread of the arguments by 4 per step; a fifth-order
//! Taylor tail then gives full double precision.

use super::elliptic::Jacobi;
use super::error::{ExactError, finite};
use super::scaling::{exponent, ldexp, pow2};

/// R_F(x, y, z) = ½ ∫₀^∞ dt / √((t+x)(t+y)(t+z)), for x, y, z ≥ 0 with at most one zero,
/// over the whole f64 range.
///
/// ```
/// use precess_core::exact::carlson::rf;
/// // R_F(1, 2, 0) = 1.3110287771461 (Carlson 1995, test values).
/// approx::assert_relative_eq!(rf(1.0, 2.0, 0.0)?, 1.311_028_777_146_059_9, max_relative = 1e-15);
/// // Homogeneous of degree −½: R_F(λx, λy, λz) = R_F(x, y, z)/√λ, even at λ = 1e308.
/// approx::assert_relative_eq!(rf(1e308, 1e308, 1e308)?, 1e-154, max_relative = 1e-15);
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
    let largest = x.max(y).max(z);
    if (RF_SAFE_LOW..=RF_SAFE_HIGH).contains(&largest) {
        Ok(rf_duplication(x, y, z))
    } else {
        // Beyond 2¹⁰⁰⁰ the sum x + y + z overflows and the duplication never ends; below
        // 2⁻¹⁰⁰⁰ subnormal arguments lose digits. The square roots scale without loss.
        Ok(rf_roots(x.sqrt(), y.sqrt(), z.sqrt()))
    }
}

/// The largest argument of R_F that the duplication takes directly, without rescaling.
const RF_SAFE_HIGH: f64 = f64::from_bits((1023 + 1000) << 52); // 2¹⁰⁰⁰
/// The smallest largest-argument of R_F taken directly.
const RF_SAFE_LOW: f64 = f64::from_bits((1023 - 1000) << 52); // 2⁻¹⁰⁰⁰

/// Below this ratio to the largest, a square root's square is negligible in R_F and R_J
/// (and could underflow): 2⁻⁴⁸⁰, whose square 2⁻⁹⁶⁰ is far below f64's relative precision.
pub(crate) const SMALL_ROOT: f64 = f64::from_bits((1023 - 480) << 52); // 2⁻⁴⁸⁰

/// Carlson's duplication for R_F, for arguments checked and in a safe range.
fn rf_duplication(x: f64, y: f64, z: f64) -> f64 {
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
    (1.0 - e2 / 10.0 + e3 / 14.0 + e2 * e2 / 24.0 - 3.0 * e2 * e3 / 44.0) / a.sqrt()
}

/// R_F(a², b², c²) from the square roots a, b, c ≥ 0 (finite, at most one zero), for any
/// magnitudes: scaled by the power of two of the largest (R_F(s²·) = R_F(·)/s), and when the
/// two smaller are below [`SMALL_ROOT`] of the largest r, the limit
/// R_F(p², q², r²) = ln(4r/(p + q))/r + O((q/r)² ln), which no f64 square could carry.
pub(crate) fn rf_roots(a: f64, b: f64, c: f64) -> f64 {
    let mut v = [a, b, c];
    v.sort_by(f64::total_cmp);
    let [p, q, r] = v;
    if q < SMALL_ROOT * r {
        // Logarithms of the unscaled roots: r/(p + q) itself may overflow.
        return (4f64.ln() + r.ln() - (p + q).ln()) / r;
    }
    let s = pow2(exponent(r));
    let (p, q, r) = (p / s, q / s, r / s);
    rf_duplication(p * p, q * q, r * r) / s
}

/// R_J(x, y, z, p) = 3/2 ∫₀^∞ dt / ((t+p) √((t+x)(t+y)(t+z))), for x, y, z ≥ 0
/// (at most one zero) and p > 0, over the whole f64 range.
///
/// ```
/// use precess_core::exact::carlson::rj;
/// // R_J(0, 1, 2, 3) = 0.77688623778582 (Carlson 1995, test values).
/// approx::assert_relative_eq!(rj(0.0, 1.0, 2.0, 3.0)?, 0.776_886_237_785_82, max_relative = 1e-13);
/// // Homogeneous of degree −3/2: R_J(λ·) = R_J(·)/λ^{3/2}, also at λ = 2¹⁰⁰⁰.
/// let l = 2f64.powi(1000);
/// approx::assert_relative_eq!(
///     rj(0.0, l, 2.0 * l, 3.0 * l)?,
///     0.776_886_237_785_82 / 2f64.powi(1500),
///     max_relative = 1e-13
/// );
/// # Ok::<(), precess_core::exact::ExactError>(())
/// ```
///
/// # Errors
/// [`ExactError::CarlsonDomain`] outside the domain; [`ExactError::NonFinite`] for NaN or ∞;
/// [`ExactError::CarlsonRange`] when the value overflows f64 or the arguments span more
/// orders of magnitude than one power-of-two scaling can bring into range.
pub fn rj(x: f64, y: f64, z: f64, p: f64) -> Result<f64, ExactError> {
    for v in [x, y, z, p] {
        finite("rj argument", v)?;
    }
    let zeros = [x, y, z].iter().filter(|&&v| v == 0.0).count();
    if x < 0.0 || y < 0.0 || z < 0.0 || zeros > 1 || p <= 0.0 {
        return Err(ExactError::CarlsonDomain { x, y, z });
    }
    let out_of_range = ExactError::CarlsonRange { x, y, z, p };
    let largest = x.max(y).max(z).max(p);
    let value = if (RJ_SAFE_LOW..=RJ_SAFE_HIGH).contains(&largest) {
        rj_in_range(x, y, z, p)?
    } else {
        // Beyond 2³⁰⁰ the products (p − x)(p − y)(p − z) and d² of the duplication overflow
        // (rj(1, 2, 3, 1e308) went through NaN); below 2⁻³⁰⁰ they underflow. Scale by 4ᵏ,
        // R_J(4ᵏ ·) = 2⁻³ᵏ R_J(·): up to [1, 4) when all are tiny (exact), down only as far
        // as 2³⁰⁰ when the largest is huge (the small ones keep their digits).
        let e = exponent(largest);
        let k = if e > 0 {
            (e - 298).div_euclid(2)
        } else {
            e.div_euclid(2)
        };
        let scaled = [x, y, z, p].map(|v| ldexp(v, -2 * k));
        let zeros = scaled[..3].iter().filter(|&&v| v == 0.0).count();
        if zeros > 1 || scaled[3] == 0.0 {
            return Err(out_of_range);
        }
        let [xs, ys, zs, ps] = scaled;
        // 2⁻³ᵏ in two halves: the scaled value may be far outside f64 while the result is not.
        let half = -3 * k / 2;
        ldexp(ldexp(rj_in_range(xs, ys, zs, ps)?, half), -3 * k - half)
    };
    if value.is_finite() {
        Ok(value)
    } else {
        Err(out_of_range)
    }
}

/// The largest argument of R_J that the duplication takes directly: its products of three
/// differences stay below 2⁹⁰⁶.
const RJ_SAFE_HIGH: f64 = f64::from_bits((1023 + 300) << 52); // 2³⁰⁰
/// The smallest largest-argument of R_J taken directly.
const RJ_SAFE_LOW: f64 = f64::from_bits((1023 - 300) << 52); // 2⁻³⁰⁰

/// Above this ratio of p to the largest of x, y, z the duplication would crawl (p shrinks by
/// 4 per step while x, y, z stay put, and the factors 4⁻³ⁿ underflow before it ends).
const RJ_SLOW_RATIO: f64 = f64::from_bits((1023 + 40) << 52); // 2⁴⁰

/// R_J for arguments checked and in a safe range. For p far above x, y, z it goes through
/// DLMF 19.21.12 with x the largest of the three:
/// (p − x) R_J(x, y, z, p) + (q − x) R_J(x, y, z, q) = 3 R_F(x, y, z) − 3 R_C(yz/x, pq/x),
/// (p − x)(q − x) = (y − x)(z − x), whose q lies beside x, y, z, where the duplication is
/// quick; the right-hand side is dominated by 3 R_F, so nothing cancels.
fn rj_in_range(x: f64, y: f64, z: f64, p: f64) -> Result<f64, ExactError> {
    if p <= RJ_SLOW_RATIO * x.max(y).max(z) {
        return rj_duplication(x, y, z, p);
    }
    let mut v = [x, y, z];
    v.sort_by(|a, b| b.total_cmp(a));
    let [x, y, z] = v;
    let q = x + (y - x) * (z - x) / (p - x);
    let rc_term = rc(y * z / x, p * q / x);
    // R_J(x, y, z, q) has all four arguments beside x: scaled by 4ᵏ to x ≈ 1 its products
    // cannot underflow, R_J(4ᵏ ·) = 2⁻³ᵏ R_J(·); the factor is applied after (q − x), since
    // R_J alone may exceed f64 where the product does not.
    let k = exponent(x).div_euclid(2);
    let [xs, ys, zs, qs] = [x, y, z, q].map(|v| ldexp(v, -2 * k));
    let q_term = ldexp((q - x) * rj_duplication(xs, ys, zs, qs)?, -3 * k);
    Ok((3.0 * rf(x, y, z)? - 3.0 * rc_term - q_term) / (p - x))
}

/// Carlson's duplication for R_J, for arguments checked and in a safe range.
fn rj_duplication(x: f64, y: f64, z: f64, p: f64) -> Result<f64, ExactError> {
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
/// use precess_core::exact::{ExactError, carlson::ellip_f};
/// // F(φ | 0) = φ.
/// approx::assert_relative_eq!(ellip_f(0.7, 1.0)?, 0.7, max_relative = 1e-15);
/// // At m = 1 the integral diverges at φ = π/2: beyond it there is no value.
/// assert_eq!(ellip_f(2.0, 0.0), Err(ExactError::Diverges { phi: 2.0 }));
/// # Ok::<(), ExactError>(())
/// ```
///
/// # Errors
/// [`ExactError::ParameterOutOfRange`], [`ExactError::NonFinite`]; [`ExactError::Diverges`]
/// for |φ| > π/2 with m_c = 0, where K = ∞.
pub fn ellip_f(phi: f64, mc: f64) -> Result<f64, ExactError> {
    finite("phi", phi)?;
    let jac = Jacobi::new(mc)?;
    let (j, s, c) = reduce_amplitude(phi);
    if j != 0.0 && jac.kc() == 0.0 {
        return Err(ExactError::Diverges { phi });
    }
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
/// [`ExactError::NonFinite`], [`ExactError::ParameterOutOfRange`],
/// [`ExactError::CarlsonDomain`] for s = c = 0, and [`ExactError::Diverges`] for
/// |φ| ≥ π/2 with m_c = 0.
pub fn ellip_f_sc(s: f64, c: f64, mc: f64) -> Result<f64, ExactError> {
    finite("sin φ", s)?;
    finite("cos φ", c)?;
    if s.hypot(c) == 0.0 {
        return Err(ExactError::CarlsonDomain { x: s, y: c, z: mc });
    }
    ellip_f_sc_of(s, c, &Jacobi::new(mc)?)
}

/// [`ellip_f_sc`] for the parameter of `jac`, which also carries k' = √m_c where m_c itself
/// underflows (a rigid body 1e-170 off its intermediate axis has m_c ≈ 1e-340).
///
/// # Errors
/// As [`ellip_f_sc`].
pub(crate) fn ellip_f_sc_of(s: f64, c: f64, jac: &Jacobi) -> Result<f64, ExactError> {
    finite("sin φ", s)?;
    finite("cos φ", c)?;
    let r = s.hypot(c);
    let (mc, kc) = (jac.mc(), jac.kc());
    if r == 0.0 {
        return Err(ExactError::CarlsonDomain { x: s, y: c, z: mc });
    }
    let (s, c) = (s / r, c / r);
    let diverges = || ExactError::Diverges { phi: s.atan2(c) };
    if kc == 0.0 && c <= 0.0 {
        return Err(diverges());
    }
    if s == 0.0 {
        return Ok(if c > 0.0 { 0.0 } else { 2.0 * jac.k() });
    }
    let base = if kc >= SMALL_ROOT {
        s * rf(c * c, c * c + mc * s * s, 1.0)?
    } else {
        // m_c s² may underflow: R_F(c², Δ², 1) from the roots |c| and Δ = √(c² + k'² s²).
        s * rf_roots(c.abs(), c.hypot(kc * s), 1.0)
    };
    if c >= 0.0 {
        Ok(base)
    } else {
        // φ = ±π − φ_r: F(φ) = ±2K − F(φ_r).
        Ok(s.signum() * 2.0 * jac.k() - base)
    }
}

/// R_C(x, y) = R_F(x, y, y), for x ≥ 0 and y > 0 in a safe range.
pub(crate) fn rc(x: f64, y: f64) -> f64 {
    rf_duplication(x, y, y)
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The logarithmic limit of [`rf_roots`] against the duplication where both still work
    /// (squares 1e-300 are representable), and the [`rj_in_range`] transformation against
    /// the duplication at p = 2⁴¹ max(x, y, z), just past where it takes over.
    #[test]
    fn limits_agree_with_the_duplication_where_both_apply() {
        let limit = rf_roots(1e-150, 2e-150, 1.0);
        let direct = rf_duplication(1e-300, 4e-300, 1.0);
        assert!((limit - direct).abs() <= 1e-15 * direct, "{limit} {direct}");
        let (x, y, z) = (0.5, 0.25, 0.125);
        let p = 2f64.powi(41) * 0.5;
        let via = rj_in_range(x, y, z, p).unwrap();
        let direct = rj_duplication(x, y, z, p).unwrap();
        assert!((via - direct).abs() <= 1e-14 * direct, "{via:e} {direct:e}");
    }
}
