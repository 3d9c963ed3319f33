//! The torque-free rigid body's angular momentum in closed form, in every regime.
//!
//! Body angular momentum m obeys ṁ = m × (I⁻¹ m). In principal axes sorted I₁ ≤ I₂ ≤ I₃,
//! with the cancellation-free quantities
//! D₁ = m₂²(I₂−I₁)/I₂ + m₃²(I₃−I₁)/I₃ = G² − 2HI₁ ≥ 0,
//! D₃ = −[m₁²(I₃−I₁)/I₁ + m₂²(I₃−I₂)/I₂] = G² − 2HI₃ ≤ 0,
//! D₂ = m₃²(I₃−I₂)/I₃ − m₁²(I₂−I₁)/I₁ = G² − 2HI₂:
//! - D₂ > 0 (about the largest axis): m = (A₁ cn, A₂ sn, ±A₃ dn)(λt + u₀),
//! - D₂ < 0 (about the smallest axis): m = (±A₁ dn, A₂ sn, A₃ cn)(λt + u₀),
//! - D₂ = 0 (separatrix): the same with m_c = 0, sn = tanh, cn = dn = sech.
//!
//! m_c comes from these formulas, never from 1 − k², and D₁, D₂, D₃, λ and the phase are
//! carried in double-double: near the separatrix and over long times that is where the
//! digits go.

use nalgebra::Vector3;

use super::carlson::ellip_f_sc_of;
use super::double_double::Dd;
use super::elliptic::{Jacobi, MAX_ARGUMENT};
use super::error::{ExactError, finite};
use super::scaling::{exponent, pow2, pow2_scale};

/// x · 2ᵉ for a double-double (exact unless a part leaves the f64 range).
fn ldexp_dd(x: Dd, e: i32) -> Dd {
    use super::scaling::ldexp;
    Dd {
        hi: ldexp(x.hi, e),
        lo: ldexp(x.lo, e),
    }
}

/// The exponent of the larger of |a|, |b| (0 when both are zero): the pair divided by 2 to
/// this power has its larger in [1, 2), so its squares neither overflow nor underflow.
fn pair_exponent(a: f64, b: f64) -> i32 {
    let mx = a.abs().max(b.abs());
    if mx > 0.0 { exponent(mx) } else { 0 }
}

/// Which motion the initial state starts on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Regime {
    /// A relative equilibrium (m along a principal axis, or any m for a sphere): m constant.
    Steady,
    /// Rotation about the axis of largest moment (D₂ > 0).
    AboutLargest,
    /// Rotation about the axis of smallest moment (D₂ < 0).
    AboutSmallest,
    /// On the separatrix through the intermediate axis (D₂ = 0).
    Separatrix,
}

/// The exact angular-momentum solution m(t) of the free rigid body from m(0).
///
/// ```
/// use precess_core::exact::FreeBodyExact;
/// // The Geometric Numerical Integration book's body: m(10) quoted to 30 digits.
/// let fb = FreeBodyExact::new([2.0, 1.0, 2.0 / 3.0], [1.1f64.cos(), 0.0, 1.1f64.sin()])?;
/// let m = fb.m_at(10.0)?;
/// approx::assert_relative_eq!(m[0], 0.407_066_136_588_040_8, epsilon = 1e-14);
/// approx::assert_relative_eq!(m[1], 0.283_007_426_812_843_7, epsilon = 1e-14);
/// approx::assert_relative_eq!(m[2], 0.868_449_167_661_561_7, epsilon = 1e-14);
/// # Ok::<(), precess_core::exact::ExactError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FreeBodyExact {
    m0: [f64; 3],
    regime: Regime,
    /// perm[k] is the original axis of the k-th smallest moment.
    perm: [usize; 3],
    /// Signed amplitudes in sorted axes, applied to (cn, sn, dn) or (dn, sn, cn).
    amp: [f64; 3],
    /// λ with the sign that solves the equations, times −1 for an odd axis permutation.
    lambda: Dd,
    u0: f64,
    jac: Jacobi,
}

