//! Jacobi elliptic functions sn, cn, dn and the complete integral K, computed from the
//! complementary parameter m_c = 1 − m so that no digits are lost near m = 1.
//!
//! K = π / (2 AGM(1, √m_c)); sn, cn, dn by the descending Gauss (Landen) transformation of
//! Bulirsch (Numer. Math. 7, 1965; A&S 16.4). The argument is reduced modulo 2K in
//! double-double arithmetic, so large arguments keep their digits.

use super::double_double::{Dd, PI};
use super::error::{ExactError, finite};

/// Longest AGM chain kept (m_c down to 1e-300 needs about 12 steps).
const MAX_AGM: usize = 24;

/// Largest |u| the checked entry points accept: the double-double reduction modulo 2K keeps
/// about 32 digits, so beyond ~1e15 the reduced argument would lose its absolute accuracy.
pub const MAX_ARGUMENT: f64 = 1e15;

/// Jacobi elliptic functions of one parameter, with the AGM chain and K precomputed.
///
/// ```
/// use precess_core::exact::Jacobi;
/// // DETEST B5 is (sn, cn, dn)(t | m = 0.51).
/// let j = Jacobi::new(0.49)?;
/// let (sn, cn, dn) = j.sncndn(20.0);
/// approx::assert_relative_eq!(sn, -0.939_657_079_872_920_4, epsilon = 1e-15);
/// approx::assert_relative_eq!(cn * cn + sn * sn, 1.0, epsilon = 1e-15);
/// approx::assert_relative_eq!(dn, 0.741_412_659_619_995_3, epsilon = 1e-15);
/// # Ok::<(), precess_core::exact::ExactError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jacobi {
    mc: f64,
    /// k' = √m_c, which stays representable where m_c underflows.
    kc: f64,
    /// K in double-double; +∞ in `hi` when m_c = 0.
    k: Dd,
    /// Arithmetic means a₀…a_{n−1} and geometric means b₀…b_{n−1} of the AGM chain.
    a: [f64; MAX_AGM],
    b: [f64; MAX_AGM],
    len: usize,
    /// The limit of the chain, c = π / (2K).
    c: f64,
}

impl Jacobi {
    /// Prepares sn, cn, dn and K for the complementary parameter `mc` ∈ [0, 1].
    ///
    /// # Errors
    /// [`ExactError::ParameterOutOfRange`] for `mc` outside [0, 1] or NaN.
    pub fn new(mc: f64) -> Result<Self, ExactError> {
        if !(0.0..=1.0).contains(&mc) {
            return Err(ExactError::ParameterOutOfRange { mc });
        }
        Ok(Self::build(mc, mc.sqrt(), Dd::from(mc).sqrt()))
    }

    /// Prepares the functions from the complementary modulus k' = √m_c ∈ [0, 1] (clamped),
    /// for parameters whose m_c = k'² is below the f64 range: the AGM chain starts from k'
    /// itself.
    pub(crate) fn from_kc(kc: Dd) -> Self {
        let kc = if kc.hi > 1.0 {
            Dd::from(1.0)
        } else if kc.hi < 0.0 {
            Dd::from(0.0)
        } else {
            kc
        };
        Self::build((kc * kc).to_f64(), kc.to_f64(), kc)
    }

