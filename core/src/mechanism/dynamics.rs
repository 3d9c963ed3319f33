//! The trait `#[derive(Mechanism)]` implements: the derived equations of a mechanism of `N`
//! coordinates as straight-line code, with its energy, power and conserved momenta.

use nalgebra::SMatrix;

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
    /// result that overflows); those of [`MechanismDynamics::check_parameters`] for the
    /// struct's field values; [`MechanismError::SingularMassMatrix`] when a pivot of the
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

    /// The generalised momenta p = ∂L/∂q̇ = M(q) q̇, one per coordinate, in the order of
    /// [`MechanismDynamics::COORDINATES`] (the conserved ones among them are those
    /// [`MechanismDynamics::conserved_momenta`] names).
    ///
    /// T is a quadratic form in q̇ (no load or constraint reads t into it) and V does not read
    /// q̇, so the central difference pᵢ = (T(q, q̇ + h eᵢ) − T(q, q̇ − h eᵢ)) / 2h is exact for
    /// every h: no truncation error, only rounding. h is the largest |q̇ⱼ| (1 at rest), which
    /// keeps that rounding at a few ulps of M |q̇|. 2N evaluations of T.
    ///
    /// ```
    /// use approx::assert_relative_eq;
    /// use precess::prelude::*;
    ///
    /// /// A unit mass two units down a hinge: p = m l² θ̇.
    /// #[derive(Mechanism)]
    /// #[mechanism(gravity = 9.81)]
    /// #[body(bob, parent = ground, joint = revolute(axis = x), q = theta,
    ///        parts(particle(mass = 1.0, at = [0.0, 0.0, -2.0])))]
    /// struct Pendulum;
    ///
    /// assert_relative_eq!(Pendulum.momenta(&[0.3], &[1.5])[0], 4.0 * 1.5, max_relative = 1e-15);
    /// ```
    fn momenta(&self, q: &[f64; N], qdot: &[f64; N]) -> [f64; N] {
        let largest = qdot.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let h = if largest > 0.0 && largest.is_finite() {
            largest
        } else {
            1.0
        };
        std::array::from_fn(|i| {
            let (mut up, mut down) = (*qdot, *qdot);
            up[i] += h;
            down[i] -= h;
            (self.kinetic(q, &up) - self.kinetic(q, &down)) / (2.0 * h)
        })
    }

    /// The momentum ∂L/∂q̇ᵢ of each cyclic coordinate (absent from L and from every load, so
    /// conserved), `None` for the others.
    fn conserved_momenta(&self, q: &[f64; N], qdot: &[f64; N]) -> [Option<f64>; N];

    /// Checks the values the struct's fields give the mechanism, with the rules literals meet
    /// at compile time: every value finite; each part's mass not negative (zero is a massless
    /// link), its dimensions positive and its explicit inertia physical; every axis of
    /// non-zero length; springs and dampers not negative. [`MechanismDynamics::accelerations`]
    /// and the Jacobians call it first; a mechanism of literals has nothing to check.
    ///
    /// # Errors
    /// [`MechanismError::NonFiniteParameter`], [`MechanismError::Part`],
    /// [`MechanismError::ZeroAxis`] or [`MechanismError::NegativeParameter`], naming the body
    /// or joint, the quantity and its value.
    fn check_parameters(&self) -> Result<(), MechanismError> {
        Ok(())
    }

    /// The Jacobian of q̈ with respect to the state: `(∂q̈/∂q, ∂q̈/∂q̇)`, each `[row][column]`
    /// (row i is q̈ᵢ). The derive gives the exact derivatives of its symbolic and factored
    /// routes (with user-function efforts τ, `effort = f`: q̈'s with τ held, plus
    /// (∂q̈/∂τ)(∂τ/∂(q, q̇)), ∂q̈/∂τ exact and only ∂τ differenced, by [`effort_jacobian`]);
    /// this default (taken by the recursive route, which has no closed form to
    /// differentiate at compile time) uses central differences of
    /// [`MechanismDynamics::accelerations_unchecked`] with Richardson extrapolation
    /// ([`crate::linalg::jacobian`]): 12N evaluations of q̈ (6 per component of the state),
    /// accurate to about 1e-12 relative to the scale of q̈ and its derivatives for a
    /// well-conditioned M, worse by the conditioning near a singular one (on the four-link
    /// chain example it agrees with differences of an independent Newton–Euler q̈ to 1e-10).
    ///
    /// # Errors
    /// Those of [`MechanismDynamics::accelerations`] at the state, and
    /// [`MechanismError::NonFinite`] if a difference quotient is not finite.
    #[allow(clippy::type_complexity)]
    fn acceleration_jacobian(
        &self,
        t: f64,
        q: &[f64; N],
        qdot: &[f64; N],
    ) -> Result<([[f64; N]; N], [[f64; N]; N]), MechanismError> {
        self.accelerations(t, q, qdot)?;
        let state: Vec<f64> = q.iter().chain(qdot.iter()).copied().collect();
        let jac = crate::linalg::jacobian(
            |y, out| {
                let (mut q, mut qdot) = ([0.0; N], [0.0; N]);
                q.copy_from_slice(&y[..N]);
                qdot.copy_from_slice(&y[N..]);
                let a = self.accelerations_unchecked(t, &q, &qdot);
                out[..N].copy_from_slice(&qdot);
                out[N..].copy_from_slice(&a);
            },
            &state,
        )
        .map_err(|_| MechanismError::NonFinite {
            quantity: "difference quotients of the accelerations",
            values: state.clone(),
        })?;
        let by_q = std::array::from_fn(|i| std::array::from_fn(|j| jac[(N + i, j)]));
        let by_qdot = std::array::from_fn(|i| std::array::from_fn(|j| jac[(N + i, N + j)]));
        Ok((by_q, by_qdot))
    }

    /// The Jacobian ∂(q̇, q̈)/∂(q, q̇) of the first-order system over `[q, q̇]`, 2N × 2N:
    /// `[[0, I], [∂q̈/∂q, ∂q̈/∂q̇]]`, for linearisation (its eigenvalues about an
    /// equilibrium are ±i ω of the normal modes) and implicit steppers.
    ///
    /// # Errors
    /// Those of [`MechanismDynamics::acceleration_jacobian`].
    ///
    /// # Examples
    ///
    /// A pendulum of length l hanging at rest: the linearised system has eigenvalues ±i √(g/l).
    ///
    /// ```
    /// use approx::assert_relative_eq;
    /// use precess::prelude::*;
    ///
    /// #[derive(Mechanism)]
    /// #[mechanism(gravity = 9.81)]
    /// #[body(bob, parent = ground, joint = revolute(axis = x), q = theta,
    ///        parts(particle(mass = 1.0, at = [0.0, 0.0, -2.0])))]
    /// struct Pendulum;
    ///
    /// let j = Pendulum.jacobian(0.0, &[0.0], &[0.0])?;
    /// // [[0, 1], [−g/l, 0]]
    /// assert_eq!((j[(0, 0)], j[(0, 1)], j[(1, 1)]), (0.0, 1.0, 0.0));
    /// assert_relative_eq!(j[(1, 0)], -9.81 / 2.0, max_relative = 1e-14);
    /// # Ok::<(), precess::mechanism::MechanismError>(())
    /// ```
    fn jacobian(
        &self,
        t: f64,
        q: &[f64; N],
        qdot: &[f64; N],
    ) -> Result<nalgebra::DMatrix<f64>, MechanismError> {
        let (by_q, by_qdot) = self.acceleration_jacobian(t, q, qdot)?;
        let mut jac = nalgebra::DMatrix::zeros(2 * N, 2 * N);
        for i in 0..N {
            jac[(i, N + i)] = 1.0;
            for j in 0..N {
                jac[(N + i, j)] = by_q[i][j];
                jac[(N + i, N + j)] = by_qdot[i][j];
            }
        }
        Ok(jac)
    }
}

