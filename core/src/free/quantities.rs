//! The standard quantities of a derived free body as trajectory columns: energy, power and
//! the sizes of its momenta, per sample of a run over the state of [`super::layout`], named
//! as a top's and a mechanism's are.

use super::dynamics::FreeDynamics;
use super::state::STATE_LEN;
use crate::ode::Quantities;

/// The names of the state's slots, in the order of [`super::layout`]: what
/// [`FreeQuantities::state_names`] heads the CSV with and [`FreeDynamics::coordinate`] looks
/// up (the derive's consts `X` … `OMEGA_3` are the same slots in capitals).
pub const STATE_NAMES: [&str; STATE_LEN] = [
    "x", "y", "z", "vx", "vy", "vz", "qw", "qx", "qy", "qz", "omega_1", "omega_2", "omega_3",
];

/// The standard quantities of a free body over its state (the array of [`super::layout`]):
/// `energy` (½ M |v|² + ½ Σ Iᵢ ωᵢ² − M g·x), `power` (dE/dt of every force but gravity),
/// `p` (|M v|) and `L` (|x × M v + R I ω|, about the space origin), then that angular
/// momentum's space components `L_x`, `L_y`, `L_z`.
///
/// Add them to a run with [`Run::quantities`](crate::ode::Run::quantities); name the state
/// columns of its CSV with [`FreeQuantities::state_names`], as a top's and a mechanism's.
///
/// # Examples
///
/// A 2 kg brick thrown under gravity alone: its energy stays ½ M |v0|² + ½ ω0ᵀ I ω0, and
/// |p| = M |v| = 2 √(1 + (5 − g t)²) along the parabola.
///
/// ```
/// use approx::assert_relative_eq;
/// use precess::free::{FreeDynamics, FreeQuantities, FreeState, FreeSystem};
/// use precess::ode::{AdaptiveConfig, Dop853, Run};
/// use precess::prelude::*;
///
/// #[derive(RigidBody)]
/// #[rigid(cuboid(mass = 2.0, size = [0.1, 0.2, 0.3]))]
/// #[free(gravity = 9.81)]
/// struct Brick;
///
/// let s = FreeState {
///     velocity: Vector3::new(1.0, 0.0, 5.0),
///     omega_principal: Vector3::new(1.0, 2.0, 3.0),
///     ..FreeState::at_rest()
/// };
/// let i = Brick.principal_cm().moments;
/// let e0 = 0.5 * 2.0 * 26.0 + 0.5 * (i[0] + 4.0 * i[1] + 9.0 * i[2]);
/// let tight = AdaptiveConfig::with_tol(1e-12, 1e-12);
/// let mut ode = Dop853::new(FreeSystem(&Brick), 0.0, s.to_array(), tight)?;
/// let out = Run::new(&mut ode, 1.0)
///     .sample_every(0.1)
///     .quantities(FreeQuantities::new(&Brick))
///     .integrate()?;
/// assert_eq!(out.trajectory.quantity_names(), ["energy", "power", "p", "L", "L_x", "L_y", "L_z"]);
/// for e in out.trajectory.column("energy").unwrap() {
///     assert_relative_eq!(e, e0, max_relative = 1e-10);
/// }
/// let p = out.trajectory.column("p").unwrap();
/// for (t, p) in out.trajectory.times().iter().zip(p) {
///     assert_relative_eq!(p, 2.0 * (1.0 + (5.0 - 9.81 * t).powi(2)).sqrt(), max_relative = 1e-10);
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct FreeQuantities<'a, F> {
    body: &'a F,
}

impl<'a, F> FreeQuantities<'a, F> {
    /// The quantities of `body`.
    pub fn new(body: &'a F) -> Self {
        Self { body }
    }
}

impl<F> FreeQuantities<'_, F> {
    /// The names of the whole state of a body with `N` slots: the 13 of
    /// [`FreeQuantities::state_names`], then `rotor_k` for each driven rotor (the slot
    /// `Self::ROTOR_k` indexes, holding its relative rate Ωₖ).
    pub fn all_state_names<const N: usize>() -> Vec<String>
    where
        F: FreeDynamics<N>,
    {
        STATE_NAMES
            .iter()
            .chain(F::DRIVEN_ROTORS)
            .map(|&s| s.to_owned())
            .collect()
    }
}

impl<F: FreeDynamics> FreeQuantities<'_, F> {
    /// The names of the state of [`super::layout`], for
    /// [`Trajectory::set_state_names`](crate::ode::Trajectory::set_state_names): the centre
    /// `x, y, z`, its velocity `vx, vy, vz`, the quaternion `qw, qx, qy, qz` (principal to
    /// space) and ω in principal axes `omega_1, omega_2, omega_3`.
    ///
    /// ```
    /// use precess::free::{FreeQuantities, layout};
    /// use precess::prelude::*;
    ///
    /// #[derive(RigidBody)]
    /// #[rigid(sphere(mass = 1.0, radius = 0.1))]
    /// #[free(gravity = 9.81)]
    /// struct Ball;
    ///
    /// let names = FreeQuantities::<Ball>::state_names();
    /// assert_eq!(names[layout::QUATERNION], "qw");
    /// assert_eq!(names[layout::OMEGA + 2], "omega_3");
    /// ```
    pub fn state_names() -> [String; STATE_LEN] {
        STATE_NAMES.map(String::from)
    }
}

impl<const N: usize, F: FreeDynamics<N>> Quantities<[f64; N]> for FreeQuantities<'_, F> {
    fn names(&self) -> Vec<String> {
        ["energy", "power", "p", "L", "L_x", "L_y", "L_z"]
            .map(String::from)
            .to_vec()
    }

    fn evaluate(&mut self, t: f64, y: &[f64; N], out: &mut [f64]) {
        let l = self.body.angular_momentum_origin(y);
        let values = [
            self.body.energy(y),
            self.body.power(t, y),
            self.body.linear_momentum(y).norm(),
            l.norm(),
            l.x,
            l.y,
            l.z,
        ];
        for (o, v) in out.iter_mut().zip(values) {
            *o = v;
        }
    }
}
