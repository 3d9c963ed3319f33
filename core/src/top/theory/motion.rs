//! The symmetric heavy top's motion in closed form: conserved quantities, the cubic in
//! cos θ and its roots, the nutation period, θ(t), and the mean precession rate.

use super::cubic::ShiftedCubic;
use super::error::{TheoryError, finite};
use super::heavy::HeavyTopTheory;
use crate::exact::carlson::{rf, rj};
use crate::exact::{ellip_k, sncndn};

/// Slack on the nutation band when [`HeavyTopMotion::precession_rate_at`] checks a cosine.
const BAND_SLACK: f64 = 1e-12;

/// The exact motion of a symmetric heavy top from one state.
///
/// # The mathematics
///
/// With u = cos θ, a = p_ψ/I1, b = p_φ/I1, β = 2 M g l / I1 and α = (2E − I3 ω3²)/I1,
/// energy conservation gives u̇² = f(u) = (α − β u)(1 − u²) − (b − a u)², a cubic with
/// f(±1) = −(b ∓ a)² ≤ 0. For M g l > 0 its roots are u1 ≤ u2 in [−1, 1] (the turning
/// points, θ_max = arccos u1 and θ_min = arccos u2) and u3 ≥ 1. Writing
/// f = β (u − u1)(u2 − u)(u3 − u) and u = u1 + (u2 − u1) sin²χ turns dt = du/√f into
/// dt = 2 dχ / (√(β (u3 − u1)) √(1 − m sin²χ)), m = (u2 − u1)/(u3 − u1), so
///
/// - u(t) = u1 + (u2 − u1) sn²(ν (t − t1) | m), ν = √(β (u3 − u1))/2 = √(M g l (u3 − u1)/(2 I1)),
///   t1 a time of θ_max;
/// - the nutation period is T = 2K(m)/ν;
/// - φ̇ = (b − a u)/(1 − u²) = ½((b − a)/(1 − u) + (b + a)/(1 + u)) averages over a period to
///   ⟨φ̇⟩ = [(b − a) Π(n₊|m)/(1 − u1) + (b + a) Π(n₋|m)/(1 + u1)] / (2K(m)), with
///   n₊ = (u2 − u1)/(1 − u1), n₋ = −(u2 − u1)/(1 + u1) and the complete integral of the
///   third kind Π(n|m) = R_F(0, 1−m, 1) + (n/3) R_J(0, 1−m, 1, 1−n) (DLMF 19.25.2). It is
///   evaluated as φ̇(u1) plus the R_J terms, with 1 − n₊ = (1 − u2)/(1 − u1) and
///   1 − n₋ = (1 + u2)/(1 + u1) formed directly; Carlson's integrals are accurate to a few ε,
///   and the result agrees with a 4096-point periodic quadrature to 1.4e-14
///   (`tests/top_theory.rs`).
///
/// For M g l < 0 (a top hanging below its pivot) the same holds for u′ = −u, a′ = −a, and the
/// answers are mapped back. The roots are found about the initial u0 (see the source of
/// `cubic.rs`), so turning points keep their digits even for tiny nutation.
///
/// Degenerate cases are the limits, not NaN: zero nutation (a steady precession, u1 = u2)
/// gives m = 0, θ(t) = θ0 and the small-oscillation period π/ν; u2 = u3 (the separatrix, an
/// unstable steady motion approached asymptotically) gives an infinite period and the
/// precession rate at the limit; u1 = u2 = u3 (a sleeping top exactly at its threshold)
/// gives an infinite period.
///
/// # Examples
///
/// The reference top I1 = 1, I3 = ½, M g l = 1, released at rest from θ0 = 60° spinning at
/// ω3 = 20 (published: nutation 1.7580e-2 rad over 0.634549 s; mean precession close to
/// M g l/(I3 ω3) = 0.1):
///
/// ```
/// use approx::assert_relative_eq;
/// use precess_core::top::HeavyTopTheory;
///
/// let top = HeavyTopTheory::new(1.0, 0.5, 1.0)?;
/// let theta0 = std::f64::consts::FRAC_PI_3;
/// let motion = top.motion_from_angles(&[0.0, theta0, 0.0], &[0.0, 0.0, 20.0])?;
/// assert_relative_eq!(motion.theta_min(), theta0, max_relative = 1e-15);
/// assert_relative_eq!(motion.theta_max() - theta0, 1.7580e-2, max_relative = 1e-4);
/// assert_relative_eq!(motion.nutation_period(), 0.634549, max_relative = 1e-6);
/// let half = motion.nutation_period() / 2.0;
/// assert_relative_eq!(motion.theta_at(half)?, motion.theta_max(), max_relative = 1e-14);
/// assert_relative_eq!(motion.mean_precession_rate()?, 0.1, max_relative = 0.02);
/// # Ok::<(), precess_core::top::TheoryError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeavyTopMotion {
    theory: HeavyTopTheory,
    theta0: f64,
    energy: f64,
    p_phi: f64,
    p_psi: f64,
    /// A0 = α − β u0 and B0 = b − a u0 (the same in both frames).
    a0: f64,
    b0: f64,
    /// σ = sign(M g l): the frame u′ = σ u, in which β > 0.
    sign: f64,
    beta: f64,
    /// a′ = σ p_ψ / I1 and b = p_φ / I1.
    a: f64,
    b: f64,
    /// 1 − u0′ and 1 + u0′, from half angles.
    one_minus0: f64,
    one_plus0: f64,
    /// The roots u′_i − u0′, ascending.
    x: [f64; 3],
    mc: f64,
    k: f64,
    /// ν = √(β (u3′ − u1′))/2.
    rate: f64,
    /// The elliptic phase at t = 0 (τ with u′ = u1′ + (u2′ − u1′) sn² τ), or `None` when u
    /// stays at u0.
    phase: Option<f64>,
}

