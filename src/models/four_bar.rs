//! A crank-rocker four-bar linkage under gravity: a closed loop declared on
//! `#[derive(Mechanism)]` with `closes = ..` (`docs/mechanisms.md`, "Closed loops"), whose
//! position analysis is Freudenstein's equation ([`FourBar::positions`]).

use crate::mechanism::MechanismError;
use crate::mechanism::loops::LoopDynamics;
use crate::prelude::Mechanism;

/// The crank a \[m\]: the ground pivot A = (0, 0) to the crank pin.
pub const CRANK: f64 = 1.0;
/// The coupler b \[m\]: the crank pin to the rocker pin B.
pub const COUPLER: f64 = 3.0;
/// The rocker c \[m\]: the ground pivot D = (d, 0) to the rocker pin B.
pub const ROCKER: f64 = 2.5;
/// The ground d \[m\]: the distance between the pivots A and D.
pub const GROUND: f64 = 3.0;
/// The links' masses \[kg\] (crank, coupler, rocker): uniform thin rods.
pub const MASSES: [f64; 3] = [0.5, 1.5, 1.2];
/// Gravity g \[m/s²\], along −y.
pub const GRAVITY: f64 = 9.81;

/// Which of the two assemblies of the loop at a crank angle: the turn from the crank pin to
/// the rocker's pivot D to the rocker pin B. A Grashof crank-rocker stays on its circuit
/// through every crank turn (it has no change point).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Circuit {
    /// B clockwise from the crank pin and D (below the line from the crank pin to D while
    /// the crank points up): the circuit of the example `four_bar` and the tests.
    Clockwise,
    /// B counterclockwise from the crank pin and D.
    Counterclockwise,
}

/// A crank-rocker four-bar in the xy plane, gravity along −y: crank a = 1, coupler b = 3,
/// rocker c = 2.5, ground d = 3 m (the constants of this module), uniform rods of 0.5, 1.5
/// and 1.2 kg. Grashof's s + l < p + q holds (1 + 3 < 3 + 2.5) with the shortest link the
/// crank beside the ground, so the crank turns fully and the rocker swings.
///
/// The coordinates are θ₁ (the crank, from +x), θ₂ (the coupler, relative to the crank) and
/// θ₃ (the rocker about D = (d, 0), from +x). The tree is crank → coupler and rocker, cut
/// at the coupler–rocker pin, which `closes = rocker(..)` puts back with two rows (ground
/// axes, `CLOSURE_ROWS` = `coupler.x`, `coupler.y`):
///
/// φ(q) = a (cos θ₁, sin θ₁) + b (cos(θ₁ + θ₂), sin(θ₁ + θ₂)) − (d + c cos θ₃, c sin θ₃) = 0.
///
/// Eliminating the coupler gives Freudenstein's equation for the rocker,
///
/// K₁ cos θ₃ − K₂ cos θ₁ + K₃ = cos(θ₁ − θ₃), K₁ = d/a, K₂ = d/c,
/// K₃ = (a² − b² + c² + d²)/(2ac),
///
/// solved in closed form by [`FourBar::positions`]. The equations of motion are
/// M q̈ = f + Aᵀ λ with A = ∂φ/∂q, λ the pin force on the coupler (ground axes): see
/// [`LoopDynamics`], which the derive implements.
///
/// # Examples
///
/// A few steps (a fifth of a second, a quarter of a crank turn) from Freudenstein's
/// positions with the crank at 6 rad/s: the run loop keeps the loop closed and the energy is
/// conserved.
///
/// ```
/// use approx::assert_relative_eq;
/// use precess::mechanism::loops::LoopDynamics;
/// use precess::models::FourBar;
/// use precess::models::four_bar::Circuit;
/// use precess::ode::{AdaptiveConfig, Stepper};
///
/// let y0 = FourBar.start(0.3, 6.0, Circuit::Clockwise)?;
/// let (q0, qd0) = ([y0[0], y0[1], y0[2]], [y0[3], y0[4], y0[5]]);
/// assert!(FourBar.residual(&q0) < 1e-15);
/// let mut run = FourBar.closed_run(0.0, y0, AdaptiveConfig::with_tol(1e-11, 1e-11))?;
/// run.advance_to(0.2)?;
/// let y = run.state().x;
/// let (q, qd) = ([y[0], y[1], y[2]], [y[3], y[4], y[5]]);
/// assert!(FourBar.residual(&q) < 1e-13);
/// assert_relative_eq!(FourBar.energy(&q, &qd), FourBar.energy(&q0, &qd0), max_relative = 1e-9);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Mechanism)]
#[mechanism(gravity = [0.0, -9.81, 0.0])]
#[body(crank, joint = revolute(axis = z), q = theta1,
       parts(rod(mass = 0.5, length = 1.0, axis = x, at = [0.5, 0.0, 0.0])))]
