//! The symmetric heavy top's parameters and the answers that need no initial state: steady
//! precession, its small nutation, the sleeping top, and the reduced system in θ.

use nalgebra::{DMatrix, Vector3};

use super::error::{TheoryError, finite};
use super::motion::HeavyTopMotion;
use crate::linalg::LinearSystem;

/// The largest relative difference |I1 − I2| / max(I1, I2) that
/// [`HeavyTopTheory::from_principal`] takes as a symmetric top.
pub const SYMMETRY_TOLERANCE: f64 = 1e-12;

/// The relative residual below which (θ, Ω, ω3) counts as a steady precession.
pub const STEADY_TOLERANCE: f64 = 1e-8;

/// The symmetric heavy top: transverse moment I1 = I2 and axial moment I3 about the pivot,
/// and the gravity torque scale M g l (l from the pivot to the centre of mass along the
/// symmetry axis, positive above the pivot; a negative M g l is a top hanging below it).
///
/// With the ZXZ angles (φ, θ, ψ) of the symmetry axis (θ from the vertical) and the axial
/// spin ω3 = ψ̇ + φ̇ cos θ, the Lagrangian
/// L = ½ I1 (θ̇² + φ̇² sin²θ) + ½ I3 ω3² − M g l cos θ has the conserved momenta
/// p_ψ = I3 ω3 and p_φ = I1 φ̇ sin²θ + p_ψ cos θ, and the energy
/// E = ½ I1 (θ̇² + φ̇² sin²θ) + ½ I3 ω3² + M g l cos θ.
///
/// # Examples
///
/// The reference top I1 = 1, I3 = ½, M g l = 1 at θ = 60° with ω3 = 10 precesses steadily at
/// Ω = 0.204168476687 or 9.795831523313 rad/s; it sleeps stably above ω3 = 4 rad/s:
///
/// ```
/// use approx::assert_relative_eq;
/// use precess_core::top::{HeavyTopTheory, SleepingTop};
///
/// let top = HeavyTopTheory::new(1.0, 0.5, 1.0)?;
/// let steady = top.steady_precession(std::f64::consts::FRAC_PI_3, 10.0)?;
/// assert_relative_eq!(steady.slow, 0.204168476687, max_relative = 1e-11);
/// assert_relative_eq!(steady.fast.unwrap(), 9.795831523313, max_relative = 1e-12);
/// assert_relative_eq!(top.sleeping_threshold(), 4.0);
/// assert!(matches!(top.sleeping_top(3.9)?, SleepingTop::Unstable { .. }));
/// # Ok::<(), precess_core::top::TheoryError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeavyTopTheory {
    i1: f64,
    i3: f64,
    mgl: f64,
}

/// The two steady precession rates at one θ and ω3: the roots of
/// I1 cos θ Ω² − I3 ω3 Ω + M g l = 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyPrecession {
    /// The tilt θ.
    pub theta: f64,
    /// The axial spin ω3 = ψ̇ + φ̇ cos θ (held fixed, as p_ψ = I3 ω3 is).
    pub omega3: f64,
    /// The root of smaller magnitude: M g l / (I3 ω3) in the fast-top limit.
    pub slow: f64,
    /// The other root, I3 ω3 / (I1 cos θ) in the fast-top limit; `None` at cos θ = 0, where
    /// the balance is linear in Ω.
    pub fast: Option<f64>,
}

impl SteadyPrecession {
    /// The ZXZ rates (φ̇, θ̇, ψ̇) = (Ω, 0, ω3 − Ω cos θ) of the steady precession at Ω.
    pub fn rates(&self, precession: f64) -> [f64; 3] {
        [precession, 0.0, self.omega3 - precession * self.theta.cos()]
    }
}

/// The upright sleeping top (θ = 0, spinning at ω3) and its linear stability.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SleepingTop {
    /// ω3² > 4 M g l I1 / I3²: small tilts precess in cones at the two rates
    /// (I3 ω3 ∓ √(I3² ω3² − 4 I1 M g l)) / (2 I1), the steady precessions at θ → 0.
    Stable {
        /// The slower cone rate.
        slow: f64,
        /// The faster cone rate.
        fast: f64,
    },
    /// ω3² < 4 M g l I1 / I3²: small tilts grow at √(4 I1 M g l − I3² ω3²) / (2 I1) while
    /// turning at I3 ω3 / (2 I1).
    Unstable {
        /// The exponential growth rate of a small tilt.
        growth_rate: f64,
        /// The rate at which the growing tilt turns about the vertical.
        rotation_rate: f64,
    },
    /// ω3² = 4 M g l I1 / I3² exactly: the two cone rates merge at I3 ω3 / (2 I1); tilts
    /// grow linearly in time.
    Threshold {
        /// The merged cone rate.
        rate: f64,
    },
}