impl FreeBodyExact {
    /// Sets up the solution for principal moments `inertia` (any order) and m(0) = `m0`.
    ///
    /// Any finite positive moments, subnormal ones included, and any finite m(0): the
    /// problem is scaled by exact powers of two, so a body whose moments and momentum are
    /// both tiny moves as the same body at unit scale.
    ///
    /// # Errors
    /// [`ExactError::InvalidInertia`] unless all moments are finite and > 0;
    /// [`ExactError::NonFinite`] for a non-finite `m0`; [`ExactError::RateOverflow`] when
    /// the rate of the motion, about |m|/I, is beyond f64 (moments of 1e-310 for |m| = 1).
    pub fn new(
        inertia: impl Into<Vector3<f64>>,
        m0: impl Into<Vector3<f64>>,
    ) -> Result<Self, ExactError> {
        let (inertia, m0) = (array(inertia), array(m0));
        if !inertia.iter().all(|&v| v.is_finite() && v > 0.0) {
            return Err(ExactError::InvalidInertia { inertia });
        }
        for v in m0 {
            finite("m0", v)?;
        }
        let mut perm = [0, 1, 2];
        perm.sort_by(|&a, &b| inertia[a].total_cmp(&inertia[b]));
        // A swap of two axes is a reflection: it reverses the sense of m × ω, i.e. time.
        let odd = matches!(perm, [0, 2, 1] | [1, 0, 2] | [2, 1, 0]);
        let parity = if odd { -1.0 } else { 1.0 };
        // Exact power-of-two scalings keep squares and products of huge or tiny inputs in
        // range: m = s_m m̃(t s_m/s_I) solves the scaled problem with I = s_I Ĩ.
        let (sm, si) = (pow2_scale(&m0), pow2_scale(&inertia));
        let i = perm.map(|k| inertia[k] / si);
        let m = perm.map(|k| m0[k] / sm);
        let mut me = Self {
            m0,
            regime: Regime::Steady,
            perm,
            amp: [0.0; 3],
            lambda: Dd::default(),
            u0: 0.0,
            jac: Jacobi::new(1.0)?,
        };
        let w = [m[0] / i[0], m[1] / i[1], m[2] / i[2]];
        let cross = [
            m[1] * w[2] - m[2] * w[1],
            m[2] * w[0] - m[0] * w[2],
            m[0] * w[1] - m[1] * w[0],
        ];
        if cross.iter().all(|&c| c == 0.0) {
            return Ok(me);
        }
        let d = |x: f64| Dd::from(x);
        let sq = |x: f64| Dd::prod(x, x);
        let (i1, i2, i3) = (d(i[0]), d(i[1]), d(i[2]));
        let (i21, i31, i32) = (i2 - i1, i3 - i1, i3 - i2);
        // Each Dₖ involves two components of m. It is formed from those two divided by the
        // power of two of the larger (Dₖ = 4^eₖ D̃ₖ), so that near a principal axis, where
        // the others are 1e-170 of it, no square underflows: the amplitudes and k' = √m_c
        // then come out as √D̃ₖ · 2^eₖ.
        let (e12, e13, e23) = (
            pair_exponent(m[0], m[1]),
            pair_exponent(m[0], m[2]),
            pair_exponent(m[1], m[2]),
        );
        let (s12, s13, s23) = (pow2(e12), pow2(e13), pow2(e23));
        let d1 = sq(m[1] / s23) * i21 / i2 + sq(m[2] / s23) * i31 / i3;
        let d3 = -(sq(m[0] / s12) * i31 / i1 + sq(m[1] / s12) * i32 / i2);
        let d2 = sq(m[2] / s13) * i32 / i3 - sq(m[0] / s13) * i21 / i1;
        let i123 = i1 * i2 * i3;
        let root = |x: Dd, e: i32| x.sqrt().to_f64() * pow2(e);
        // (amplitudes, λ, m_c / 4^e and e, sign, cos of the initial amplitude)
        let (amp, lam, mc_scaled, e_mc, s, cn_ratio) = if d2.hi >= 0.0 {
            let amp = [
                root(-d3 * i1 / i31, e12),
                root(-d3 * i2 / i32, e12),
                root(d1 * i3 / i31, e23),
            ];
            let s3 = if m[2] < 0.0 { -1.0 } else { 1.0 };
            // On the separatrix cn = dn = sech > 0, so the sign of m₁ goes into its
            // amplitude and, since ṁ₂ ∝ m₁m₃, into λ.
            let s1 = if d2.hi == 0.0 && m[0] < 0.0 {
                -1.0
            } else {
                1.0
            };
            (
                amp,
                (i32 * d1 / i123).sqrt() * d(s23),
                d2 * i31 / (d1 * i32),
                e13 - e23,
                s3 * s1,
                s1 * m[0] / amp[0],
            )
        } else {
            let amp = [
                root(-d3 * i1 / i31, e12),
                root(d1 * i2 / i21, e23),
                root(d1 * i3 / i31, e23),
            ];
            let s = if m[0] < 0.0 { -1.0 } else { 1.0 };
            (
                amp,
                (i21 * (-d3) / i123).sqrt() * d(s12),
                d2 * i31 / (d3 * i21),
                e13 - e12,
                s,
                m[2] / amp[2],
            )
        };
        me.regime = if d2.hi > 0.0 {
            Regime::AboutLargest
        } else if d2.hi < 0.0 {
            Regime::AboutSmallest
        } else {
            Regime::Separatrix
        };
        let mc = ldexp_dd(mc_scaled, 2 * e_mc).to_f64().clamp(0.0, 1.0);
        me.jac = if mc >= f64::MIN_POSITIVE {
            Jacobi::new(mc)?
        } else {
            // m_c underflows (a state 1e-170 off the intermediate axis): k' does not.
            Jacobi::from_kc(ldexp_dd(mc_scaled.sqrt(), e_mc))
        };
        me.amp = amp.map(|a| a * sm);
        match me.regime {
            Regime::AboutSmallest => me.amp[0] *= s,
            Regime::Separatrix => {
                let (s1, s3) = (m[0].signum(), m[2].signum());
                me.amp[0] *= s1;
                me.amp[2] *= s3;
            }
            _ => me.amp[2] *= s,
        }
        // The scales enter λ as the power of two sm / si, applied exactly by exponent: in
        // double-double the quotient by a subnormal si is NaN, and at such moments the rate
        // itself may leave the f64 range.
        let lambda = ldexp_dd(lam * d(s * parity), exponent(sm) - exponent(si));
        if !lambda.hi.is_finite() {
            return Err(ExactError::RateOverflow { inertia, m0 });
        }
        me.lambda = lambda;
        // Initial phase from the amplitude φ₀ with (sin φ₀, cos φ₀) = (sn u₀, cn u₀).
        let sn0 = m[1] * sm / me.amp[1];
        me.u0 = ellip_f_sc_of(sn0, cn_ratio, &me.jac)?;
        Ok(me)
    }