/// (∂τ/∂q, ∂τ/∂q̇), P × n each, of P user-function efforts τ(q, q̇) at (q, q̇) (the
/// time held), by central differences with Richardson extrapolation
/// ([`crate::linalg::jacobian_of`], 12n evaluations of τ, about 1e-12 relative). The one
/// differenced piece of a derived mechanism's Jacobian with `effort = f`: its
/// `acceleration_jacobian` (tree) and `partials` (rolling) differentiate everything else
/// exactly, the efforts held at their values, and add the chain rule's term
/// (∂(·)/∂τ) (∂τ/∂(q, q̇)), ∂(·)/∂τ exact too (the generalised force of a unit effort).
///
/// # Errors
/// [`MechanismError::NonFinite`] if the state or a value of τ near it is not finite.
///
/// ```
/// use approx::assert_relative_eq;
/// use precess_core::mechanism::effort_jacobian;
///
/// // τ = q₀ q̇₁².
/// let tau = |q: &[f64; 2], qdot: &[f64; 2]| [q[0] * qdot[1] * qdot[1]];
/// let (by_q, by_qdot) = effort_jacobian(tau, &[3.0, 1.0], &[0.0, 2.0])?;
/// assert_relative_eq!(by_q[(0, 0)], 4.0, max_relative = 1e-12);
/// assert_relative_eq!(by_qdot[(0, 1)], 12.0, max_relative = 1e-12);
/// assert_eq!((by_q[(0, 1)], by_qdot[(0, 0)]), (0.0, 0.0));
/// # Ok::<(), precess_core::mechanism::MechanismError>(())
/// ```
#[allow(clippy::type_complexity)]
pub fn effort_jacobian<const N: usize, const P: usize>(
    efforts: impl Fn(&[f64; N], &[f64; N]) -> [f64; P],
    q: &[f64; N],
    qdot: &[f64; N],
) -> Result<(SMatrix<f64, P, N>, SMatrix<f64, P, N>), MechanismError> {
    let state: Vec<f64> = q.iter().chain(qdot.iter()).copied().collect();
    let jac = crate::linalg::jacobian_of(
        |y, out| {
            let (mut q, mut qdot) = ([0.0; N], [0.0; N]);
            q.copy_from_slice(&y[..N]);
            qdot.copy_from_slice(&y[N..]);
            out.copy_from_slice(&efforts(&q, &qdot));
        },
        &state,
        P,
    )
    .map_err(|_| MechanismError::NonFinite {
        quantity: "difference quotients of the user efforts",
        values: state.clone(),
    })?;
    Ok((
        SMatrix::from_fn(|i, j| jac[(i, j)]),
        SMatrix::from_fn(|i, j| jac[(i, N + j)]),
    ))
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