    fn build(mc: f64, kc: f64, kc_dd: Dd) -> Self {
        let mut me = Self {
            mc,
            kc,
            k: Dd::from(f64::INFINITY),
            a: [0.0; MAX_AGM],
            b: [0.0; MAX_AGM],
            len: 0,
            c: 0.0,
        };
        if kc == 0.0 {
            return me;
        }
        // Double chain for the Landen back-substitution (Bulirsch's sncndn).
        let (mut a, mut b) = (1.0_f64, kc);
        let mut c = 0.5 * (a + b);
        for i in 0..MAX_AGM {
            me.a[i] = a;
            me.b[i] = b;
            me.len = i + 1;
            c = 0.5 * (a + b);
            // Quadratic convergence: once |a − b| ≤ 1e-9 a, the next mean is exact to 1e-18.
            if (a - b).abs() <= 1e-9 * a {
                break;
            }
            b = (a * b).sqrt();
            a = c;
        }
        me.c = c;
        // Double-double chain for K itself, which sets the period.
        let (mut ad, mut bd) = (Dd::from(1.0), kc_dd);
        for _ in 0..MAX_AGM {
            let an = (ad + bd) * Dd::from(0.5);
            let done = (ad - bd).to_f64().abs() <= 1e-17 * ad.hi;
            bd = (ad * bd).sqrt();
            ad = an;
            if done {
                break;
            }
        }
        me.k = PI / (ad * Dd::from(2.0));
        me
    }

    /// The complementary parameter m_c.
    pub fn mc(&self) -> f64 {
        self.mc
    }

    /// The complementary modulus k' = √m_c.
    pub fn kc(&self) -> f64 {
        self.kc
    }

    /// The complete elliptic integral of the first kind K(m) (+∞ at m_c = 0).
    pub fn k(&self) -> f64 {
        self.k.to_f64()
    }

    /// K as a double-double, for callers that reduce long phases themselves.
    pub fn k_dd(&self) -> Dd {
        self.k
    }

    /// (sn, cn, dn)(u | m).
    pub fn sncndn(&self, u: f64) -> (f64, f64, f64) {
        self.sncndn_dd(Dd::from(u))
    }

    /// (sn, cn, dn)(u | m) for a double-double argument (phases λt + u₀ of long runs).
    ///
    /// Non-finite arguments give NaN; the checked entry point is [`sncndn`].
    pub fn sncndn_dd(&self, u: Dd) -> (f64, f64, f64) {
        if self.kc == 0.0 {
            let x = u.to_f64();
            let s = 1.0 / x.cosh();
            return (x.tanh(), s, s);
        }
        // u = 2K n + r, |r| ≤ K; sn and cn change sign with odd n, dn does not.
        let (n, r) = self.reduce(u);
        let (sn, cn, dn) = self.reduced(r);
        if n.rem_euclid(2.0) == 1.0 {
            (-sn, -cn, dn)
        } else {
            (sn, cn, dn)
        }
    }

    /// Splits u = 2K n + r with |r| ≤ K (in double-double); returns (n, r). For m_c = 0
    /// (K = ∞) returns (0, u).
    pub fn reduce(&self, u: Dd) -> (f64, f64) {
        if self.kc == 0.0 {
            return (0.0, u.to_f64());
        }
        let two_k = self.k * Dd::from(2.0);
        let n = (u / two_k).round();
        (n, (u - two_k * Dd::from(n)).to_f64())
    }

    /// (sn, cn, dn)(r) for a reduced argument |r| ≤ K (cn ≥ 0), as returned by [`Self::reduce`].
    pub fn sncndn_reduced(&self, r: f64) -> (f64, f64, f64) {
        if self.kc == 0.0 {
            let s = 1.0 / r.cosh();
            return (r.tanh(), s, s);
        }
        self.reduced(r)
    }

    /// Bulirsch's descending Landen transformation for |u| ≤ K.
    fn reduced(&self, u: f64) -> (f64, f64, f64) {
        if u.abs() < 1e-5 {
            // Taylor to the last bit (next terms are O(u⁴) relative); the back substitution
            // would overflow through cn/sn for tiny u.
            let (u2, m) = (u * u, 1.0 - self.mc);
            return (
                u - (1.0 + m) * u * u2 / 6.0,
                1.0 - 0.5 * u2,
                1.0 - 0.5 * m * u2,
            );
        }
        let x = u * self.c;
        let (s, co) = x.sin_cos();
        if s == 0.0 {
            return (0.0, 1.0, 1.0);
        }
        // Back substitution: c ← c·a/… carries cn/sn and dn down the chain.
        let mut ratio = co / s;
        let mut c = self.c * ratio;
        let mut dn = 1.0;
        for i in (0..self.len).rev() {
            let b = self.a[i];
            ratio *= c;
            c *= dn;
            dn = (self.b[i] + ratio) / (b + ratio);
            ratio = c / b;
        }
        let a = 1.0 / (c * c + 1.0).sqrt();
        let sn = if s >= 0.0 { a } else { -a };
        (sn, c * sn, dn)
    }
}