impl HeavyTopMotion {
    /// The motion from θ, θ̇ and the conserved momenta p_φ, p_ψ.
    ///
    /// # Errors
    /// [`TheoryError::NonFinite`]; [`TheoryError::TransverseMomentumAtPole`] at sin θ = 0
    /// unless p_φ = ±p_ψ (the axis vertical needs it); [`TheoryError::Exact`] should an
    /// elliptic integral fail (not seen for a physical state).
    pub fn new(
        theory: HeavyTopTheory,
        theta: f64,
        theta_dot: f64,
        p_phi: f64,
        p_psi: f64,
    ) -> Result<Self, TheoryError> {
        finite("θ", theta)?;
        finite("θ̇", theta_dot)?;
        finite("p_φ", p_phi)?;
        finite("p_ψ", p_psi)?;
        let (s, c) = theta.sin_cos();
        let b0 = (p_phi - p_psi * c) / theory.i1();
        let phi_dot_sin = if s == 0.0 {
            if b0 != 0.0 {
                return Err(TheoryError::TransverseMomentumAtPole {
                    theta,
                    p_phi,
                    p_psi,
                });
            }
            0.0
        } else {
            b0 / s
        };
        let a0 = theta_dot * theta_dot + phi_dot_sin * phi_dot_sin;
        Self::build(theory, theta, theta_dot, a0, b0, p_phi, p_psi)
    }

    /// The motion from ZXZ angles q = (φ, θ, ψ) and rates q̇ = (φ̇, θ̇, ψ̇).
    ///
    /// At sin θ = 0 the chart is singular but the state is not: the axis is vertical, and
    /// φ̇ and ψ̇ enter only through ω3 = ψ̇ + φ̇ cos θ.
    ///
    /// # Errors
    /// [`TheoryError::NonFinite`]; as [`HeavyTopMotion::new`].
    pub fn from_angles(
        theory: HeavyTopTheory,
        q: &[f64; 3],
        q_dot: &[f64; 3],
    ) -> Result<Self, TheoryError> {
        for (quantity, v) in [("q", q), ("q̇", q_dot)] {
            for value in v {
                finite(quantity, *value)?;
            }
        }
        let theta = q[1];
        let (s, c) = theta.sin_cos();
        let [phi_dot, theta_dot, psi_dot] = *q_dot;
        let p_psi = theory.i3() * (psi_dot + phi_dot * c);
        // B0 = φ̇ sin²θ directly: p_φ − p_ψ cos θ would cancel.
        let b0 = phi_dot * s * s;
        let p_phi = theory.i1() * b0 + p_psi * c;
        let a0 = theta_dot * theta_dot + (phi_dot * s).powi(2);
        Self::build(theory, theta, theta_dot, a0, b0, p_phi, p_psi)
    }

