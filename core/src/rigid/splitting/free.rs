//! The free rigid body split into exact rotations.
//!
//! The free-body energy T = ½ Σ mᵢ²/Iᵢ is split as
//! T = ½|m|²/I₂ + ½ m₁²(1/I₁ − 1/I₂) + ½ m₃²(1/I₃ − 1/I₂):
//! each part is an exact rotation about a body axis (or about m), so |m| is conserved to
//! round-off and the attitude stays a unit quaternion. The |m|² part is a Casimir: it commutes
//! with the others and is applied once per step. Strang gives order 2; the triple jump
//! (Yoshida 1990) gives 4, and applied again, 6.

use nalgebra::{Quaternion, UnitQuaternion, Vector3};

use crate::exact::array;
use crate::ode::{OdeError, Stats, check_inertia, two_sum};
use crate::rigid::kinematics::{exp_rotation, rotate_body};
use crate::rigid::state::{BodyMomentum, check_momentum, momentum_is_finite};

/// Order of the composed method.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SplittingOrder {
    /// Strang splitting, order 2 (one rotation pair per step).
    #[default]
    Two,
    /// Triple jump of Strang, order 4 (3 Strang steps).
    Four,
    /// Triple jump of the order-4 method, order 6 (9 Strang steps).
    Six,
}

/// Triple-jump weights (γ₁, γ₂, γ₁) raising a symmetric method of order p to p + 2.
fn triple_jump(p: i32) -> (f64, f64) {
    let r = 2f64.powf(1.0 / (p as f64 + 1.0));
    (1.0 / (2.0 - r), -r / (2.0 - r))
}

/// The low-order bits of (q, m) that compensated summation carries beside a
/// [`BodyMomentum`] from one rotation to the next.
///
/// A rotation written as y ← R y rounds every component at ε|y| whatever the angle, and
/// near the separatrix those √n·ε steps, amplified by the motion's sensitivity, set a floor
/// near 1e-10 (measured on I = (3, 5, 9), T = 200). Written as y ← y + (R − I) y with the
/// increment (of size θ|y|) added by TwoSum and its rounding kept here, the round-off per
/// rotation falls to θ·ε.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct Carry {
    q: Quaternion<f64>,
    m: Vector3<f64>,
}

impl Carry {
    /// Adds `dq`, `dm` to y with compensation.
    #[inline]
    fn add(&mut self, y: &mut BodyMomentum, dq: &Quaternion<f64>, dm: &Vector3<f64>) {
        let mut q = *y.q.quaternion();
        for ((hi, lo), d) in q
            .coords
            .iter_mut()
            .zip(self.q.coords.iter_mut())
            .zip(&dq.coords)
        {
            (*hi, *lo) = two_sum(*hi, d + *lo);
        }
        // Off unit by round-off only (the increment keeps |q| to θ·ε): normalised in `finish`.
        y.q = UnitQuaternion::new_unchecked(q);
        for ((hi, lo), d) in y.m.iter_mut().zip(self.m.iter_mut()).zip(dm) {
            (*hi, *lo) = two_sum(*hi, d + *lo);
        }
    }

    /// Folds the carried bits into y and renormalises q once.
    pub(crate) fn finish(&mut self, y: &mut BodyMomentum) {
        y.q = UnitQuaternion::new_normalize(y.q.quaternion() + self.q);
        y.m += self.m;
        *self = Self::default();
    }
}

/// cos x − 1 = −sin²x/(1 + cos x) without cancellation for |x| < π/2.
#[inline]
fn cos_minus_one(s: f64, c: f64) -> f64 {
    if c > 0.0 { -s * s / (1.0 + c) } else { c - 1.0 }
}

