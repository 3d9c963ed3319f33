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
use crate::ode::{OdeError, check_inertia};
use crate::rigid::kinematics::rotate_body;
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

/// Turns the body by `theta` about body axis `axis`: q ← q ⊗ exp(θ eₐ/2), m ← Rᵀ m.
/// m gets its own correctly rounded sin_cos θ: deriving it from θ/2 (c² − s², 2sc)
/// costs |m| a visibly larger random walk.
#[inline]
fn axis_rotation(y: &mut BodyMomentum, axis: usize, theta: f64) {
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
    let q = y.q.quaternion() * Quaternion::new(ch, e[0], e[1], e[2]);
    y.q = UnitQuaternion::new_normalize(q);
    let (a, b) = ((axis + 1) % 3, (axis + 2) % 3);
    let (ma, mb) = (y.m[a], y.m[b]);
    // One rounding fewer per component than c·a + s·b: less random walk in |m|.
    y.m[a] = c.mul_add(ma, s * mb);
    y.m[b] = c.mul_add(mb, -(s * ma));
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
        })
    }

    /// Principal moments.
    pub fn inertia(&self) -> Vector3<f64> {
        self.inertia.into()
    }

    /// The exact flow of ½ m₁²(1/I₁ − 1/I₂) for time τ: a rotation about body axis 1.
    #[inline]
    fn r1(&self, y: &mut BodyMomentum, tau: f64) {
        axis_rotation(y, 0, tau * self.a1 * y.m.x);
    }

    /// The exact flow of ½ m₃²(1/I₃ − 1/I₂) for time τ: a rotation about body axis 3.
    #[inline]
    fn r3(&self, y: &mut BodyMomentum, tau: f64) {
        axis_rotation(y, 2, tau * self.a3 * y.m.z);
    }

    /// The exact flow of the Casimir part ½|m|²/I₂: m fixed, the body turns about m.
    #[inline]
    fn casimir(&self, y: &mut BodyMomentum, tau: f64) {
        y.q = rotate_body(&y.q, &(y.m * (tau / self.inertia[1])));
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
        let (w, k) = self.weights();
        for &g in &w[..k] {
            self.r1(y, 0.5 * g * h);
            self.r3(y, g * h);
            self.r1(y, 0.5 * g * h);
        }
        self.casimir(y, h);
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
        let mut done = 0;
        while done < n {
            // Checked after each block of a few steps (a non-finite component stays
            // non-finite), then replayed to stop at the first bad step.
            let len = CHECK_BLOCK.min(n - done);
            let (y_start, pending_start) = (*y, pending);
            for _ in 0..len {
                self.merged_step(y, &mut pending, weights, h);
            }
            if !momentum_is_finite(y) {
                (*y, pending) = (y_start, pending_start);
                for i in done..done + len {
                    let (y_prev, pending_prev) = (*y, pending);
                    self.merged_step(y, &mut pending, weights, h);
                    if !momentum_is_finite(y) {
                        // The last finite state, with its pending half rotation applied.
                        *y = y_prev;
                        self.r1(y, pending_prev);
                        return Err(OdeError::NonFiniteState { t: i as f64 * h });
                    }
                }
            }
            done += len;
        }
        self.r1(y, pending);
        Ok(())
    }

    /// One step of [`Self::run`], leaving its last R₁ half-rotation pending to merge with the
    /// next step's first.
    #[inline]
    fn merged_step(&self, y: &mut BodyMomentum, pending: &mut f64, weights: &[f64], h: f64) {
        for &g in weights {
            self.r1(y, *pending + 0.5 * g * h);
            self.r3(y, g * h);
            *pending = 0.5 * g * h;
        }
        self.casimir(y, h);
    }
}

/// Steps between two checks of the state in [`FreeBodySplitting::run`].
const CHECK_BLOCK: u64 = 8;

pub(super) fn check_step(h: f64) -> Result<(), OdeError> {
    if h.is_finite() && h > 0.0 {
        Ok(())
    } else {
        Err(OdeError::InvalidStep { h })
    }
}