    fn build(
        theory: HeavyTopTheory,
        theta: f64,
        theta_dot: f64,
        a0: f64,
        b0: f64,
        p_phi: f64,
        p_psi: f64,
    ) -> Result<Self, TheoryError> {
        let (i1, i3, mgl) = (theory.i1(), theory.i3(), theory.mgl());
        let (s, c) = theta.sin_cos();
        let sign = mgl.signum();
        let beta = 2.0 * mgl.abs() / i1;
        let (a, b) = (sign * p_psi / i1, p_phi / i1);
        let u0 = sign * c;
        // 1 ∓ cos θ = 2 sin²(θ/2), 2 cos²(θ/2): no cancellation near the poles.
        let (down, up) = (
            2.0 * (theta / 2.0).sin().powi(2),
            2.0 * (theta / 2.0).cos().powi(2),
        );
        let (one_minus0, one_plus0) = if sign > 0.0 { (down, up) } else { (up, down) };
        let s2 = s * s;
        let cubic = ShiftedCubic {
            f0: theta_dot * theta_dot * s2,
            f1: -2.0 * a0 * u0 - beta * s2 + 2.0 * a * b0,
            f2: -a0 + 2.0 * beta * u0 - a * a,
            beta,
        };
        let x = cubic.roots(-one_plus0, one_minus0);
        let energy = 0.5 * i1 * a0 + 0.5 * p_psi * p_psi / i3 + mgl * c;
        let (d21, d31, d32) = (x[1] - x[0], x[2] - x[0], x[2] - x[1]);
        let (m, mc) = if d31 > 0.0 {
            (d21 / d31, d32 / d31)
        } else {
            (0.0, 1.0)
        };
        let k = ellip_k(mc)?;
        let rate = 0.5 * (beta * d31).sqrt();
        let phase = if d21 == 0.0 || (mc == 0.0 && x[1] == 0.0) {
            // No nutation, or at rest on the unstable side of a separatrix.
            None
        } else {
            let (sn2, cn2) = (-x[0] / d21, x[1] / d21);
            let f = sn2.sqrt() * rf(cn2, 1.0 - m * sn2, 1.0)?;
            // u̇′ = −σ θ̇ sin θ: τ runs forward from θ_max (u1′) when u′ rises.
            Some(if -sign * theta_dot * s < 0.0 { -f } else { f })
        };
        Ok(HeavyTopMotion {
            theory,
            theta0: theta,
            energy,
            p_phi,
            p_psi,
            a0,
            b0,
            sign,
            beta,
            a,
            b,
            one_minus0,
            one_plus0,
            x,
            mc,
            k,
            rate,
            phase,
        })
    }

    /// The top's parameters.
    pub fn theory(&self) -> HeavyTopTheory {
        self.theory
    }

    /// The energy E = ½ I1 (θ̇² + φ̇² sin²θ) + ½ I3 ω3² + M g l cos θ.
    pub fn energy(&self) -> f64 {
        self.energy
    }

    /// p_φ = I1 φ̇ sin²θ + I3 ω3 cos θ, the angular momentum about the vertical.
    pub fn p_phi(&self) -> f64 {
        self.p_phi
    }

    /// p_ψ = I3 ω3, the angular momentum about the symmetry axis.
    pub fn p_psi(&self) -> f64 {
        self.p_psi
    }

    /// The axial spin ω3 = ψ̇ + φ̇ cos θ, constant.
    pub fn omega3(&self) -> f64 {
        self.p_psi / self.theory.i3()
    }

    /// The coefficients [c0, c1, c2, c3] of f(u) = u̇² = c3 u³ + c2 u² + c1 u + c0:
    /// β, −(α + a²), 2ab − β and α − b², in ascending powers.
    pub fn cubic_coefficients(&self) -> [f64; 4] {
        let (beta, a, b) = (self.sign * self.beta, self.sign * self.a, self.b);
        let alpha = self.a0 + beta * self.theta0.cos();
        [alpha - b * b, 2.0 * a * b - beta, -(alpha + a * a), beta]
    }

    /// f(u) = (α − β u)(1 − u²) − (b − a u)², formed about the initial u0 so that it keeps
    /// its digits near the roots (any real u; |u| > 1 gives the cubic's value all the same).
    pub fn cubic_at(&self, u: f64) -> f64 {
        let (beta, a) = (self.sign * self.beta, self.sign * self.a);
        let dx = u - self.theta0.cos();
        (self.a0 - beta * dx) * (1.0 - u * u) - (self.b0 - a * dx).powi(2)
    }