/// Turns the body by `theta` about body axis `axis`: q ← q ⊗ exp(θ eₐ/2), m ← Rᵀ m.
/// m gets its own correctly rounded sin_cos θ: deriving it from θ/2 (c² − s², 2sc)
/// costs |m| a visibly larger random walk. With `carry` the update is the compensated
/// increment form (see [`Carry`]); without it, the plain rotation.
#[inline]
fn axis_rotation(y: &mut BodyMomentum, carry: Option<&mut Carry>, axis: usize, theta: f64) {
    let (s, c) = theta.sin_cos();
    // Half-angle for q without a second sin_cos (q is renormalised anyway); |θ| ≥ π/2
    // would lose digits in 1 + cos θ, so those take the direct route.
    let (sh, ch) = if c > 0.0 {
        let ch = (0.5 * (1.0 + c)).sqrt();
        (0.5 * s / ch, ch)
    } else {
        (0.5 * theta).sin_cos()
    };
    let mut e = [0.0; 3];
    e[axis] = sh;
    let (a, b) = ((axis + 1) % 3, (axis + 2) % 3);
    let (ma, mb) = (y.m[a], y.m[b]);
    let Some(carry) = carry else {
        let q = y.q.quaternion() * Quaternion::new(ch, e[0], e[1], e[2]);
        y.q = UnitQuaternion::new_normalize(q);
        // One rounding fewer per component than c·a + s·b: less random walk in |m|.
        y.m[a] = c.mul_add(ma, s * mb);
        y.m[b] = c.mul_add(mb, -(s * ma));
        return;
    };
    let dq = y.q.quaternion() * Quaternion::new(cos_minus_one(sh, ch), e[0], e[1], e[2]);
    let cm1 = cos_minus_one(s, c);
    let mut dm = Vector3::zeros();
    dm[a] = cm1.mul_add(ma, s * mb);
    dm[b] = cm1.mul_add(mb, -(s * ma));
    carry.add(y, &dq, &dm);
}

/// The free rigid body split into exact rotations.
///
/// ```
/// use nalgebra::{UnitQuaternion, Vector3};
/// use precess_core::rigid::{BodyMomentum, FreeBodySplitting, SplittingOrder};
/// let s = FreeBodySplitting::new([2.0, 1.0, 2.0 / 3.0], SplittingOrder::Four)?;
/// let mut y = BodyMomentum { q: UnitQuaternion::identity(), m: Vector3::new(1.1f64.cos(), 0.0, 1.1f64.sin()) };
/// for _ in 0..1000 {
///     s.step(&mut y, 0.01)?;
/// }
/// // m(10) of the GNI book's body.
/// approx::assert_relative_eq!(y.m.x, 0.407_066_136_588_040_8, epsilon = 1e-8);
/// approx::assert_relative_eq!(y.m.norm(), 1.0, epsilon = 1e-14);
/// # Ok::<(), precess_core::ode::OdeError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FreeBodySplitting {
    inertia: [f64; 3],
    /// 1/I₁ − 1/I₂ and 1/I₃ − 1/I₂.
    a1: f64,
    a3: f64,
    order: SplittingOrder,
    /// Compensated rotations (default); see [`FreeBodySplitting::with_compensation`].
    compensated: bool,
}

impl FreeBodySplitting {
    /// A splitting of the given order for principal moments `inertia`.
    ///
    /// # Errors
    /// [`OdeError::InvalidInertia`] unless the moments are finite and > 0.
    pub fn new(inertia: impl Into<Vector3<f64>>, order: SplittingOrder) -> Result<Self, OdeError> {
        let inertia = array(inertia);
        check_inertia(1.0, inertia)?;
        Ok(Self {
            inertia,
            a1: 1.0 / inertia[0] - 1.0 / inertia[1],
            a3: 1.0 / inertia[2] - 1.0 / inertia[1],
            order,
            compensated: true,
        })
    }