impl HeavyTopTheory {
    /// The top with transverse moment `i1` = I1 = I2 and axial moment `i3` about the pivot,
    /// and `mgl` = M g l.
    ///
    /// # Errors
    /// [`TheoryError::NonFinite`], [`TheoryError::NonPositiveMoment`], and
    /// [`TheoryError::NoGravity`] for M g l = 0 (see [`super::TorqueFreeSymmetric`]).
    pub fn new(i1: f64, i3: f64, mgl: f64) -> Result<Self, TheoryError> {
        for (moment, value) in [("I1", i1), ("I3", i3)] {
            finite(moment, value)?;
            if value <= 0.0 {
                return Err(TheoryError::NonPositiveMoment { moment, value });
            }
        }
        finite("M g l", mgl)?;
        if mgl == 0.0 {
            return Err(TheoryError::NoGravity);
        }
        Ok(HeavyTopTheory { i1, i3, mgl })
    }

    /// The top from principal moments about the pivot (I1, I2, I3), axis 3 the symmetry
    /// axis, as [`crate::body::Principal::moments`] gives them.
    ///
    /// # Errors
    /// [`TheoryError::NotSymmetric`] if I1 and I2 differ by more than
    /// [`SYMMETRY_TOLERANCE`] relative; as [`HeavyTopTheory::new`].
    pub fn from_principal(moments: impl Into<Vector3<f64>>, mgl: f64) -> Result<Self, TheoryError> {
        let moments = moments.into();
        let (i1, i2, i3) = (moments.x, moments.y, moments.z);
        finite("I2", i2)?;
        let me = Self::new(i1, i3, mgl)?;
        let relative = (i1 - i2).abs() / i1.max(i2);
        if relative.is_nan() || relative > SYMMETRY_TOLERANCE {
            return Err(TheoryError::NotSymmetric {
                i1,
                i2,
                relative,
                limit: SYMMETRY_TOLERANCE,
            });
        }
        Ok(me)
    }

    /// I1 = I2, the transverse moment about the pivot.
    pub fn i1(&self) -> f64 {
        self.i1
    }

    /// I3, the axial moment.
    pub fn i3(&self) -> f64 {
        self.i3
    }

    /// M g l.
    pub fn mgl(&self) -> f64 {
        self.mgl
    }

    /// The exact motion from θ, θ̇ and the conserved momenta p_φ, p_ψ.
    ///
    /// # Errors
    /// As [`HeavyTopMotion::new`].
    pub fn motion(
        &self,
        theta: f64,
        theta_dot: f64,
        p_phi: f64,
        p_psi: f64,
    ) -> Result<HeavyTopMotion, TheoryError> {
        HeavyTopMotion::new(*self, theta, theta_dot, p_phi, p_psi)
    }

    /// The exact motion from ZXZ angles q = (φ, θ, ψ) and rates q̇.
    ///
    /// # Errors
    /// As [`HeavyTopMotion::from_angles`].
    pub fn motion_from_angles(
        &self,
        q: &[f64; 3],
        q_dot: &[f64; 3],
    ) -> Result<HeavyTopMotion, TheoryError> {
        HeavyTopMotion::from_angles(*self, q, q_dot)
    }

    /// The steady precession rates at tilt θ and axial spin ω3 (= ψ̇ + φ̇ cos θ): the roots of
    /// I1 cos θ Ω² − I3 ω3 Ω + M g l = 0, the θ̈ = 0 balance at θ̇ = 0.
    ///
    /// The roots are formed without cancellation: with
    /// q = ½ (I3 ω3 + sgn(ω3) √(I3² ω3² − 4 I1 M g l cos θ)), they are M g l / q and
    /// q / (I1 cos θ).
    ///
    /// # Errors
    /// [`TheoryError::NonFinite`]; [`TheoryError::NoSteadyPrecession`] when the
    /// discriminant is negative (the spin is too slow for this θ).
    pub fn steady_precession(
        &self,
        theta: f64,
        omega3: f64,
    ) -> Result<SteadyPrecession, TheoryError> {
        finite("θ", theta)?;
        finite("ω3", omega3)?;
        let c = theta.cos();
        let spin = self.i3 * omega3;
        let disc = spin * spin - 4.0 * self.i1 * self.mgl * c;
        if disc < 0.0 {
            return Err(TheoryError::NoSteadyPrecession {
                theta,
                omega3,
                min_omega3: (4.0 * self.i1 * self.mgl * c).sqrt() / self.i3,
            });
        }
        let sign = if spin >= 0.0 { 1.0 } else { -1.0 };
        let q = 0.5 * (spin + sign * disc.sqrt());
        let (r1, r2) = (self.mgl / q, q / (self.i1 * c));
        let (slow, fast) = if c == 0.0 {
            (r1, None)
        } else if r1.abs() <= r2.abs() {
            (r1, Some(r2))
        } else {
            (r2, Some(r1))
        };
        Ok(SteadyPrecession {
            theta,
            omega3,
            slow,
            fast,
        })
    }