    /// The roots [u1, u2, u3] of f: u1 ≤ u2 the turning points cos θ_max, cos θ_min in
    /// [−1, 1], and the third root (≥ 1 for M g l > 0, ≤ −1 for M g l < 0).
    pub fn roots(&self) -> [f64; 3] {
        let u = |i: usize| self.sign * (self.sign * self.theta0.cos() + self.x[i]);
        if self.sign > 0.0 {
            [u(0), u(1), u(2)]
        } else {
            [u(1), u(0), u(2)]
        }
    }

    /// θ from 1 − u′ and 1 + u′ (each ≥ 0), by half angles.
    fn theta_of(&self, one_minus: f64, one_plus: f64) -> f64 {
        let (down, up) = (one_minus.max(0.0).sqrt(), one_plus.max(0.0).sqrt());
        if self.sign > 0.0 {
            2.0 * down.atan2(up)
        } else {
            2.0 * up.atan2(down)
        }
    }

    fn one_minus(&self, i: usize) -> f64 {
        self.one_minus0 - self.x[i]
    }

    fn one_plus(&self, i: usize) -> f64 {
        self.one_plus0 + self.x[i]
    }

    /// The two turning angles, [θ at u1′, θ at u2′].
    fn turning_thetas(&self) -> [f64; 2] {
        [0, 1].map(|i| self.theta_of(self.one_minus(i), self.one_plus(i)))
    }

    /// The two turning angles, θ0 twice when θ stays put (at rest on a separatrix, θ never
    /// leaves the unstable equilibrium however far the cubic's band reaches).
    fn turning_thetas_reached(&self) -> [f64; 2] {
        match self.phase {
            Some(_) => self.turning_thetas(),
            None if self.x[1] > self.x[0] => [self.theta0; 2],
            None => self.turning_thetas(),
        }
    }

    /// The smallest θ reached (the axis highest).
    pub fn theta_min(&self) -> f64 {
        let [t1, t2] = self.turning_thetas_reached();
        t1.min(t2)
    }

    /// The largest θ reached (the axis lowest).
    pub fn theta_max(&self) -> f64 {
        let [t1, t2] = self.turning_thetas_reached();
        t1.max(t2)
    }

    /// The elliptic parameter m = (u2 − u1)/(u3 − u1) of the nutation (0 for none).
    pub fn parameter(&self) -> f64 {
        1.0 - self.mc
    }

    /// The nutation period T = 2K(m)/ν, ν = √(M g l (u3 − u1)/(2 I1)): the time between two
    /// θ_max. For zero nutation, the limit π/ν (the period of small nutation); +∞ on a
    /// separatrix or at the sleeping threshold.
    pub fn nutation_period(&self) -> f64 {
        if self.rate == 0.0 {
            f64::INFINITY
        } else {
            2.0 * self.k / self.rate
        }
    }

    /// The first times t ≥ 0 at which θ = θ_max and θ = θ_min, or `None` when θ stays put
    /// (zero nutation, or at rest on a separatrix).
    pub fn turning_times(&self) -> Option<[f64; 2]> {
        let tau0 = self.phase?;
        if !self.k.is_finite() {
            // On a separatrix θ reaches its limit only as t → ∞; the other turning point is
            // passed at most once.
            let t = -tau0 / self.rate;
            return Some(if self.sign > 0.0 {
                [t.max(0.0), f64::INFINITY]
            } else {
                [f64::INFINITY, t.max(0.0)]
            });
        }
        let period = 2.0 * self.k;
        // u′ = u1′ at τ ≡ 0 and u′ = u2′ at τ ≡ K (mod 2K).
        let first = |target: f64| (target - tau0).rem_euclid(period) / self.rate;
        let (at_u1, at_u2) = (first(0.0), first(self.k));
        Some(if self.sign > 0.0 {
            [at_u1, at_u2]
        } else {
            [at_u2, at_u1]
        })
    }

    /// θ(t) in closed form: u′(t) = u1′ + (u2′ − u1′) sn²(ν t + τ0 | m), θ by half angles
    /// from 1 ∓ u′ = (1 ∓ u1′) cn² + (1 ∓ u2′) sn² (both sums of non-negative terms).
    ///
    /// # Errors
    /// [`TheoryError::NonFinite`] for a non-finite t; [`TheoryError::Exact`] if ν t exceeds
    /// the range where sn can be reduced accurately (about 1e15).
    pub fn theta_at(&self, t: f64) -> Result<f64, TheoryError> {
        let (one_minus, one_plus) = self.halves_at(t)?;
        Ok(self.theta_of(one_minus, one_plus))
    }

