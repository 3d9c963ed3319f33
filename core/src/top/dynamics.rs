//! The trait `#[top(...)]` implements: a derived top's equations in both angle charts and in
//! Eulerian form, with the helpers built on them.

use nalgebra::{Matrix3, UnitQuaternion, Vector3};

use super::checks::{TopParameters, checked_accelerations, checked_motors};
use super::error::TopError;
use super::theory::{HeavyTopTheory, derived_theory};
use crate::body::RigidBody;
use crate::codegen::Typeset;
use crate::rigid::AngleSequence;
use crate::rigid::rates_from_omega;

/// A top about a fixed pivot, its equations derived at compile time by `#[top(...)]`.
///
/// Angle-form methods take the angles `q` and rates `q̇` of [`TopDynamics::SEQUENCE`]; the `_in`
/// methods take either sequence (both are generated, so a simulation can switch charts at
/// gimbal lock, see [`super::ChartedTop`]). The Eulerian form takes the attitude and the
/// body angular velocity, in the description axes of the body.
///
/// The generated methods are straight-line code without checks, for the steppers' inner
/// loops: at a chart's gimbal lock (sin θ = 0 for ZXZ, cos pitch = 0 for ZYX) q̈ comes out
/// NaN or infinite. The checked methods ([`TopDynamics::accelerations`], [`TopDynamics::accelerations_in`])
/// and [`TopDynamics::rates_from_omega`] check the state and the chart first, under the one
/// rule of [`crate::rigid::check_chart`]; the checked methods and
/// [`super::ChartedTop::new`] check the whole top first, through [`TopDynamics::check_all`].
///
/// Every top is a [`RigidBody`] (the same derive implements both), so its body is checked
/// with its settings.
///
/// # Driven rotors
///
/// `N` is the length of the state: 6, `[q, q̇]`, for every top but one whose rotors are
/// turned by motors (`rotor(axis = [..], inertia = J, torque = path)`), whose state is
/// `[q, q̇, Ω₀, …, Ωₖ₋₁]`, `N = 6 + k`, with each driven wheel's rate relative to the body
/// (rad/s) in the slot `Self::ROTOR_j` (j counting every rotor as declared, the name
/// `"rotor_j"` of [`TopDynamics::coordinate`] and [`TopDynamics::DRIVEN_ROTORS`]). The
/// methods over the whole state (`_in`, [`TopDynamics::rhs_in`]) take it whole. `T:
/// TopDynamics` is `TopDynamics<6>`, so the helpers written for tops without motors
/// ([`super::EulerianTop`], [`super::FastTop`], the linearisations, the variational
/// equations) take no driven top: the compiler refuses it. The methods over `(q, q̇)`
/// alone cannot see the wheels' rates: on a driven top [`TopDynamics::accelerations`]
/// returns [`TopError::DrivenState`], [`TopDynamics::accelerations_unchecked`],
/// [`TopDynamics::energy`] and the generated [`TopDynamics::angle_jacobian`] and
/// [`TopDynamics::eulerian_rhs`] NaN and [`TopDynamics::conserved_momenta`] `None`
/// ([`TopDynamics::conserved_momenta_in`] reads the whole state).
///
/// # Examples
///
/// The symmetric heavy top with I1 = 1, I3 = ½ about the pivot and M g l = 1 precesses
/// steadily at θ = 60° with ω3 = 10 at Ω = 0.204168476687 rad/s (the slow root of
/// I1 cos θ Ω² − I3 ω3 Ω + M g l = 0), so θ̈ vanishes there; straight up, the ZXZ chart is
/// singular and the checked helper says so:
///
/// ```
/// use precess::prelude::*;
/// use precess::top::TopError;
///
/// #[derive(RigidBody)]
/// #[rigid(
///     body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
///     pivot = [0.0, 0.0, 0.0],
/// )]
/// #[top(gravity = 1.0)]
/// struct Heavy;
///
/// let (theta, omega_p, w3) = (std::f64::consts::FRAC_PI_3, 0.204168476687, 10.0);
/// // ω3 = ψ̇ + φ̇ cos θ.
/// let q_dot = [omega_p, 0.0, w3 - omega_p * theta.cos()];
/// let q_ddot = Heavy.accelerations(0.0, &[0.0, theta, 0.0], &q_dot).unwrap();
/// assert!(q_ddot[1].abs() < 1e-10);
///
/// let vertical = Heavy.accelerations(0.0, &[0.0, 0.0, 0.0], &[0.0, 0.0, 5.0]);
/// assert!(matches!(vertical, Err(TopError::Chart(ChartError::SingularChart { .. }))));
/// ```
pub trait TopDynamics<const N: usize = 6>: RigidBody {
    /// The declared angle sequence.
    const SEQUENCE: AngleSequence;