    /// The same splitting with compensated summation on (`true`, the default) or off.
    ///
    /// Compensated, every rotation is applied as y ← y + (R − I) y with the increment's
    /// rounding carried to the next rotation, so round-off per rotation is θ·ε rather than
    /// ε: on I = (3, 5, 9), m(0) = (0, 2, 0.01), T = 200 the error then keeps falling with h
    /// instead of flattening near 1e-10. `false` gives the plain rotations, kept to measure
    /// the difference. [`Self::run`] and [`Self::integrate_to`] carry the bits across steps;
    /// [`Self::step`] (and so a `FixedStepper`) within one step.
    ///
    /// ```
    /// use precess_core::rigid::{FreeBodySplitting, SplittingOrder};
    /// let s = FreeBodySplitting::new([3.0, 5.0, 9.0], SplittingOrder::Four)?;
    /// assert!(s.is_compensated());
    /// assert!(!s.with_compensation(false).is_compensated());
    /// # Ok::<(), precess_core::ode::OdeError>(())
    /// ```
    pub fn with_compensation(self, compensated: bool) -> Self {
        Self {
            compensated,
            ..self
        }
    }

    /// Whether the rotations are summed with compensation.
    pub fn is_compensated(&self) -> bool {
        self.compensated
    }

    /// Principal moments.
    pub fn inertia(&self) -> Vector3<f64> {
        self.inertia.into()
    }

    /// The exact flow of ½ m₁²(1/I₁ − 1/I₂) for time τ: a rotation about body axis 1.
    #[inline]
    fn r1(&self, y: &mut BodyMomentum, c: Option<&mut Carry>, tau: f64) {
        axis_rotation(y, c, 0, tau * self.a1 * y.m.x);
    }

    /// The exact flow of ½ m₃²(1/I₃ − 1/I₂) for time τ: a rotation about body axis 3.
    #[inline]
    fn r3(&self, y: &mut BodyMomentum, c: Option<&mut Carry>, tau: f64) {
        axis_rotation(y, c, 2, tau * self.a3 * y.m.z);
    }

    /// The exact flow of the Casimir part ½|m|²/I₂: m fixed, the body turns about m.
    #[inline]
    fn casimir(&self, y: &mut BodyMomentum, c: Option<&mut Carry>, tau: f64) {
        let phi = y.m * (tau / self.inertia[1]);
        let Some(c) = c else {
            y.q = rotate_body(&y.q, &phi);
            return;
        };
        // exp(φ/2) − 1, its scalar part −2 sin²(θ/4) free of cancellation.
        let mut d = exp_rotation(&phi);
        let sq = (0.25 * phi.norm()).sin();
        d.w = -2.0 * sq * sq;
        c.add(y, &(y.q.quaternion() * d), &Vector3::zeros());
    }

