//! The standard quantities of a derived mechanism as trajectory columns: energy, power and the
//! conserved momenta, per sample of a run over `[q, q̇]`, named as a top's are.

use super::dynamics::{MechanismDynamics, split_state};
use crate::ode::Quantities;

/// A generic state at which [`MechanismQuantities::new`] asks which momenta the mechanism
/// conserves (the answer depends on the mechanism, not on the state).
fn probe<const N: usize>() -> ([f64; N], [f64; N]) {
    let q = std::array::from_fn(|i| 0.3 + 0.1 * i as f64);
    let qdot = std::array::from_fn(|i| 0.1 + 0.05 * i as f64);
    (q, qdot)
}

/// The standard quantities of a mechanism of `N` coordinates over the state `[q, q̇]` of
/// `S = 2N` numbers (the generated `System` impl's): `energy` (T + V), `power` (dE/dt of the
/// loads E does not hold), then each conserved momentum `p_<coordinate>`, as
/// a top's `TopQuantities` names them.
///
/// Add them to a run with [`Run::quantities`](crate::ode::Run::quantities); name the state
/// columns with [`MechanismQuantities::state_names`].
///
/// # Examples
///
/// A pendulum of unit mass on a massless rod of length 2 under g = 9.81, released at rest
/// from θ0 = 0.5: E = −m g l cos θ0 all along, and the power is zero.
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
/// assert_eq!(out.trajectory.quantity_names(), ["energy", "power"]);
/// for e in out.trajectory.column("energy").unwrap() {
///     assert_relative_eq!(e, -9.81 * 2.0 * 0.5f64.cos(), max_relative = 1e-10);
/// }
/// assert_eq!(MechanismQuantities::<Pendulum, 1>::state_names(), ["theta", "theta_dot"]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// A unit mass a unit length down a hinge about x, on a massless turntable about the vertical:
/// gravity does not read φ, so p_φ = m l² sin²θ φ̇ is conserved, sin²(0.5) · 2 from θ0 = 0.5
/// and φ̇0 = 2.
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
/// assert_eq!(out.trajectory.quantity_names(), ["energy", "power", "p_phi"]);
/// for p in out.trajectory.column("p_phi").unwrap() {
///     assert_relative_eq!(p, 0.5f64.sin().powi(2) * 2.0, max_relative = 1e-10);
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct MechanismQuantities<'a, D, const N: usize> {
    mechanism: &'a D,
    /// Which coordinates' momenta the mechanism conserves.
    conserved: [bool; N],
}

impl<'a, D: MechanismDynamics<N>, const N: usize> MechanismQuantities<'a, D, N> {
    /// The quantities of `mechanism`.
    pub fn new(mechanism: &'a D) -> Self {
        let (q, qdot) = probe::<N>();
        let conserved = mechanism.conserved_momenta(&q, &qdot).map(|p| p.is_some());
        Self {
            mechanism,
            conserved,
        }
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
        let mut names = vec!["energy".to_string(), "power".to_string()];
        for (name, _) in D::COORDINATES
            .iter()
            .zip(self.conserved)
            .filter(|(_, c)| *c)
        {
            names.push(format!("p_{name}"));
        }
        names
    }

    fn evaluate(&mut self, t: f64, y: &[f64; S], out: &mut [f64]) {
        // A state of the wrong length is no state of this mechanism: NaN, not a panic.
        let Some((q, qdot)) = split_state::<N, S>(y) else {
            out.fill(f64::NAN);
            return;
        };
        let momenta = self.mechanism.conserved_momenta(&q, &qdot);
        let conserved = momenta
            .iter()
            .zip(self.conserved)
            .filter(|(_, c)| *c)
            // A mechanism conserves a momentum everywhere or nowhere; NaN would say otherwise.
            .map(|(p, _)| p.unwrap_or(f64::NAN));
        let values = [
            self.mechanism.energy(&q, &qdot),
            self.mechanism.power(t, &q, &qdot),
        ]
        .into_iter()
        .chain(conserved);
        for (o, v) in out.iter_mut().zip(values) {
            *o = v;
        }
    }
}