#[body(coupler, parent = crank, joint = revolute(axis = z, at = [1.0, 0.0, 0.0]), q = theta2,
       parts(rod(mass = 1.5, length = 3.0, axis = x, at = [1.5, 0.0, 0.0])),
       closes = rocker(at = [3.0, 0.0, 0.0], to = [2.5, 0.0, 0.0]))]
#[body(rocker, joint = revolute(axis = z, at = [3.0, 0.0, 0.0]), q = theta3,
       parts(rod(mass = 1.2, length = 2.5, axis = x, at = [1.25, 0.0, 0.0])))]
pub struct FourBar;

impl FourBar {
    /// The coordinates [θ₁, θ₂, θ₃] on the loop with the crank at θ₁, on `circuit`:
    /// Freudenstein's equation written A cos θ₃ + B sin θ₃ = C (A = K₁ − cos θ₁,
    /// B = −sin θ₁, C = K₂ cos θ₁ − K₃) and solved by the half-angle substitution
    /// t = tan(θ₃/2), then the coupler's absolute angle from the closing triangle. From the
    /// constants of this module, not from what the derive read, so that comparing the two
    /// checks the derive. (θ₃ in (−π, π], θ₂ = that angle − θ₁.)
    pub fn positions(theta1: f64, circuit: Circuit) -> [f64; 3] {
        let (a, b, c, d) = (CRANK, COUPLER, ROCKER, GROUND);
        let (k1, k2, k3) = (
            d / a,
            d / c,
            (a * a - b * b + c * c + d * d) / (2.0 * a * c),
        );
        let (ca, cb, cc) = (k1 - theta1.cos(), -theta1.sin(), k2 * theta1.cos() - k3);
        // The two roots of (C + A) t² − 2B t + (C − A) = 0; the discriminant
        // A² + B² − C² stays positive on a crank-rocker.
        let branch = match circuit {
            Circuit::Clockwise => 1.0,
            Circuit::Counterclockwise => -1.0,
        };
        let t = (-cb + branch * (ca * ca + cb * cb - cc * cc).sqrt()) / (-cc - ca);
        let theta3 = 2.0 * t.atan();
        let bx = d + c * theta3.cos() - a * theta1.cos();
        let by = c * theta3.sin() - a * theta1.sin();
        [theta1, by.atan2(bx) - theta1, theta3]
    }

    /// A state [q, q̇] on the loop: the crank at θ₁ turning at `omega` \[rad/s\], the other
    /// coordinates from [`FourBar::positions`], their rates from A q̇ = 0.
    ///
    /// # Errors
    /// [`MechanismError::NonFinite`] for a θ₁ or ω not finite.
    pub fn start(
        &self,
        theta1: f64,
        omega: f64,
        circuit: Circuit,
    ) -> Result<[f64; FourBar::STATE], MechanismError> {
        let q = Self::positions(theta1, circuit);
        let qd = self.rates_from(&q, [FourBar::THETA1], [omega])?;
        Ok([q[0], q[1], q[2], qd[0], qd[1], qd[2]])
    }
}