    /// The carry to use: `Some` when compensated.
    #[inline]
    fn carry<'a>(&self, c: &'a mut Carry) -> Option<&'a mut Carry> {
        self.compensated.then_some(c)
    }

    /// Strang sub-step weights of one step: (1), the triple jump, or the triple jump of it.
    fn weights(&self) -> ([f64; 9], usize) {
        let (a1, a2) = triple_jump(2);
        let mut w = [0.0; 9];
        match self.order {
            SplittingOrder::Two => {
                w[0] = 1.0;
                (w, 1)
            }
            SplittingOrder::Four => {
                w[..3].copy_from_slice(&[a1, a2, a1]);
                (w, 3)
            }
            SplittingOrder::Six => {
                let (b1, b2) = triple_jump(4);
                for (j, b) in [b1, b2, b1].iter().enumerate() {
                    w[3 * j..3 * j + 3].copy_from_slice(&[b * a1, b * a2, b * a1]);
                }
                (w, 9)
            }
        }
    }

    /// One step of the configured order: Strang sub-steps R₁(τ/2) R₃(τ) R₁(τ/2) with the
    /// triple-jump weights, and the Casimir rotation (which commutes with both) once.
    ///
    /// # Errors
    /// [`OdeError::InvalidStep`] for h ≤ 0 or non-finite, [`OdeError::NonFiniteInitialState`]
    /// or [`OdeError::NotUnitQuaternion`] for a bad `y`, [`OdeError::NonFiniteState`] (with
    /// t = 0) if the rotation angles overflow; `y` is left as it was on error.
    pub fn step(&self, y: &mut BodyMomentum, h: f64) -> Result<(), OdeError> {
        check_step(h)?;
        check_momentum(y)?;
        let mut z = *y;
        self.step_unchecked(&mut z, h);
        if !momentum_is_finite(&z) {
            return Err(OdeError::NonFiniteState { t: 0.0 });
        }
        *y = z;
        Ok(())
    }

    /// [`Self::step`] without its checks, for callers that make them.
    pub(super) fn step_unchecked(&self, y: &mut BodyMomentum, h: f64) {
        let mut c = Carry::default();
        let (w, k) = self.weights();
        for &g in &w[..k] {
            self.r1(y, self.carry(&mut c), 0.5 * g * h);
            self.r3(y, self.carry(&mut c), g * h);
            self.r1(y, self.carry(&mut c), 0.5 * g * h);
        }
        self.casimir(y, self.carry(&mut c), h);
        self.finish(y, &mut c);
    }

    /// Folds the carried bits into y when compensated (the plain rotations carry none).
    #[inline]
    fn finish(&self, y: &mut BodyMomentum, c: &mut Carry) {
        if self.compensated {
            c.finish(y);
        }
    }

    /// `n` steps of size `h`; the same map as `n` calls of [`Self::step`], but adjacent
    /// R₁ half-rotations are merged (flows of one Hamiltonian add), so each Strang sub-step
    /// costs two rotations and |m| sees a third less round-off.
    ///
    /// # Errors
    /// [`OdeError::InvalidStep`] for h ≤ 0 or non-finite; [`OdeError::NonFiniteInitialState`]
    /// or [`OdeError::NotUnitQuaternion`] for a bad `y`; [`OdeError::NonFiniteState`] at the
    /// first step whose rotation angles overflow (t = i·h from the start of the call), with
    /// `y` left at the last finite state (at t).
    pub fn run(&self, y: &mut BodyMomentum, h: f64, n: u64) -> Result<(), OdeError> {
        check_step(h)?;
        check_momentum(y)?;
        let (w, k) = self.weights();
        let weights = &w[..k];
        let mut pending = 0.0;
        let mut c = Carry::default();
        let mut done = 0;
        while done < n {
            // Checked after each block of a few steps (a non-finite component stays
            // non-finite), then replayed to stop at the first bad step.
            let len = CHECK_BLOCK.min(n - done);
            let (y_start, pending_start, c_start) = (*y, pending, c);
            for _ in 0..len {
                self.merged_step(y, &mut c, &mut pending, weights, h);
            }
            if !momentum_is_finite(y) {
                (*y, pending, c) = (y_start, pending_start, c_start);
                for i in done..done + len {
                    let (y_prev, pending_prev, c_prev) = (*y, pending, c);
                    self.merged_step(y, &mut c, &mut pending, weights, h);
                    if !momentum_is_finite(y) {
                        // The last finite state, with its pending half rotation applied.
                        (*y, c) = (y_prev, c_prev);
                        self.r1(y, self.carry(&mut c), pending_prev);
                        self.finish(y, &mut c);
                        return Err(OdeError::NonFiniteState { t: i as f64 * h });
                    }
                }
            }
            done += len;
        }
        self.r1(y, self.carry(&mut c), pending);
        self.finish(y, &mut c);
        Ok(())
    }

    /// Advances y over the span `t_span` ≥ 0 in steps of `h`, the last one partial so that
    /// it lands exactly on `t_span`: ⌊t_span/h⌋ full steps by [`Self::run`] (a remainder
    /// below 10⁻¹² h is dropped), then one step of the remainder. Returns the steps taken.
    ///
    /// ```
    /// use nalgebra::{UnitQuaternion, Vector3};
    /// use precess_core::exact::FreeBodyExact;
    /// use precess_core::rigid::{BodyMomentum, FreeBodySplitting, SplittingOrder};
    /// let (i, m0) = ([2.0, 1.0, 2.0 / 3.0], [1.1f64.cos(), 0.0, 1.1f64.sin()]);
    /// let s = FreeBodySplitting::new(i, SplittingOrder::Six)?;
    /// let mut y = BodyMomentum { q: UnitQuaternion::identity(), m: Vector3::from(m0) };
    /// // 0.03 does not divide 10: 333 steps of 0.03 and one of 0.01.
    /// let stats = s.integrate_to(&mut y, 10.0, 0.03)?;
    /// assert_eq!(stats.steps, 334);
    /// let exact = FreeBodyExact::new(i, m0).unwrap().m_at(10.0).unwrap();
    /// approx::assert_relative_eq!(y.m, exact, epsilon = 1e-9);
    /// # Ok::<(), precess_core::ode::OdeError>(())
    /// ```
    ///
    /// # Errors
    /// [`OdeError::InvalidStep`] for h ≤ 0 or non-finite, or a negative or non-finite
    /// `t_span` (as `InvalidStep { h: t_span }`); otherwise as [`Self::run`], with the time
    /// of a failed step counted from the start.
    pub fn integrate_to(
        &self,
        y: &mut BodyMomentum,
        t_span: f64,
        h: f64,
    ) -> Result<Stats, OdeError> {
        check_step(h)?;
        let (n, rest) = full_steps(t_span, h)?;
        self.run(y, h, n)?;
        let mut stats = Stats {
            steps: n,
            ..Stats::default()
        };
        if rest > 0.0 {
            self.step(y, rest).map_err(|e| match e {
                OdeError::NonFiniteState { .. } => OdeError::NonFiniteState { t: n as f64 * h },
                other => other,
            })?;
            stats.steps += 1;
        }
        Ok(stats)
    }

    /// One step of [`Self::run`], leaving its last R₁ half-rotation pending to merge with the
    /// next step's first.
    #[inline]
    fn merged_step(
        &self,
        y: &mut BodyMomentum,
        c: &mut Carry,
        pending: &mut f64,
        weights: &[f64],
        h: f64,
    ) {
        for &g in weights {
            self.r1(y, self.carry(c), *pending + 0.5 * g * h);
            self.r3(y, self.carry(c), g * h);
            *pending = 0.5 * g * h;
        }
        self.casimir(y, self.carry(c), h);
    }
}

