//! The trait `#[derive(Mechanism)]` implements: the derived equations of a mechanism of `N`
//! coordinates as straight-line code, with its energy, power and conserved momenta.

use super::MechanismError;

/// The equations of motion of a mechanism with `N` coordinates, `M(q) q̈ = f(t, q, q̇)`,
/// solved for `q̈` and specialised to one mechanism by `#[derive(Mechanism)]`.
///
/// Coordinates and rates are arrays in the order of [`MechanismDynamics::COORDINATES`]. The
/// derive also implements `precess::ode::System<{2N}>` on the struct itself, over the state
/// `[q, q̇]` (the struct is local to the user's crate, so that impl is allowed where a
/// blanket one over `2N` could not be written), and gives each coordinate's index as an
/// associated const named in capitals (`Self::THETA1`).
///
/// ```
/// use approx::assert_relative_eq;
/// use precess::prelude::*;
///
/// /// A point mass on a massless rod of length l: a simple pendulum.
/// #[derive(Mechanism)]
/// #[mechanism(gravity = 9.81)]
/// #[body(bob, parent = ground, joint = revolute(axis = x), q = theta,
///        parts(particle(mass = 1.0, at = [0.0, 0.0, -l])))]
/// struct Pendulum { l: f64 }
///
/// let p = Pendulum { l: 2.0 };
/// let theta_ddot = p.accelerations(0.0, &[0.3], &[0.0])?[Pendulum::THETA];
/// // θ̈ = −(g/l) sin θ.
/// assert_relative_eq!(theta_ddot, -9.81 / 2.0 * 0.3f64.sin(), max_relative = 1e-14);
/// assert_eq!(Pendulum::coordinate("theta"), Some(0));
/// # Ok::<(), precess::mechanism::MechanismError>(())
/// ```
pub trait MechanismDynamics<const N: usize> {
    /// The coordinate names, in state order.
    const COORDINATES: [&'static str; N];

    /// The route the accelerations were solved by (`"symbolic"`, `"factored"`,
    /// `"recursive"`).
    const ROUTE: &'static str;

    /// The index of the coordinate called `name`, if there is one.
    fn coordinate(name: &str) -> Option<usize>
    where
        Self: Sized,
    {
        Self::COORDINATES.iter().position(|&c| c == name)
    }

    /// `q̈(t, q, q̇)`, checked: the inputs and the result are finite and the mass matrix
    /// is regular.
    ///
    /// # Errors
    /// [`MechanismError::NonFinite`] for a NaN or infinite time, coordinate or rate (or a
    /// result that overflows); [`MechanismError::SingularMassMatrix`] when a pivot of the
    /// mass matrix is not positive (a massless link, say).
    fn accelerations(
        &self,
        t: f64,
        q: &[f64; N],
        qdot: &[f64; N],
    ) -> Result<[f64; N], MechanismError>;

    /// `q̈(t, q, q̇)` without any check: the fast path for integrators (NaN where the
    /// checked form would return an error).
    fn accelerations_unchecked(&self, t: f64, q: &[f64; N], qdot: &[f64; N]) -> [f64; N];

    /// The kinetic energy T(q, q̇).
    fn kinetic(&self, q: &[f64; N], qdot: &[f64; N]) -> f64;

    /// The potential energy V(q): −Σ m g·r of the bodies' centres r in ground coordinates
    /// (zero on the ground frame's origin) and ½ k (q − rest)² of each spring.
    fn potential(&self, q: &[f64; N]) -> f64;

    /// The energy E = T + V.
    fn energy(&self, q: &[f64; N], qdot: &[f64; N]) -> f64 {
        self.kinetic(q, qdot) + self.potential(q)
    }

    /// dE/dt: the power of the loads E does not hold (dampers, efforts, torques); zero when
    /// the mechanism is conservative.
    fn power(&self, t: f64, q: &[f64; N], qdot: &[f64; N]) -> f64;

    /// The momentum ∂L/∂q̇ᵢ of each cyclic coordinate (absent from L and from every load, so
    /// conserved), `None` for the others.
    fn cyclic_momenta(&self, q: &[f64; N], qdot: &[f64; N]) -> [Option<f64>; N];
}

/// Splits an ODE state `[q, q̇]` of `S = 2N` numbers into `q` and `q̇` (what the generated
/// `System` impl does); `None` if `S ≠ 2N`.
///
/// ```
/// use precess::mechanism::split_state;
/// let (q, qdot) = split_state::<2, 4>(&[1.0, 2.0, 3.0, 4.0]).unwrap();
/// assert_eq!((q, qdot), ([1.0, 2.0], [3.0, 4.0]));
/// ```
pub fn split_state<const N: usize, const S: usize>(y: &[f64; S]) -> Option<([f64; N], [f64; N])> {
    if S != 2 * N {
        return None;
    }
    let q: [f64; N] = y.get(..N)?.try_into().ok()?;
    let qdot: [f64; N] = y.get(N..)?.try_into().ok()?;
    Some((q, qdot))
}