    /// The first declared torque other than gravity, by its `#[top(...)]` name (`damping`,
    /// `body_torque`, `space_torque`, `torque`), or `None` when gravity is all that acts
    /// (the heavy-top closed forms of [`TopDynamics::theory`] then apply).
    const BEYOND_GRAVITY: Option<&'static str> = None;

    /// How many internal rotors `#[top(rotor(...))]` declares (a gyrostat when > 0),
    /// driven ones included.
    const ROTORS: usize = 0;

    /// The names of the driven rotors' rates in the state, in the order of their slots
    /// 6, 7, …: `"rotor_j"`, j the rotor's place among every rotor declared. Empty (and
    /// `N = 6`) without motors.
    const DRIVEN_ROTORS: &'static [&'static str] = &[];

    /// The paths of the driven rotors' motor functions as `rotor(torque = path)` writes
    /// them, in the order of [`TopDynamics::DRIVEN_ROTORS`]. Empty without motors.
    const MOTORS: &'static [&'static str] = &[];

    /// Writes motor k's torque uₖ = `motor(self, t, state)` into `out[k]`, in the order of
    /// [`TopDynamics::MOTORS`] (motors past `out`'s length are not called). Generated for a
    /// driven top; unchecked (the checked [`TopDynamics::accelerations_in`] and the runs
    /// check the values).
    fn motor_torques(&self, t: f64, state: &[f64; N], out: &mut [f64]) {
        let _ = (t, state, out);
    }

    /// The constant-rate rotors' total relative angular momentum h = Σ J Ω â in body
    /// (description) axes, for the current field values; zero without rotors. The top's
    /// angular momentum about the pivot is I ω + h (a driven wheel's part, Jₖ Ωₖ âₖ, reads
    /// its rate from the state and is not included).
    fn rotor_momentum(&self) -> Vector3<f64> {
        Vector3::zeros()
    }

    /// Every rotor's relative angular momentum at the state `state` (body axes): h of
    /// [`TopDynamics::rotor_momentum`] plus each driven wheel's Jₖ Ωₖ âₖ, Ωₖ read from its
    /// slot. The top's angular momentum about the pivot is I ω + this.
    fn rotor_momentum_in(&self, state: &[f64; N]) -> Vector3<f64> {
        let _ = state;
        self.rotor_momentum()
    }

    /// The index of the angle called `name` in q and q̇ of [`TopDynamics::SEQUENCE`] (`"phi"`,
    /// `"theta"`, `"psi"` in ZXZ; `"yaw"`, `"pitch"`, `"roll"` in ZYX), if there is one: in
    /// the state `[q, q̇]` the angle is slot i and its rate slot 3 + i. The derive gives the
    /// same indices as consts named in capitals (`Self::THETA`), as a mechanism's. A driven
    /// rotor's rate `"rotor_j"` gives its slot in the whole state (6 and on), as
    /// `Self::ROTOR_j` does.
    ///
    /// ```
    /// use precess::prelude::*;
    ///
    /// #[derive(RigidBody)]
    /// #[rigid(body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
    ///         pivot = [0.0, 0.0, 0.0])]
    /// #[top(gravity = 9.81)]
    /// struct Heavy;
    ///
    /// assert_eq!(Heavy::coordinate("theta"), Some(Heavy::THETA));
    /// assert_eq!((Heavy::PHI, Heavy::THETA, Heavy::PSI), (0, 1, 2));
    /// assert_eq!(Heavy::coordinate("roll"), None);
    /// ```
    fn coordinate(name: &str) -> Option<usize>
    where
        Self: Sized,
    {
        Self::SEQUENCE
            .names()
            .iter()
            .position(|&c| c == name)
            .or_else(|| {
                Self::DRIVEN_ROTORS
                    .iter()
                    .position(|&c| c == name)
                    .map(|j| 6 + j)
            })
    }

    /// q̈ in the chart `seq` at time `t` and state `[q, q̇]` (`[q, q̇, Ω]` for a driven top).
    fn accelerations_unchecked_in(&self, seq: AngleSequence, t: f64, state: &[f64; N]) -> [f64; 3];

    /// The whole state's rate in the chart `seq`: `(q̇, q̈)`, and for a driven top the
    /// wheels' Ω̇ₖ = uₖ/Jₖ − âₖ·ω̇ (generated; this default, for `N = 6`, leaves any slot past
    /// the sixth at zero). Unchecked, as [`TopDynamics::accelerations_unchecked_in`].
    fn rhs_in(&self, seq: AngleSequence, t: f64, state: &[f64; N], rate: &mut [f64; N]) {
        let a = self.accelerations_unchecked_in(seq, t, state);
        for (k, r) in rate.iter_mut().enumerate() {
            *r = match k {
                0..=2 => state.get(k + 3).copied().unwrap_or(f64::NAN),
                3..=5 => a[k - 3],
                _ => 0.0,
            };
        }
    }

    /// R(q) in the chart `seq`, body to space.
    fn rotation_in(&self, seq: AngleSequence, q: &[f64; 3]) -> Matrix3<f64>;

    /// B(q) in the chart `seq`: ω = B q̇.
    fn rate_matrix_in(&self, seq: AngleSequence, q: &[f64; 3]) -> Matrix3<f64>;

    /// The energy T + V in the chart `seq` (for a driven top the wheels' relative spin
    /// counts: T = ½ ωᵀ I ω + Σ J Ω â·ω + ½ Σ J Ω²).
    fn energy_in(&self, seq: AngleSequence, state: &[f64; N]) -> f64;

    /// The Jacobian of q̈ with respect to `(q, q̇)` in [`TopDynamics::SEQUENCE`]: row i holds
    /// `∂q̈_i/∂(q_0, q_1, q_2, q̇_0, q̇_1, q̇_2)`.
    fn angle_jacobian(&self, t: f64, q: &[f64; 3], q_dot: &[f64; 3]) -> [[f64; 6]; 3];

    /// The momenta `∂L/∂q̇_i` of [`TopDynamics::SEQUENCE`] that are conserved for this scene
    /// (`None` for the others).
    fn conserved_momenta(&self, q: &[f64; 3], q_dot: &[f64; 3]) -> [Option<f64>; 3];

    /// [`TopDynamics::conserved_momenta`] over the whole state of the declared chart: for a
    /// driven top the momenta read the wheels' rates (about the vertical, ẑ·R (I ω + h),
    /// conserved whatever the motors do, their torques being internal).
    fn conserved_momenta_in(&self, state: &[f64; N]) -> [Option<f64>; 3] {
        let [a, b, c, d, e, f] = std::array::from_fn(|k| state.get(k).copied().unwrap_or(f64::NAN));
        self.conserved_momenta(&[a, b, c], &[d, e, f])
    }

    /// The Eulerian form: ω̇ = I⁻¹(τ − ω × (I ω + h)), with the same torques and rotors, for the attitude
    /// (body to space) and body angular velocity ω.
    fn eulerian_rhs(
        &self,
        t: f64,
        attitude: &UnitQuaternion<f64>,
        omega: &Vector3<f64>,
    ) -> Vector3<f64>;

    /// The values of the declared torque settings (gravity, damping, constant torques), read
    /// from the fields where `#[top(...)]` names fields.
    fn top_parameters(&self) -> TopParameters;

    /// Checks the declared settings alone under the rules literals are held to at compile
    /// time ([`TopParameters::check`]): gravity and damping finite and ≥ 0, torques finite.
    /// Part of [`TopDynamics::check_all`], which the checked entry points call; the generated
    /// equations do not.
    ///
    /// # Errors
    /// As [`TopParameters::check`].
    fn check_parameters(&self) -> Result<(), TopError> {
        self.top_parameters().check()
    }

    /// Checks everything the top's field values decide, under the rules literals meet at
    /// compile time: the body (every rule of [`RigidBody::validate`]: masses and sizes > 0,
    /// inertias positive definite and within the triangle inequality, rotations that are
    /// rotations) and the settings ([`TopDynamics::check_parameters`]: gravity, damping,
    /// torques). The one checked entry: the checked accelerations, [`super::ChartedTop::new`] over
    /// [`super::TopChart`]s and [`TopDynamics::validate_top`] all call it.
    ///
    /// [`RigidBody::validate`] alone checks the body only (a negative gravity passes it).
    ///
    /// # Errors
    /// [`TopError::Body`] for the body's first broken rule, then as
    /// [`TopDynamics::check_parameters`].
    fn check_all(&self) -> Result<(), TopError> {
        self.validate()?;
        self.check_parameters()
    }

    /// The same as [`TopDynamics::check_all`] (the name of the body's check with `_top`).
    ///
    /// # Errors
    /// As [`TopDynamics::check_all`].
    fn validate_top(&self) -> Result<(), TopError> {
        self.check_all()
    }

    /// `self`, if it passes [`TopDynamics::check_all`]: a checked constructor for tops
    /// with field values, `Spinner { g: 9.81 }.validated_top()?`.
    ///
    /// # Errors
    /// As [`TopDynamics::check_all`].
    fn validated_top(self) -> Result<Self, TopError>
    where
        Self: Sized,
    {
        self.check_all()?;
        Ok(self)
    }

    /// The symmetric heavy top's closed forms for this top ([`HeavyTopTheory`]: steady
    /// precession, the sleeping top's threshold, the nutation bounds and period of a
    /// motion, its precession), with I1 = I2, I3 about the pivot and M g l = M g l_z read
    /// from the top's own mass, centre of mass and gravity (l_z the height of the centre
    /// above the pivot along the description z axis; negative below it).
    ///
    /// The closed forms are in the ZXZ angles of the description z axis, the angles of the
    /// top's ZXZ chart.
    ///
    /// # Examples
    ///
    /// A cylinder of 0.3 kg, radius 1 cm and length 20 cm standing on its end: I3 = ½ m r²,
    /// I1 = m (3 r² + h²)/12 + m (h/2)² and M g l = m g h/2, so it sleeps above
    /// ω3 = √(4 M g l I1)/I3:
    ///
    /// ```
    /// use approx::assert_relative_eq;
    /// use precess::prelude::*;
    ///
    /// #[derive(RigidBody)]
    /// #[rigid(
    ///     cylinder(mass = 0.3, radius = 0.01, length = 0.2, axis = z, at = [0.0, 0.0, 0.1]),
    ///     pivot = [0.0, 0.0, 0.0],
    /// )]
    /// #[top(gravity = 9.81)]
    /// struct Rod;
    ///
    /// let (m, r, h, g) = (0.3, 0.01, 0.2, 9.81);
    /// let (i1, i3, mgl) = (m * (3.0 * r * r + h * h) / 12.0 + m * h * h / 4.0, 0.5 * m * r * r, m * g * h / 2.0);
    /// let theory = Rod.theory()?;
    /// assert_relative_eq!(theory.mgl(), mgl, max_relative = 1e-15);
    /// assert_relative_eq!(theory.sleeping_threshold(), (4.0 * mgl * i1).sqrt() / i3, max_relative = 1e-14);
    /// # Ok::<(), precess::top::TopError>(())
    /// ```
    ///
    /// # Errors
    /// As [`TopDynamics::check_all`] first; then, in [`TopError::Theory`]:
    /// [`TheoryError::OtherTorque`](super::TheoryError::OtherTorque) when damping or another torque is declared
    /// ([`TopDynamics::BEYOND_GRAVITY`]); [`TheoryError::ProductsOfInertia`](super::TheoryError::ProductsOfInertia) when the z
    /// axis is not principal about the pivot; [`TheoryError::NotSymmetric`](super::TheoryError::NotSymmetric) when
    /// Ixx ≠ Iyy about the pivot; [`TheoryError::CentreOffAxis`](super::TheoryError::CentreOffAxis) when the centre of mass
    /// lies off the z axis through the pivot (each beyond
    /// [`super::SYMMETRY_TOLERANCE`] relative); [`TheoryError::NoGravity`](super::TheoryError::NoGravity) when gravity is
    /// undeclared or zero, or the centre of mass is at the pivot;
    /// [`TheoryError::Rotor`](super::TheoryError::Rotor) when the top carries rotors
    /// ([`TopDynamics::ROTORS`]).
    fn theory(&self) -> Result<HeavyTopTheory, TopError> {
        derived_theory(self)
    }

    /// The scene's equations as a paper prints them (L, the equations of motion, q̈, the
    /// conserved momenta, one LaTeX string each) and the operation counts of the generated
    /// methods, computed when the derive expanded: `'static` data, nothing computed at run
    /// time. [`super::TopScene::typeset`] gives equal strings for a scene built at run time.
    /// `docs/equations.md` describes the form.
    ///
    /// # Examples
    ///
    /// The heavy symmetric top: p_ψ = I₃ (ψ̇ + φ̇ cos θ) = I₃ ω₃ is conserved, and q̈ costs
    /// 34 operations (one of them a paired `sin_cos`).
    ///
    /// ```
    /// use precess::prelude::*;
    ///
    /// #[allow(non_snake_case)]
    /// #[derive(RigidBody)]
    /// #[rigid(
    ///     body(mass = M, at = [0.0, 0.0, l], inertia = diag(I_1, I_1, I_3), about = pivot),
    ///     pivot = [0.0, 0.0, 0.0],
    /// )]
    /// #[top(gravity = g)]
    /// struct HeavyTop { I_1: f64, I_3: f64, M: f64, g: f64, l: f64 }
    ///
    /// let eq = HeavyTop { I_1: 1.0, I_3: 0.5, M: 1.0, g: 9.81, l: 0.1 }.equations();
    /// assert_eq!(
    ///     eq.conserved[1],
    ///     r"p_{\psi} = I_{3} \left(\dot{\psi} + \dot{\phi} \cos\theta\right)"
    /// );
    /// let accel = eq.cost("accelerations").unwrap();
    /// assert_eq!((accel.total(), accel.sin_cos), (34, 1));
    /// ```
    fn equations(&self) -> &'static Typeset;

    /// q̈ in [`TopDynamics::SEQUENCE`], unchecked: NaN or infinite at the chart's gimbal lock (see
    /// [`TopDynamics::accelerations`]).
    ///
    /// NaN for a driven top, whose q̈ reads the wheels' rates too: use
    /// [`TopDynamics::accelerations_unchecked_in`] with the whole state.
    fn accelerations_unchecked(&self, t: f64, q: &[f64; 3], q_dot: &[f64; 3]) -> [f64; 3] {
        match state_of(q, q_dot) {
            Some(state) => self.accelerations_unchecked_in(Self::SEQUENCE, t, &state),
            None => [f64::NAN; 3],
        }
    }

    /// q̈ in [`TopDynamics::SEQUENCE`], refusing a state the chart cannot take.
    ///
    /// # Errors
    /// [`TopError::DrivenState`] for a driven top (its q̈ reads the wheels' rates: use
    /// [`TopDynamics::accelerations_in`] with the whole state); then as
    /// [`TopDynamics::accelerations_in`].
    fn accelerations(&self, t: f64, q: &[f64; 3], q_dot: &[f64; 3]) -> Result<[f64; 3], TopError> {
        let state = state_of(q, q_dot).ok_or(TopError::DrivenState {
            method: "accelerations",
            rotors: Self::DRIVEN_ROTORS.len(),
        })?;
        self.accelerations_in(Self::SEQUENCE, t, &state)
    }

    /// q̈ in the chart `seq`, refusing a state the chart cannot take.
    ///
    /// # Errors
    /// The errors of [`TopDynamics::check_all`] (a body that breaks a rule of its
    /// description, [`TopError::Body`]; a negative gravity or damping, a NaN setting);
    /// [`TopError::NonFinite`] for non-finite angles or rates; [`TopError::Chart`] ([`crate::rigid::ChartError::SingularChart`]) at
    /// the chart's gimbal lock (`|det B(q)|` below [`crate::rigid::SINGULAR_DET`]): integrate through
    /// it with [`super::ChartedTop`] or [`super::EulerianTop`]; [`TopError::NonFiniteResult`]
    /// if q̈ is not finite all the same (a NaN field or torque, or an overflow), and before it
    /// [`TopError::NonFiniteMotor`] naming a driven rotor's motor that returned NaN or ±∞.
    fn accelerations_in(
        &self,
        seq: AngleSequence,
        t: f64,
        state: &[f64; N],
    ) -> Result<[f64; 3], TopError> {
        self.check_all()?;
        // The motors are checked where q̈ is computed: at a finite state in a regular chart.
        let mut motors = Ok(());
        let accel = checked_accelerations(
            seq,
            state,
            |q| self.rate_matrix_in(seq, q),
            || {
                motors = checked_motors(self, t, state);
                self.accelerations_unchecked_in(seq, t, state)
            },
        );
        motors.and(accel)
    }

    /// The energy T + V in [`TopDynamics::SEQUENCE`]; NaN for a driven top (use
    /// [`TopDynamics::energy_in`] with the whole state).
    fn energy(&self, q: &[f64; 3], q_dot: &[f64; 3]) -> f64 {
        match state_of(q, q_dot) {
            Some(state) => self.energy_in(Self::SEQUENCE, &state),
            None => f64::NAN,
        }
    }

    /// The body angular velocity ω = B(q) q̇ of [`TopDynamics::SEQUENCE`].
    fn omega_from_rates(&self, q: &[f64; 3], q_dot: &[f64; 3]) -> Vector3<f64> {
        self.rate_matrix_in(Self::SEQUENCE, q) * Vector3::from(*q_dot)
    }

    /// The rates q̇ = B(q)⁻¹ ω of [`TopDynamics::SEQUENCE`].
    ///
    /// # Errors
    /// As [`crate::rigid::rates_from_omega`]: [`TopError::Chart`] ([`crate::rigid::ChartError::SingularChart`]) at gimbal lock
    /// (`|det B|` below [`crate::rigid::SINGULAR_DET`]), [`TopError::NonFinite`] for non-finite
    /// input.
    fn rates_from_omega(&self, q: &[f64; 3], omega: &Vector3<f64>) -> Result<[f64; 3], TopError> {
        Ok(rates_from_omega(
            Self::SEQUENCE,
            &self.rate_matrix_in(Self::SEQUENCE, q),
            q,
            omega,
        )?)
    }
}

/// The angle-form state `[q, q̇]` that [`TopDynamics::accelerations_unchecked_in`] and [`TopDynamics::energy_in`] take.
pub fn angle_state(q: &[f64; 3], q_dot: &[f64; 3]) -> [f64; 6] {
    [q[0], q[1], q[2], q_dot[0], q_dot[1], q_dot[2]]
}

/// `[q, q̇]` as the state of a top of `N` slots: `None` unless `N = 6` (a driven top's
/// state holds its wheels' rates too, which `(q, q̇)` does not give).
fn state_of<const N: usize>(q: &[f64; 3], q_dot: &[f64; 3]) -> Option<[f64; N]> {
    (N == 6).then(|| {
        let s = angle_state(q, q_dot);
        std::array::from_fn(|k| s.get(k).copied().unwrap_or(f64::NAN))
    })
}
