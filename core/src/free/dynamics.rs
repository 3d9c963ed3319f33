//! The trait `#[free(...)]` implements: a derived free body's right-hand side, wrench,
//! energy, power and momenta as straight-line code, with the checked helpers built on them.

use nalgebra::Vector3;

use super::error::FreeError;
use super::state::{FreeState, STATE_LEN};
use super::theory::FreeExact;
use crate::body::{Principal, RigidBody};
use crate::rigid::first_non_finite_motor;

/// The total force and torque acting on a free body at one state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wrench {
    /// The sum of the forces, space axes.
    pub force_space: Vector3<f64>,
    /// The sum of the torques about the centre of mass, principal axes.
    pub torque_principal: Vector3<f64>,
}

/// A free body, its equations derived at compile time by `#[free(...)]`.
///
/// The state is the array of [`super::layout`]: the centre of mass and its velocity in space
/// axes, the attitude quaternion (principal → space) and ω in principal axes; a body with
/// driven rotors appends their relative rates, so its state holds `N` = 13 + their number
/// (named in [`FreeDynamics::DRIVEN_ROTORS`]). The generated
/// methods are straight-line code without checks, for the steppers' inner loops; they read
/// the quaternion at any non-zero size (the attitude is formed from q/|q|). Build states with
/// [`FreeState::to_array`], check parameters with [`FreeDynamics::check_parameters`].
///
/// # Examples
///
/// A 2 kg box thrown upward under gravity: the generated right-hand side gives v̇ = g and,
/// since gravity makes no torque about the centre of mass, the free Euler equations.
///
/// ```
/// use approx::assert_relative_eq;
/// use precess::free::{FreeDynamics, FreeState};
/// use precess::prelude::*;
///
/// #[derive(RigidBody)]
/// #[rigid(cuboid(mass = 2.0, size = [0.1, 0.2, 0.3]))]
/// #[free(gravity = 9.81)]
/// struct Brick;
///
/// let s = FreeState {
///     velocity: Vector3::new(0.0, 0.0, 5.0),
///     omega_principal: Vector3::new(1.0, 2.0, 3.0),
///     ..FreeState::at_rest()
/// };
/// let mut d = [0.0; 13];
/// Brick.free_rhs(0.0, &s.to_array(), &mut d);
/// assert_relative_eq!(d[5], -9.81);
/// let i = Brick.principal_cm().moments;
/// assert_relative_eq!(d[10], (i[1] - i[2]) / i[0] * 2.0 * 3.0, max_relative = 1e-15);
/// // Energy is conserved: the weight is the only force and it has a potential.
/// assert_relative_eq!(Brick.power(0.0, &s.to_array()), 0.0);
/// ```
pub trait FreeDynamics<const N: usize = STATE_LEN>: RigidBody {
    /// The first declared force or torque other than uniform gravity, by its name, or `None`
    /// when gravity is all that acts (the exact flow then applies).
    const BEYOND_GRAVITY: Option<&'static str>;

