//! A slider-crank under gravity: a crank, a connecting rod and a slider on a straight
//! guide, a closed loop declared on `#[derive(Mechanism)]` with `closes = ..` whose other
//! side is a prismatic joint (`docs/mechanisms.md`, "Closed loops"). Its position analysis
//! is the slider's x(θ) = r cos θ + √(l² − r² sin² θ) ([`SliderCrank::positions`]).

use crate::mechanism::MechanismError;
use crate::mechanism::loops::LoopDynamics;
use crate::prelude::Mechanism;

/// The crank r \[m\]: the ground pivot at the origin to the crank pin.
pub const CRANK: f64 = 0.5;
/// The connecting rod l \[m\]: the crank pin to the slider's pin.
pub const ROD: f64 = 1.5;
/// The masses \[kg\] (crank, rod, slider): the crank and the rod uniform thin rods, the
/// slider a particle at its pin.
pub const MASSES: [f64; 3] = [0.4, 0.9, 2.0];
/// Gravity g \[m/s²\], along −y.
pub const GRAVITY: f64 = 9.81;

/// An in-line slider-crank in the xy plane, gravity along −y: a crank r = 0.5 m turning
/// about the origin, a connecting rod l = 1.5 m, and a slider whose pin runs on the x axis
/// (the constants of this module); uniform rods of 0.4 and 0.9 kg, a slider of 2 kg. With
/// l > r the crank turns fully.
///
/// The coordinates are θ (the crank, from +x), β (the rod, relative to the crank) and x
/// (the slider along its guide, a prismatic joint on the ground). The tree is the crank →
/// rod chain and the slider, cut at the rod–slider pin, which `closes = slider(..)` puts
/// back with two rows (ground axes, `CLOSURE_ROWS` = `rod.x`, `rod.y`):
///
/// φ(q) = (r cos θ + l cos(θ + β) − x, r sin θ + l sin(θ + β)) = 0.
///
/// The second row gives sin(θ + β) = −(r/l) sin θ, and with the slider on the +x side of
/// the crank (cos(θ + β) > 0) the first the slider's position
///
/// x(θ) = r cos θ + √(l² − r² sin² θ),
///
/// which [`SliderCrank::positions`] evaluates. The equations of motion are
/// M q̈ = f + Aᵀ λ with A = ∂φ/∂q and λ the pin force on the rod (ground axes; the slider
/// feels −λ, its guide holds it in y): see [`LoopDynamics`], which the derive implements.
///
/// # Examples
///
/// A few steps (a fifth of a second) from the closed form's positions with the crank at
/// 5 rad/s: the loop stays closed, the slider on x(θ), the energy conserved.
///
/// ```
/// use approx::assert_relative_eq;
/// use precess::mechanism::loops::LoopDynamics;
/// use precess::models::SliderCrank;
/// use precess::ode::{AdaptiveConfig, Stepper};
///
/// let y0 = SliderCrank.start(0.4, 5.0)?;
/// let (q0, qd0) = ([y0[0], y0[1], y0[2]], [y0[3], y0[4], y0[5]]);
/// assert!(SliderCrank.residual(&q0) < 1e-15);
/// let mut run = SliderCrank.closed_run(0.0, y0, AdaptiveConfig::with_tol(1e-11, 1e-11))?;
/// run.advance_to(0.2)?;
/// let y = run.state().x;
/// let (q, qd) = ([y[0], y[1], y[2]], [y[3], y[4], y[5]]);
/// assert!(SliderCrank.residual(&q) < 1e-13);
/// // x = r cos θ + √(l² − r² sin² θ), r = 0.5, l = 1.5.
/// let x = 0.5 * q[0].cos() + (1.5_f64.powi(2) - (0.5 * q[0].sin()).powi(2)).sqrt();
/// assert!((q[SliderCrank::X] - x).abs() < 1e-13);
/// assert_relative_eq!(SliderCrank.energy(&q, &qd), SliderCrank.energy(&q0, &qd0), max_relative = 1e-9);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Mechanism)]
#[mechanism(gravity = [0.0, -9.81, 0.0])]
#[body(crank, joint = revolute(axis = z), q = theta,
       parts(rod(mass = 0.4, length = 0.5, axis = x, at = [0.25, 0.0, 0.0])))]
#[body(rod, parent = crank, joint = revolute(axis = z, at = [0.5, 0.0, 0.0]), q = beta,
       parts(rod(mass = 0.9, length = 1.5, axis = x, at = [0.75, 0.0, 0.0])),
       closes = slider(at = [1.5, 0.0, 0.0]))]
#[body(slider, joint = prismatic(axis = x), q = x, parts(particle(mass = 2.0)))]
pub struct SliderCrank;

impl SliderCrank {
    /// The coordinates [θ, β, x] on the loop with the crank at θ, the slider on the +x side:
    /// β = asin(−(r/l) sin θ) − θ and x = r cos θ + √(l² − r² sin² θ). From the constants of
    /// this module, not from what the derive read, so that comparing the two checks the
    /// derive. (θ + β lies in [−π/2, π/2], so β winds with θ.)
    pub fn positions(theta: f64) -> [f64; 3] {
        let (r, l) = (CRANK, ROD);
        let s = theta.sin();
        let beta = (-(r / l) * s).asin() - theta;
        [
            theta,
            beta,
            r * theta.cos() + (l * l - r * r * s * s).sqrt(),
        ]
    }

    /// A state [q, q̇] on the loop: the crank at θ turning at `omega` \[rad/s\], the rod and
    /// the slider from [`SliderCrank::positions`], their rates from A q̇ = 0.
    ///
    /// # Errors
    /// [`MechanismError::NonFinite`] for a θ or ω not finite.
    pub fn start(
        &self,
        theta: f64,
        omega: f64,
    ) -> Result<[f64; SliderCrank::STATE], MechanismError> {
        let q = Self::positions(theta);
        let qd = self.rates_from(&q, [SliderCrank::THETA], [omega])?;
        Ok([q[0], q[1], q[2], qd[0], qd[1], qd[2]])
    }
}
