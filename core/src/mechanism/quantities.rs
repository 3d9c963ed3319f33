//! The standard quantities of a derived mechanism as trajectory columns: energy and its two
//! parts, power and every generalised momentum, per sample of a run over `[q, q̇]`, named as a
//! top's are.

use super::dynamics::{MechanismDynamics, split_state};
use crate::ode::Quantities;

/// The standard quantities of a mechanism of `N` coordinates over the state `[q, q̇]` of
/// `S = 2N` numbers (the generated `System` impl's): `energy` (T + V), `kinetic` (T),
/// `potential` (V), `power` (dE/dt of the loads E does not hold), then the generalised
/// momentum `p_<coordinate>` = ∂L/∂q̇ = (M(q) q̇)ᵢ of every coordinate
/// ([`MechanismDynamics::momenta`]), as a top's `TopQuantities` names its momenta. Those of
/// the cyclic coordinates ([`MechanismDynamics::conserved_momenta`]) stay constant along a
/// run; the others are there to be read (an impulse, a phase portrait in (q, p)).
///
/// Add them to a run with [`Run::quantities`](crate::ode::Run::quantities); name the state
/// columns with [`MechanismQuantities::state_names`].
///
/// # Examples
///
/// A pendulum of unit mass on a massless rod of length 2 under g = 9.81, released at rest
/// from θ0 = 0.5: E = −m g l cos θ0 all along, and the power is zero. At t = 0, T = 0,
/// V = E and p_θ = m l² θ̇ = 0.
///
/// ```
/// use approx::assert_relative_eq;
/// use precess::mechanism::MechanismQuantities;
/// use precess::ode::{AdaptiveConfig, Dop853, Run};
/// use precess::prelude::*;
///
/// #[derive(Mechanism)]
/// #[mechanism(gravity = 9.81)]
/// #[body(bob, parent = ground, joint = revolute(axis = x), q = theta,
///        parts(particle(mass = 1.0, at = [0.0, 0.0, -2.0])))]
/// struct Pendulum;
///
/// let mut ode = Dop853::new(&Pendulum, 0.0, [0.5, 0.0], AdaptiveConfig::with_tol(1e-12, 1e-12))?;
/// let out = Run::new(&mut ode, 2.0)
///     .sample_every(0.5)
///     .quantities(MechanismQuantities::new(&Pendulum))
///     .integrate()?;
/// let names = ["energy", "kinetic", "potential", "power", "p_theta"];
/// assert_eq!(out.trajectory.quantity_names(), names);
/// for e in out.trajectory.column("energy").unwrap() {
///     assert_relative_eq!(e, -9.81 * 2.0 * 0.5f64.cos(), max_relative = 1e-10);
/// }
/// let q0 = out.trajectory.quantities(0).unwrap();
/// assert_eq!((q0[1], q0[4]), (0.0, 0.0));
/// assert_relative_eq!(q0[2], -9.81 * 2.0 * 0.5f64.cos(), max_relative = 1e-14);
/// assert_eq!(MechanismQuantities::<Pendulum, 1>::state_names(), ["theta", "theta_dot"]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// A unit mass a unit length down a hinge about x, on a massless turntable about the vertical:
/// gravity does not read φ, so p_φ = m l² sin²θ φ̇ is conserved, sin²(0.5) · 2 from θ0 = 0.5
/// and φ̇0 = 2, while p_θ = m l² θ̇ is not.
///
/// ```
/// use approx::assert_relative_eq;
/// use precess::mechanism::MechanismQuantities;
/// use precess::ode::{AdaptiveConfig, Dop853, Run};
/// use precess::prelude::*;
///
/// #[derive(Mechanism)]
/// #[mechanism(gravity = 9.81)]
/// #[body(table, parent = ground, joint = revolute(axis = z), q = phi,
///        parts(particle(mass = 0.0, at = [0.0, 0.0, 0.0])))]
/// #[body(bob, parent = table, joint = revolute(axis = x), q = theta,
///        parts(particle(mass = 1.0, at = [0.0, 0.0, -1.0])))]
/// struct Conical;
///
/// let y0 = [0.0, 0.5, 2.0, 0.0];
/// let mut ode = Dop853::new(&Conical, 0.0, y0, AdaptiveConfig::with_tol(1e-12, 1e-12))?;
/// let out = Run::new(&mut ode, 3.0)
///     .sample_every(0.5)
///     .quantities(MechanismQuantities::new(&Conical))
///     .integrate()?;
/// let names = ["energy", "kinetic", "potential", "power", "p_phi", "p_theta"];
/// assert_eq!(out.trajectory.quantity_names(), names);
/// for p in out.trajectory.column("p_phi").unwrap() {
///     assert_relative_eq!(p, 0.5f64.sin().powi(2) * 2.0, max_relative = 1e-10);
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct MechanismQuantities<'a, D, const N: usize> {
    mechanism: &'a D,
}

impl<'a, D: MechanismDynamics<N>, const N: usize> MechanismQuantities<'a, D, N> {
    /// The quantities of `mechanism`.
    pub fn new(mechanism: &'a D) -> Self {
        Self { mechanism }
    }

    /// The names of the state `[q, q̇]`, for
    /// [`Trajectory::set_state_names`](crate::ode::Trajectory::set_state_names): the
    /// coordinates, then `<coordinate>_dot`.
    pub fn state_names() -> Vec<String> {
        let names = D::COORDINATES;
        let rates = names.iter().map(|n| format!("{n}_dot"));
        names.iter().map(|n| n.to_string()).chain(rates).collect()
    }
}

impl<D: MechanismDynamics<N>, const N: usize, const S: usize> Quantities<[f64; S]>
    for MechanismQuantities<'_, D, N>
{
    fn names(&self) -> Vec<String> {
        let momenta = D::COORDINATES.iter().map(|name| format!("p_{name}"));
        ["energy", "kinetic", "potential", "power"]
            .map(String::from)
            .into_iter()
            .chain(momenta)
            .collect()
    }

    fn evaluate(&mut self, t: f64, y: &[f64; S], out: &mut [f64]) {
        // A state of the wrong length is no state of this mechanism: NaN, not a panic.
        let Some((q, qdot)) = split_state::<N, S>(y) else {
            out.fill(f64::NAN);
            return;
        };
        let (kinetic, potential) = (
            self.mechanism.kinetic(&q, &qdot),
            self.mechanism.potential(&q),
        );
        let values = [
            kinetic + potential,
            kinetic,
            potential,
            self.mechanism.power(t, &q, &qdot),
        ]
        .into_iter()
        .chain(self.mechanism.momenta(&q, &qdot));
        for (o, v) in out.iter_mut().zip(values) {
            *o = v;
        }
    }
}