    /// The caller's axes in order of increasing moment.
    pub(crate) fn sorted_axes(&self) -> [usize; 3] {
        self.perm
    }

    /// The regime of the motion.
    pub fn regime(&self) -> Regime {
        self.regime
    }

    /// The complementary parameter m_c of the elliptic functions (1 when steady).
    pub fn mc(&self) -> f64 {
        self.jac.mc()
    }

    /// K(m) of the motion (π/2 when steady, +∞ on the separatrix).
    pub fn k(&self) -> f64 {
        self.jac.k()
    }

    /// The rate λ of the elliptic argument u = λt + u₀ (signed; 0 when steady).
    pub fn lambda(&self) -> f64 {
        self.lambda.to_f64()
    }

    /// Period of m(t): 4K/|λ| (+∞ on the separatrix or when steady).
    pub fn period(&self) -> f64 {
        match self.regime {
            Regime::Steady | Regime::Separatrix => f64::INFINITY,
            _ => 4.0 * self.k() / self.lambda().abs(),
        }
    }

    /// The elliptic functions of the motion.
    pub fn jacobi(&self) -> &Jacobi {
        &self.jac
    }

    /// The phase u(t) = λt + u₀ in double-double.
    pub fn phase(&self, t: f64) -> Dd {
        self.lambda * Dd::from(t) + Dd::from(self.u0)
    }