/// Steps between two checks of the state in [`FreeBodySplitting::run`].
const CHECK_BLOCK: u64 = 8;

/// The full steps of `h` in `t_span` and the remainder for a last partial step (0 when it is
/// below 10⁻¹² h, so a span that is a multiple of h up to round-off takes no sliver step).
///
/// # Errors
/// [`OdeError::InvalidStep`] naming `t_span` when it is negative or not finite.
pub(super) fn full_steps(t_span: f64, h: f64) -> Result<(u64, f64), OdeError> {
    if !(t_span.is_finite() && t_span >= 0.0) {
        return Err(OdeError::InvalidStep { h: t_span });
    }
    let mut n = (t_span / h).floor();
    // t_span − n h exactly enough by fma; a quotient rounded up gives a negative rest.
    let mut rest = (-n).mul_add(h, t_span);
    if rest < 0.0 {
        n -= 1.0;
        rest = (-n).mul_add(h, t_span);
    }
    if rest > h * (1.0 - 1e-12) {
        n += 1.0;
        rest = (-n).mul_add(h, t_span);
    }
    Ok((n as u64, if rest > 1e-12 * h { rest } else { 0.0 }))
}

pub(super) fn check_step(h: f64) -> Result<(), OdeError> {
    if h.is_finite() && h > 0.0 {
        Ok(())
    } else {
        Err(OdeError::InvalidStep { h })
    }
}