    /// cos θ(t).
    ///
    /// # Errors
    /// As [`HeavyTopMotion::theta_at`].
    pub fn cos_theta_at(&self, t: f64) -> Result<f64, TheoryError> {
        let (one_minus, one_plus) = self.halves_at(t)?;
        Ok(self.sign * 0.5 * (one_plus - one_minus))
    }

    /// (1 − u′(t), 1 + u′(t)).
    fn halves_at(&self, t: f64) -> Result<(f64, f64), TheoryError> {
        finite("t", t)?;
        let Some(tau0) = self.phase else {
            return Ok((self.one_minus0, self.one_plus0));
        };
        let (sn, cn, _) = sncndn(self.rate * t + tau0, self.mc)?;
        let (sn2, cn2) = (sn * sn, cn * cn);
        Ok((
            self.one_minus(0) * cn2 + self.one_minus(1) * sn2,
            self.one_plus(0) * cn2 + self.one_plus(1) * sn2,
        ))
    }

    /// φ̇ = ½((b − a′)/(1 − u′) + (b + a′)/(1 + u′)), a term dropped when its numerator is 0
    /// (its limit at the pole it would divide by).
    fn phi_dot(&self, one_minus: f64, one_plus: f64) -> f64 {
        let (minus, plus) = (self.b - self.a, self.b + self.a);
        let left = if minus == 0.0 { 0.0 } else { minus / one_minus };
        let right = if plus == 0.0 { 0.0 } else { plus / one_plus };
        0.5 * (left + right)
    }

    /// The precession rate φ̇ = (p_φ − p_ψ u)/(I1 (1 − u²)) where cos θ = u.
    ///
    /// # Errors
    /// [`TheoryError::NonFinite`], [`TheoryError::CosineOutOfRange`] for |u| > 1, and
    /// [`TheoryError::OutsideNutationBand`] for a u the motion never reaches.
    pub fn precession_rate_at(&self, u: f64) -> Result<f64, TheoryError> {
        finite("u", u)?;
        if u.abs() > 1.0 {
            return Err(TheoryError::CosineOutOfRange { u });
        }
        let [u_min, u_max, _] = self.roots();
        if u < u_min - BAND_SLACK || u > u_max + BAND_SLACK {
            return Err(TheoryError::OutsideNutationBand { u, u_min, u_max });
        }
        let rate = self.phi_dot(1.0 - self.sign * u, 1.0 + self.sign * u);
        finite("φ̇", rate)
    }

    /// The mean precession rate ⟨φ̇⟩ over a nutation period, through the complete integral
    /// of the third kind (see the type's docs). The limit on a separatrix (the rate at the
    /// asymptotic θ) and for zero nutation (the steady rate).
    ///
    /// # Errors
    /// [`TheoryError::Exact`] should a Carlson integral leave its domain (not seen for a
    /// physical state).
    pub fn mean_precession_rate(&self) -> Result<f64, TheoryError> {
        if self.mc == 0.0 {
            return Ok(self.phi_dot(self.one_minus(1), self.one_plus(1)));
        }
        let (om1, op1) = (self.one_minus(0), self.one_plus(0));
        let base = self.phi_dot(om1, op1);
        let d21 = self.x[1] - self.x[0];
        if d21 == 0.0 {
            return Ok(base);
        }
        let (minus, plus) = (self.b - self.a, self.b + self.a);
        let mut sum = 0.0;
        if minus != 0.0 {
            // (b − a′)² = β (1 − u1′)(1 − u2′)(u3′ − 1): 1 − u2′ from it when rounding leaves
            // nothing of the difference (u2′ within an ulp of 1).
            let mut om2 = self.one_minus(1);
            if om2 <= 0.0 {
                om2 = minus * minus / (self.beta * om1 * (self.x[2] - self.one_minus0));
            }
            sum += minus * rj(0.0, self.mc, 1.0, om2 / om1)? / (om1 * om1);
        }
        if plus != 0.0 {
            let op2 = self.one_plus(1);
            sum -= plus * rj(0.0, self.mc, 1.0, op2 / op1)? / (op1 * op1);
        }
        finite("⟨φ̇⟩", base + d21 * sum / (6.0 * self.k))
    }
}