    /// The angular frequency of small nutation about the steady precession at (θ, Ω, ω3):
    /// ω_n = √((a − 2 Ω cos θ)² + Ω² sin²θ), a = I3 ω3 / I1.
    ///
    /// From the reduced system θ̈ = F(θ) at fixed p_φ, p_ψ (see
    /// [`HeavyTopTheory::reduced_linearisation`]): ω_n² = −F′(θ), simplified with the
    /// balance cos θ Ω² − a Ω + M g l / I1 = 0. A sum of squares, so steady precession is
    /// never linearly unstable. In the fast-top limit Ω → M g l/(I3 ω3), ω_n → I3 ω3 / I1.
    ///
    /// # Errors
    /// [`TheoryError::NonFinite`]; [`TheoryError::NotSteady`] unless the balance vanishes
    /// to [`STEADY_TOLERANCE`] relative.
    pub fn small_nutation_frequency(
        &self,
        theta: f64,
        precession: f64,
        omega3: f64,
    ) -> Result<f64, TheoryError> {
        finite("θ", theta)?;
        finite("Ω", precession)?;
        finite("ω3", omega3)?;
        let (s, c) = theta.sin_cos();
        let terms = [
            self.i1 * c * precession * precession,
            -self.i3 * omega3 * precession,
            self.mgl,
        ];
        let residual: f64 = terms.iter().sum();
        let relative = residual.abs() / terms.iter().map(|t| t.abs()).sum::<f64>();
        if relative > STEADY_TOLERANCE {
            return Err(TheoryError::NotSteady {
                theta,
                precession,
                omega3,
                residual,
                relative,
            });
        }
        let a = self.i3 * omega3 / self.i1;
        Ok((a - 2.0 * precession * c).hypot(precession * s))
    }

    /// The reduced (Routh) system in (θ, θ̇) at fixed p_φ, p_ψ, linearised at θ:
    /// A = [[0, 1], [F′(θ), 0]] for θ̈ = F(θ), with a = p_ψ/I1, b = p_φ/I1 and
    ///
    /// ```text
    /// F(θ)  = (b − a cos θ)(b cos θ − a)/sin³θ + (M g l/I1) sin θ,
    /// F′(θ) = (2ab cos θ − a² − b²)/sin²θ − 3 cos θ (b − a cos θ)(b cos θ − a)/sin⁴θ
    ///         + (M g l/I1) cos θ.
    /// ```
    ///
    /// At an equilibrium (F(θ) = 0, a steady precession) the eigenvalues are ±i ω_n with
    /// ω_n the [`HeavyTopTheory::small_nutation_frequency`].
    ///
    /// # Errors
    /// [`TheoryError::NonFinite`]; [`TheoryError::SingularAtPole`] at sin θ = 0.
    pub fn reduced_linearisation(
        &self,
        theta: f64,
        p_phi: f64,
        p_psi: f64,
    ) -> Result<LinearSystem, TheoryError> {
        finite("θ", theta)?;
        finite("p_φ", p_phi)?;
        finite("p_ψ", p_psi)?;
        let (s, c) = theta.sin_cos();
        if s == 0.0 {
            return Err(TheoryError::SingularAtPole { theta });
        }
        let (a, b) = (p_psi / self.i1, p_phi / self.i1);
        let (s2, half_beta) = (s * s, self.mgl / self.i1);
        let slope = (2.0 * a * b * c - a * a - b * b) / s2
            - 3.0 * c * (b - a * c) * (b * c - a) / (s2 * s2)
            + half_beta * c;
        finite("F′(θ)", slope)?;
        let matrix = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, slope, 0.0]);
        LinearSystem::new(matrix).map_err(|_| TheoryError::NonFinite {
            quantity: "F′(θ)",
            value: slope,
        })
    }

    /// The spin above which the upright top sleeps stably: ω3² > 4 M g l I1 / I3², so
    /// √(4 M g l I1) / I3 (0 for a hanging top, M g l < 0, which is always stable upright
    /// in this sense: the axis then points down from the pivot).
    pub fn sleeping_threshold(&self) -> f64 {
        (4.0 * self.mgl.max(0.0) * self.i1).sqrt() / self.i3
    }

    /// The upright top's linear stability at axial spin ω3: the small tilt ξ = x + i y of
    /// the axis obeys I1 ξ̈ − i I3 ω3 ξ̇ − M g l ξ = 0, so ξ ∝ e^{iσt} with
    /// I1 σ² − I3 ω3 σ + M g l = 0 (the steady precession balance at θ = 0).
    ///
    /// # Errors
    /// [`TheoryError::NonFinite`] for a non-finite ω3.
    pub fn sleeping_top(&self, omega3: f64) -> Result<SleepingTop, TheoryError> {
        finite("ω3", omega3)?;
        let spin = self.i3 * omega3;
        let disc = spin * spin - 4.0 * self.i1 * self.mgl;
        let centre = spin / (2.0 * self.i1);
        if disc > 0.0 {
            let steady = self.steady_precession(0.0, omega3)?;
            Ok(SleepingTop::Stable {
                slow: steady.slow,
                fast: steady.fast.unwrap_or(f64::INFINITY),
            })
        } else if disc < 0.0 {
            Ok(SleepingTop::Unstable {
                growth_rate: (-disc).sqrt() / (2.0 * self.i1),
                rotation_rate: centre,
            })
        } else {
            Ok(SleepingTop::Threshold { rate: centre })
        }
    }
}