/// (sn, cn, dn)(u | m) from the complementary parameter m_c = 1 − m.
///
/// ```
/// let (sn, cn, dn) = precess_core::exact::sncndn(0.3, 1.0)?; // m = 0: sin, cos, 1
/// approx::assert_relative_eq!(sn, 0.3f64.sin(), epsilon = 1e-16);
/// approx::assert_relative_eq!(cn, 0.3f64.cos(), epsilon = 1e-16);
/// approx::assert_relative_eq!(dn, 1.0);
/// # Ok::<(), precess_core::exact::ExactError>(())
/// ```
///
/// # Errors
/// [`ExactError::ParameterOutOfRange`], [`ExactError::NonFinite`] for a non-finite `u`,
/// [`ExactError::ArgumentTooLarge`] beyond [`MAX_ARGUMENT`].
pub fn sncndn(u: f64, mc: f64) -> Result<(f64, f64, f64), ExactError> {
    finite("u", u)?;
    if u.abs() > MAX_ARGUMENT {
        return Err(ExactError::ArgumentTooLarge {
            u,
            limit: MAX_ARGUMENT,
        });
    }
    Ok(Jacobi::new(mc)?.sncndn(u))
}

/// The complete elliptic integral of the first kind, K = π / (2 AGM(1, √m_c)).
///
/// ```
/// // K(m = 0.51), DETEST B5's quarter period.
/// let k = precess_core::exact::ellip_k(0.49)?;
/// approx::assert_relative_eq!(k, 1.862_640_802_332_738_6, max_relative = 1e-16);
/// # Ok::<(), precess_core::exact::ExactError>(())
/// ```
///
/// # Errors
/// [`ExactError::ParameterOutOfRange`] for `mc` outside [0, 1].
pub fn ellip_k(mc: f64) -> Result<f64, ExactError> {
    Ok(Jacobi::new(mc)?.k())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn from_kc_matches_new_where_m_c_is_representable() {
        for mc in [0.5, 1e-10, 1e-300] {
            let (a, b) = (
                Jacobi::new(mc).unwrap(),
                Jacobi::from_kc(Dd::from(mc).sqrt()),
            );
            assert!((a.k() - b.k()).abs() <= 1e-15 * a.k(), "mc = {mc:e}");
            let (u1, u2) = (a.sncndn(0.7 * a.k()), b.sncndn(0.7 * a.k()));
            assert!((u1.0 - u2.0).abs() + (u1.1 - u2.1).abs() + (u1.2 - u2.2).abs() < 1e-15);
        }
        // Beyond: k' = 1e-170 has K = ln(4/k') + O(k'²).
        let j = Jacobi::from_kc(Dd::from(1e-170));
        assert_eq!(j.mc(), 0.0);
        assert!((j.k() - (4e170f64).ln()).abs() < 1e-13, "{}", j.k());
    }

    #[test]
    fn extreme_arguments_stay_finite() {
        for mc in [1.0, 0.5, 1e-9, 1e-15, 0.0] {
            let j = Jacobi::new(mc).unwrap();
            for u in [
                0.0, 1e-300, -1e-300, 5e-324, 1e-150, 1e-8, 1e15, -1e15, 1e300, -1e300,
            ] {
                let (s, c, d) = j.sncndn(u);
                assert!(
                    s.is_finite() && c.is_finite() && d.is_finite(),
                    "u={u:e} mc={mc:e}: {s} {c} {d}"
                );
            }
        }
    }
}