    /// The initial phase u₀.
    pub fn u0(&self) -> f64 {
        self.u0
    }

    /// The caller's axis whose component is ± A dn (the axis the motion circles), and
    /// |A| of that axis and of the cn axis; `None` when steady.
    pub fn dn_axis(&self) -> Option<(usize, f64, f64)> {
        match self.regime {
            Regime::Steady => None,
            Regime::AboutSmallest => Some((self.perm[0], self.amp[0].abs(), self.amp[2].abs())),
            _ => Some((self.perm[2], self.amp[2].abs(), self.amp[0].abs())),
        }
    }

    /// The initial angular momentum.
    pub fn m0(&self) -> Vector3<f64> {
        self.m0.into()
    }

    /// m(t) in the caller's axes.
    ///
    /// # Errors
    /// [`ExactError::NonFinite`] for a non-finite `t`; [`ExactError::ArgumentTooLarge`] when
    /// |λt + u₀| exceeds [`MAX_ARGUMENT`].
    pub fn m_at(&self, t: f64) -> Result<Vector3<f64>, ExactError> {
        self.m_array_at(t).map(Vector3::from)
    }

    /// [`FreeBodyExact::m_at`] as an array, for the steppers' inner loops.
    pub(crate) fn m_array_at(&self, t: f64) -> Result<[f64; 3], ExactError> {
        finite("t", t)?;
        if self.regime == Regime::Steady || t == 0.0 {
            return Ok(self.m0);
        }
        let u = self.lambda * Dd::from(t) + Dd::from(self.u0);
        if u.hi.is_nan() || u.hi.abs() > MAX_ARGUMENT {
            return Err(ExactError::ArgumentTooLarge {
                u: u.hi,
                limit: MAX_ARGUMENT,
            });
        }
        let (sn, cn, dn) = self.jac.sncndn_dd(u);
        let sorted = if self.regime == Regime::AboutSmallest {
            [self.amp[0] * dn, self.amp[1] * sn, self.amp[2] * cn]
        } else {
            [self.amp[0] * cn, self.amp[1] * sn, self.amp[2] * dn]
        };
        let mut out = [0.0; 3];
        for (k, &axis) in self.perm.iter().enumerate() {
            out[axis] = sorted[k];
        }
        Ok(out)
    }
}

/// The exact free-body flow of the angular momentum over `h`, as a splitting step:
/// φ_h(m) = m(h) for ṁ = m × (I⁻¹ m).
///
/// # Errors
/// As [`FreeBodyExact::new`] and [`FreeBodyExact::m_at`].
pub fn free_body_flow(
    inertia: impl Into<Vector3<f64>>,
    m: impl Into<Vector3<f64>>,
    h: f64,
) -> Result<Vector3<f64>, ExactError> {
    FreeBodyExact::new(inertia, m)?.m_at(h)
}

/// The components of a vector given as anything that converts to one (`[x, y, z]` or a
/// [`Vector3`]): the public boundary takes vectors, the arithmetic inside works on arrays.
pub(crate) fn array(v: impl Into<Vector3<f64>>) -> [f64; 3] {
    let v = v.into();
    [v.x, v.y, v.z]
}