    /// The names of the state slots after the 13 of [`super::layout`]: one per driven rotor,
    /// `rotor_k` for the rotor declared k-th (counting from 0), holding its relative rate Ωₖ
    /// (rad/s). The derive gives each slot a const in capitals (`Self::ROTOR_0`).
    const DRIVEN_ROTORS: &'static [&'static str] = &[];

    /// The paths of the driven rotors' motor functions as `rotor(torque = path)` writes
    /// them, in the order of [`FreeDynamics::DRIVEN_ROTORS`]. Empty without motors.
    const MOTORS: &'static [&'static str] = &[];

    /// Writes motor k's torque uₖ = `motor(self, t, y)` into `out[k]`, in the order of
    /// [`FreeDynamics::MOTORS`] (motors past `out`'s length are not called). Generated for a
    /// body with driven rotors; unchecked, as [`FreeDynamics::free_rhs`], which reads it.
    fn motor_torques(&self, t: f64, y: &[f64; N], out: &mut [f64]) {
        let _ = (t, y, out);
    }

    /// Calls every motor at `(t, y)` and checks its torque: what a run reports when f is not
    /// finite ([`super::FreeSystem`]'s
    /// [`System::explain_non_finite`](crate::ode::System::explain_non_finite)).
    ///
    /// # Errors
    /// [`FreeError::NonFiniteMotor`] naming the first motor that returned NaN or ±∞.
    fn check_motors(&self, t: f64, y: &[f64; N]) -> Result<(), FreeError> {
        let mut u = vec![0.0; Self::MOTORS.len()];
        self.motor_torques(t, y, &mut u);
        match first_non_finite_motor(Self::DRIVEN_ROTORS, Self::MOTORS, &u) {
            Some((rotor, motor, value)) => Err(FreeError::NonFiniteMotor {
                rotor,
                motor,
                t,
                value,
            }),
            None => Ok(()),
        }
    }

    /// The slot of the state component called `name` in the array of [`super::layout`], if
    /// there is one, by the names of [`FreeQuantities::state_names`](super::FreeQuantities::state_names)
    /// (`x`, `vx`, `qw`, `omega_2`, …). The derive gives the same slots as consts named in
    /// capitals (`Self::VX`, `Self::OMEGA_2`), as a mechanism's coordinates.
    ///
    /// ```
    /// use precess::free::{FreeDynamics, layout};
    /// use precess::prelude::*;
    ///
    /// #[derive(RigidBody)]
    /// #[rigid(sphere(mass = 1.0, radius = 0.1))]
    /// #[free(gravity = 9.81)]
    /// struct Ball;
    ///
    /// assert_eq!(Ball::coordinate("vz"), Some(layout::VELOCITY + 2));
    /// assert_eq!(Ball::OMEGA_1, layout::OMEGA);
    /// assert_eq!(Ball::coordinate("theta"), None);
    /// ```
    fn coordinate(name: &str) -> Option<usize>
    where
        Self: Sized,
    {
        super::STATE_NAMES
            .iter()
            .chain(Self::DRIVEN_ROTORS)
            .position(|&c| c == name)
    }

    /// Principal moments about the centre of mass and the rotation from principal to
    /// description axes (the frame of the state's attitude and ω).
    fn principal_cm(&self) -> Principal;

    /// Uniform gravity g, space axes (zero when undeclared).
    fn gravity(&self) -> Vector3<f64>;

    /// Writes ẏ at time `t` and state `y` into `dydt`.
    fn free_rhs(&self, t: f64, y: &[f64; N], dydt: &mut [f64; N]);

    /// The total force and the torque about the centre of mass.
    fn wrench(&self, t: f64, y: &[f64; N]) -> Wrench;

    /// The total force and torque, checked: the state is finite with a non-zero
    /// quaternion and the wrench (a user function's value included) is finite.
    ///
    /// # Errors
    /// [`FreeError::StateLength`] for a state shorter than 13; as [`FreeState::from_array`]
    /// for the state; [`FreeError::NonFiniteWrench`] naming the total force (space axes) or
    /// torque (principal axes) that holds NaN or ±∞.
    fn try_wrench(&self, t: f64, y: &[f64; N]) -> Result<Wrench, FreeError> {
        let head = y.first_chunk::<STATE_LEN>().ok_or(FreeError::StateLength {
            len: N,
            expected: STATE_LEN + Self::DRIVEN_ROTORS.len(),
        })?;
        FreeState::from_array(head)?;
        let w = self.wrench(t, y);
        let parts = [
            ("total force, space axes", w.force_space),
            (
                "total torque about the centre of mass, principal axes",
                w.torque_principal,
            ),
        ];
        for (part, v) in parts {
            if v.iter().any(|c| !c.is_finite()) {
                return Err(FreeError::NonFiniteWrench {
                    part,
                    values: [v.x, v.y, v.z],
                });
            }
        }
        Ok(w)
    }

    /// The energy ½ M |v|² + ½ Σ Iᵢ ωᵢ² − M g·x, with driven rotors plus their wheels' own
    /// Σ Jₖ Ωₖ âₖ·ω + ½ Σ Jₖ Ωₖ² (the true total).
    fn energy(&self, y: &[f64; N]) -> f64;

    /// The power of every force but gravity, F'·v + τ·ω (+ Σ uₖ Ωₖ, the driven rotors'
    /// motors): dE/dt along the motion.
    fn power(&self, t: f64, y: &[f64; N]) -> f64;

    /// The linear momentum M v, space axes.
    fn linear_momentum(&self, y: &[f64; N]) -> Vector3<f64>;

    /// The angular momentum about the space origin, x × M v + R (I ω + h), space axes (h the
    /// rotors' relative momentum).
    fn angular_momentum_origin(&self, y: &[f64; N]) -> Vector3<f64>;

    /// Checks the struct's fields that the body and its forces read, and the body's rules
    /// for their values.
    ///
    /// # Errors
    /// [`FreeError::NonFiniteParameter`] naming a NaN or infinite field, [`FreeError::Body`]
    /// for a rule of the description broken.
    fn check_parameters(&self) -> Result<(), FreeError>;

    /// The exact motion from `state` at time `t0`: the parabola of the centre of mass and
    /// the torque-free attitude, answering the whole body at any time in O(1).
    ///
    /// # Errors
    /// [`FreeError::NotExact`] when a force other than uniform gravity is declared; as
    /// [`FreeDynamics::check_parameters`] and [`FreeExact::new`].
    fn exact(&self, t0: f64, state: &FreeState) -> Result<FreeExact, FreeError> {
        if let Some(declared) = Self::BEYOND_GRAVITY {
            return Err(FreeError::NotExact { declared });
        }
        self.check_parameters()?;
        FreeExact::new(&self.principal_cm().moments, &self.gravity(), t0, state)
    }
}
