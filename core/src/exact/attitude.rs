//! The exact attitude of the torque-free rigid body (after Celledoni, Fassò, Säfström,
//! Zanna, SIAM J. Sci. Comput. 30(4), 2008).
//!
//! With π = R m the constant spatial angular momentum, write the body-to-space rotation as
//! R(t) = P · R_z(φ(t)) · B(m(t)), where B(m) = R_x(θ) R_z(ψ) turns m onto G ẑ
//! (m'/G = (sin θ sin ψ, sin θ cos ψ, cos θ) in axes relabelled cyclically so that the third is
//! the axis a whose component is ±A dn, which never vanishes: no division by zero), and
//! P = R(0) B(m(0))ᵀ. Then
//! φ̇ = G (m'₁²/I'₁ + m'₂²/I'₂)/(m'₁² + m'₂²) = G/I_a + G c_a / (A_cn² (1 − n sn² u)),
//! with c_a = Σ mᵢ²(1/Iᵢ − 1/I_a) (one-signed, no cancellation), n = −A_dn² k²/A_cn², so
//! φ(t) = G t/I_a + G c_a/(A_cn² λ) · [Π̃(u(t)) − Π̃(u₀)], Π̃(u) = ∫₀ᵘ dv/(1 − n sn² v),
//! which is Π(n; am u | m) and is evaluated with Carlson's R_F and R_J after reducing u
//! modulo 2K.

use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};

use super::carlson::{SMALL_ROOT, rc, rf, rj};
use super::double_double::Dd;
use super::elliptic::MAX_ARGUMENT;
use super::error::{ExactError, finite};
use super::free_body::{FreeBodyExact, Regime, array};
use super::scaling::pow2_scale;

/// Constants of the precession angle φ(t).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Precession {
    /// Caller's axis of the dn component.
    axis: usize,
    /// Constant spatial factor P = R(0) B(m₀)ᵀ.
    p: UnitQuaternion<f64>,
    /// G / I_a.
    rate: f64,
    /// G c_a / (A_cn² λ).
    coef: f64,
    /// Characteristic n of the third-kind integral.
    n: f64,
    /// Π̃(K) (0 when K = ∞, never used then).
    pi_k: f64,
    /// Π̃(u₀).
    pi_u0: f64,
}

/// The exact solution (q(t), m(t)) of the free rigid body from (q₀, m₀).
///
/// ```
/// use nalgebra::{UnitQuaternion, Vector3};
/// use precess_core::exact::FreeBodyAttitude;
/// let q0 = UnitQuaternion::identity();
/// let fb = FreeBodyAttitude::new([2.0, 1.0, 2.0 / 3.0], q0, [1.1f64.cos(), 0.0, 1.1f64.sin()])?;
/// let (q, m) = fb.at(10.0)?;
/// // The spatial angular momentum π = q m q⁻¹ is conserved.
/// let pi = q * Vector3::from(m);
/// approx::assert_relative_eq!(pi, Vector3::new(1.1f64.cos(), 0.0, 1.1f64.sin()), epsilon = 1e-14);
/// # Ok::<(), precess_core::exact::ExactError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FreeBodyAttitude {
    /// The scaled problem: m̃ = m/s_m, Ĩ = I/s_I (exact powers of two), in time τ = t s_m/s_I.
    fb: FreeBodyExact,
    inertia: [f64; 3],
    q0: UnitQuaternion<f64>,
    m0: [f64; 3],
    scale_m: f64,
    scale_t: f64,
    prec: Option<Precession>,
}

/// B(m) = R_x(θ) R_z(ψ) · C_a: turns m onto |m| ẑ, with C_a the cyclic relabelling that
/// makes axis a the third.
fn align(m: &[f64; 3], axis: usize) -> UnitQuaternion<f64> {
    let (i1, i2) = ((axis + 1) % 3, (axis + 2) % 3);
    let (m1, m2, m3) = (m[i1], m[i2], m[axis]);
    let rho = m1.hypot(m2);
    let g = rho.hypot(m3);
    let (st, ct) = (rho / g, m3 / g);
    let (sp, cp) = (m1 / rho, m2 / rho);
    let rx = Matrix3::new(1.0, 0.0, 0.0, 0.0, ct, -st, 0.0, st, ct);
    let rz = Matrix3::new(cp, -sp, 0.0, sp, cp, 0.0, 0.0, 0.0, 1.0);
    let mut c = Matrix3::zeros();
    c[(0, i1)] = 1.0;
    c[(1, i2)] = 1.0;
    c[(2, axis)] = 1.0;
    UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(rx * rz * c))
}

