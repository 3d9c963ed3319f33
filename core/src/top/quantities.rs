//! The standard quantities of a derived top as trajectory columns: energy, |ω|, |L| and the
//! conserved momenta, per sample of a run of its angle form.

use super::dynamics::TopDynamics;
use crate::body::RigidBody;
use crate::ode::Quantities;

/// A generic regular state of either chart, at which [`TopQuantities::new`] asks which
/// momenta the scene conserves (the answer depends on the scene, not on the state).
const PROBE: ([f64; 3], [f64; 3]) = ([0.3, 0.7, 0.2], [0.1, 0.2, 0.3]);

/// The standard quantities of a top in its declared angle chart (state `[q, q̇]`, as
/// [`super::TopChart::declared`] integrates): `energy` (T + V), `omega` (|ω|), `L` (|L| about
/// the pivot, |I ω + h| with the rotors' momentum h), then each conserved momentum `p_<angle>` (`p_phi`, `p_psi` for a
/// symmetric top under gravity in ZXZ).
///
/// Add them to a run with [`Run::quantities`](crate::ode::Run::quantities); name the state
/// columns of its CSV with [`TopQuantities::state_names`].
///
/// # Examples
///
/// The heavy top (I1 = 1, I3 = ½ about the pivot, M g l = 1) released at rest from
/// θ0 = 60° spinning at ω3 = 20 keeps E = ½ I3 ω3² + M g l cos θ0 = 100.5, p_ψ = I3 ω3 = 10
/// and p_φ = p_ψ cos θ0 = 5 along the run:
///
/// ```
/// use approx::assert_relative_eq;
/// use precess::ode::{AdaptiveConfig, Dop853, Run};
/// use precess::prelude::*;
/// use precess::top::TopQuantities;
///
/// #[derive(RigidBody)]
/// #[rigid(
///     body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
///     pivot = [0.0, 0.0, 0.0],
/// )]
/// #[top(gravity = 1.0)]
/// struct Heavy;
///
/// let chart = TopChart::declared(&Heavy);
/// let y0 = [0.0, std::f64::consts::FRAC_PI_3, 0.0, 0.0, 0.0, 20.0];
/// let mut ode = Dop853::new(&chart, 0.0, y0, AdaptiveConfig::with_tol(1e-12, 1e-12))?;
/// let mut out = Run::new(&mut ode, 1.0)
///     .sample_every(0.1)
///     .quantities(TopQuantities::new(&Heavy))
///     .integrate()?;
/// let names = out.trajectory.quantity_names().to_vec();
/// assert_eq!(names, ["energy", "omega", "L", "p_phi", "p_psi"]);
/// for (e, p_phi) in out.trajectory.column("energy").unwrap().iter().zip(out.trajectory.column("p_phi").unwrap()) {
///     assert_relative_eq!(*e, 100.5, max_relative = 1e-11);
///     assert_relative_eq!(p_phi, 5.0, max_relative = 1e-11);
/// }
/// out.trajectory.set_state_names(TopQuantities::<Heavy>::state_names())?;
/// assert!(out.trajectory.to_csv().starts_with("t,phi,theta,psi,phi_dot,theta_dot,psi_dot,energy,"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct TopQuantities<'a, T> {
    top: &'a T,
    /// Which of the angles' momenta the scene conserves.
    conserved: [bool; 3],
}

impl<'a, T> TopQuantities<'a, T> {
    /// The quantities of `top`.
    pub fn new<const N: usize>(top: &'a T) -> Self
    where
        T: TopDynamics<N>,
    {
        let (q, q_dot) = PROBE;
        // A driven top's wheels at a generic rate too.
        let probe: [f64; N] = std::array::from_fn(|k| match k {
            0..=2 => q[k],
            3..=5 => q_dot[k - 3],
            _ => 0.4 + 0.1 * k as f64,
        });
        let conserved = top.conserved_momenta_in(&probe).map(|p| p.is_some());
        Self { top, conserved }
    }
}

impl<T> TopQuantities<'_, T> {
    /// The names of the angle-form state `[q, q̇]` of the declared chart, for
    /// [`Trajectory::set_state_names`](crate::ode::Trajectory::set_state_names): the angles,
    /// then `<angle>_dot`.
    pub fn state_names<const N: usize>() -> [String; N]
    where
        T: TopDynamics<N>,
    {
        let n = T::SEQUENCE.names();
        std::array::from_fn(|k| match k {
            0..=2 => n[k].to_string(),
            3..=5 => format!("{}_dot", n[k - 3]),
            _ => T::DRIVEN_ROTORS
                .get(k - 6)
                .map_or_else(|| format!("slot_{k}"), |r| (*r).to_string()),
        })
    }
}

impl<T: TopDynamics<N> + RigidBody, const N: usize> Quantities<[f64; N]> for TopQuantities<'_, T> {
    fn names(&self) -> Vec<String> {
        let mut names = vec!["energy".to_string(), "omega".to_string(), "L".to_string()];
        for (name, _) in T::SEQUENCE
            .names()
            .iter()
            .zip(self.conserved)
            .filter(|(_, c)| *c)
        {
            names.push(format!("p_{name}"));
        }
        names
    }

    fn evaluate(&mut self, _t: f64, y: &[f64; N], out: &mut [f64]) {
        let slot = |k: usize| y.get(k).copied().unwrap_or(f64::NAN);
        let q = [slot(0), slot(1), slot(2)];
        let omega = self.top.rate_matrix_in(T::SEQUENCE, &q)
            * nalgebra::Vector3::new(slot(3), slot(4), slot(5));
        let momenta = self.top.conserved_momenta_in(y);
        let conserved = momenta
            .iter()
            .zip(self.conserved)
            .filter(|(_, c)| *c)
            // A scene conserves a momentum everywhere or nowhere; NaN would say otherwise.
            .map(|(p, _)| p.unwrap_or(f64::NAN));
        let values = [
            self.top.energy_in(T::SEQUENCE, y),
            omega.norm(),
            (self.top.angular_momentum(&omega) + self.top.rotor_momentum_in(y)).norm(),
        ]
        .into_iter()
        .chain(conserved);
        for (o, v) in out.iter_mut().zip(values) {
            *o = v;
        }
    }
}