impl FreeBodyAttitude {
    /// Sets up the solution for principal moments `inertia`, attitude `q0` (body to space)
    /// and body angular momentum `m0`.
    ///
    /// # Errors
    /// [`ExactError::InvalidInertia`], [`ExactError::NonFinite`] for non-finite q0 or m0,
    /// [`ExactError::NotUnitQuaternion`] for a q0 that is no rotation (|q0| off 1 by more
    /// than 1e-6, such as the zero quaternion).
    pub fn new(
        inertia: impl Into<Vector3<f64>>,
        q0: UnitQuaternion<f64>,
        m0: impl Into<Vector3<f64>>,
    ) -> Result<Self, ExactError> {
        let (inertia, m0) = (array(inertia), array(m0));
        // Validate the caller's numbers first, then work on the scaled problem so that no
        // product of huge or tiny moments and momenta overflows.
        FreeBodyExact::new(inertia, m0)?;
        for v in q0.coords.iter() {
            finite("q0", *v)?;
        }
        ExactError::check_unit(&q0)?;
        let m_orig = m0;
        let (scale_m, scale_i) = (pow2_scale(&m0), pow2_scale(&inertia));
        let m0 = m0.map(|x| x / scale_m);
        let inertia = inertia.map(|x| x / scale_i);
        let fb = FreeBodyExact::new(inertia, m0)?;
        let prec = match fb.dn_axis() {
            None => None,
            Some((axis, _, _)) => {
                // c_a / A_cn² and n = −A_dn² k²/A_cn² reduce to constants of the body (the
                // m-dependence cancels exactly), so nothing quadratic in a component of m is
                // formed: in sorted axes, about the largest axis
                // c_a/A_cn² = (I₃−I₁)/(I₁I₃), n = −I₃(I₂−I₁)/(I₁(I₃−I₂)); about the smallest
                // c_a/A_cn² = −(I₃−I₁)/(I₁I₃), n = −I₁(I₃−I₂)/(I₃(I₂−I₁)).
                let g = m0[0].hypot(m0[1]).hypot(m0[2]);
                let [i1, i2, i3] = fb.sorted_axes().map(|k| inertia[k]);
                let (ratio, n) = if fb.regime() == Regime::AboutSmallest {
                    (-(i3 - i1) / (i1 * i3), -i1 * (i3 - i2) / (i3 * (i2 - i1)))
                } else {
                    ((i3 - i1) / (i1 * i3), -i3 * (i2 - i1) / (i1 * (i3 - i2)))
                };
                let jac = fb.jacobi();
                let (mc, kc) = (jac.mc(), jac.kc());
                let pi_k = if kc >= SMALL_ROOT {
                    rf(0.0, mc, 1.0)? + n / 3.0 * rj(0.0, mc, 1.0, 1.0 - n)?
                } else if kc > 0.0 {
                    // R_F(0, k'², 1) = K and R_J(0, k'², 1, p) → (3/p)(K − R_C(1, p)) as k' → 0.
                    let k = jac.k();
                    k + n / (1.0 - n) * (k - rc(1.0, 1.0 - n))
                } else {
                    0.0
                };
                let mut pr = Precession {
                    axis,
                    p: q0 * align(&m0, axis).inverse(),
                    rate: g / inertia[axis],
                    coef: g * ratio / fb.lambda(),
                    n,
                    pi_k,
                    pi_u0: 0.0,
                };
                pr.pi_u0 = Self::pi_tilde(&fb, &pr, fb.phase(0.0))?;
                Some(pr)
            }
        };
        Ok(Self {
            fb,
            inertia,
            q0,
            m0: m_orig,
            scale_m,
            scale_t: scale_m / scale_i,
            prec,
        })
    }

    /// Π̃(u) = ∫₀ᵘ dv/(1 − n sn² v) = 2jΠ̃(K) + Π̃(r) for u = 2jK + r, |r| ≤ K.
    fn pi_tilde(fb: &FreeBodyExact, pr: &Precession, u: Dd) -> Result<f64, ExactError> {
        let jac = fb.jacobi();
        let (j, r) = jac.reduce(u);
        let (s, c, d) = jac.sncndn_reduced(r);
        let part = if s == 0.0 {
            0.0
        } else if c.abs() < SMALL_ROOT && d < SMALL_ROOT {
            // Near u = ±K with k' tiny, c² and d² underflow. Then s R_F(c², d², 1) = F(am r) = r
            // exactly, and R_J(c², d², 1, p) = (3/p)(R_F(c², d², 1) − R_C(1, p)) to O(d² ln d).
            let p = 1.0 - pr.n * s * s;
            r + pr.n * s * s * s / p * (r / s - rc(1.0, p))
        } else {
            let (c2, d2) = (c * c, d * d);
            s * rf(c2, d2, 1.0)? + pr.n / 3.0 * s * s * s * rj(c2, d2, 1.0, 1.0 - pr.n * s * s)?
        };
        Ok(2.0 * j * pr.pi_k + part)
    }

    /// The angular-momentum solution underneath.
    pub fn momentum(&self) -> &FreeBodyExact {
        &self.fb
    }

    /// The regime of the motion.
    pub fn regime(&self) -> Regime {
        self.fb.regime()
    }

    /// (q(t), m(t)).
    ///
    /// # Errors
    /// [`ExactError::NonFinite`] for a non-finite `t`.
    pub fn at(&self, t: f64) -> Result<(UnitQuaternion<f64>, Vector3<f64>), ExactError> {
        self.array_at(t).map(|(q, m)| (q, m.into()))
    }

    /// [`FreeBodyAttitude::at`] with m as an array, for the steppers' inner loops.
    pub(crate) fn array_at(&self, t: f64) -> Result<(UnitQuaternion<f64>, [f64; 3]), ExactError> {
        finite("t", t)?;
        if t == 0.0 {
            return Ok((self.q0, self.m0));
        }
        let tau = t * self.scale_t;
        if !tau.is_finite() {
            return Err(ExactError::ArgumentTooLarge {
                u: tau,
                limit: MAX_ARGUMENT,
            });
        }
        let (q, m) = self.scaled_at(tau)?;
        let m = m.map(|x| x * self.scale_m);
        if !m.iter().chain(q.coords.iter()).all(|v| v.is_finite()) {
            return Err(ExactError::ArgumentTooLarge {
                u: tau,
                limit: MAX_ARGUMENT,
            });
        }
        Ok((q, m))
    }

    /// (q, m̃) of the scaled problem at scaled time τ.
    fn scaled_at(&self, t: f64) -> Result<(UnitQuaternion<f64>, [f64; 3]), ExactError> {
        let m = self.fb.m_array_at(t)?;
        let Some(pr) = self.prec else {
            // Steady: ω = I⁻¹m is constant and along m, the body spins uniformly.
            let w = Vector3::new(
                m[0] / self.inertia[0],
                m[1] / self.inertia[1],
                m[2] / self.inertia[2],
            );
            return Ok((self.q0 * UnitQuaternion::from_scaled_axis(w * t), m));
        };
        let phi =
            pr.rate * t + pr.coef * (Self::pi_tilde(&self.fb, &pr, self.fb.phase(t))? - pr.pi_u0);
        let rz = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), phi);
        Ok((pr.p * rz * align(&m, pr.axis), m))
    }
}

/// The exact free-body flow of (q, m) over `h`, as a splitting step.
///
/// # Errors
/// As [`FreeBodyAttitude::new`] and [`FreeBodyAttitude::at`].
pub fn free_body_flow_attitude(
    inertia: impl Into<Vector3<f64>>,
    q: UnitQuaternion<f64>,
    m: impl Into<Vector3<f64>>,
    h: f64,
) -> Result<(UnitQuaternion<f64>, Vector3<f64>), ExactError> {
    FreeBodyAttitude::new(inertia, q, m)?.at(h)
}
