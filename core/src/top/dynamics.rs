//! The trait `#[top(...)]` implements: a derived top's equations in both angle charts and in
//! Eulerian form, with the helpers built on them.

use nalgebra::{Matrix3, UnitQuaternion, Vector3};

use super::error::TopError;
use super::parameters::TopParameters;
use super::theory::{HeavyTopTheory, derived_theory};
use crate::body::RigidBody;
use crate::codegen::Typeset;
use crate::rigid::AngleSequence;
use crate::rigid::{check_chart, rates_from_omega};

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
pub trait TopDynamics: RigidBody {
    /// The declared angle sequence.
    const SEQUENCE: AngleSequence;

    /// The first declared torque other than gravity, by its `#[top(...)]` name (`damping`,
    /// `body_torque`, `space_torque`, `torque`), or `None` when gravity is all that acts
    /// (the heavy-top closed forms of [`TopDynamics::theory`] then apply).
    const BEYOND_GRAVITY: Option<&'static str> = None;

    /// How many internal rotors `#[top(rotor(...))]` declares (a gyrostat when > 0).
    const ROTORS: usize = 0;

    /// The rotors' total relative angular momentum h = Σ J Ω â in body (description) axes,
    /// for the current field values; zero without rotors. The top's angular momentum about
    /// the pivot is I ω + h.
    fn rotor_momentum(&self) -> Vector3<f64> {
        Vector3::zeros()
    }

    /// The index of the angle called `name` in q and q̇ of [`TopDynamics::SEQUENCE`] (`"phi"`,
    /// `"theta"`, `"psi"` in ZXZ; `"yaw"`, `"pitch"`, `"roll"` in ZYX), if there is one: in
    /// the state `[q, q̇]` the angle is slot i and its rate slot 3 + i. The derive gives the
    /// same indices as consts named in capitals (`Self::THETA`), as a mechanism's.
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
        Self::SEQUENCE.names().iter().position(|&c| c == name)
    }

    /// q̈ in the chart `seq` at time `t` and state `[q, q̇]`.
    fn accelerations_unchecked_in(&self, seq: AngleSequence, t: f64, state: &[f64; 6]) -> [f64; 3];

    /// R(q) in the chart `seq`, body to space.
    fn rotation_in(&self, seq: AngleSequence, q: &[f64; 3]) -> Matrix3<f64>;

    /// B(q) in the chart `seq`: ω = B q̇.
    fn rate_matrix_in(&self, seq: AngleSequence, q: &[f64; 3]) -> Matrix3<f64>;

    /// The energy T + V in the chart `seq`.
    fn energy_in(&self, seq: AngleSequence, state: &[f64; 6]) -> f64;

    /// The Jacobian of q̈ with respect to `(q, q̇)` in [`TopDynamics::SEQUENCE`]: row i holds
    /// `∂q̈_i/∂(q_0, q_1, q_2, q̇_0, q̇_1, q̇_2)`.
    fn angle_jacobian(&self, t: f64, q: &[f64; 3], q_dot: &[f64; 3]) -> [[f64; 6]; 3];

    /// The momenta `∂L/∂q̇_i` of [`TopDynamics::SEQUENCE`] that are conserved for this scene
    /// (`None` for the others).
    fn conserved_momenta(&self, q: &[f64; 3], q_dot: &[f64; 3]) -> [Option<f64>; 3];

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
    fn accelerations_unchecked(&self, t: f64, q: &[f64; 3], q_dot: &[f64; 3]) -> [f64; 3] {
        self.accelerations_unchecked_in(Self::SEQUENCE, t, &angle_state(q, q_dot))
    }

    /// q̈ in [`TopDynamics::SEQUENCE`], refusing a state the chart cannot take.
    ///
    /// # Errors
    /// As [`TopDynamics::accelerations_in`].
    fn accelerations(&self, t: f64, q: &[f64; 3], q_dot: &[f64; 3]) -> Result<[f64; 3], TopError> {
        self.accelerations_in(Self::SEQUENCE, t, &angle_state(q, q_dot))
    }

    /// q̈ in the chart `seq`, refusing a state the chart cannot take.
    ///
    /// # Errors
    /// The errors of [`TopDynamics::check_all`] (a body that breaks a rule of its
    /// description, [`TopError::Body`]; a negative gravity or damping, a NaN setting);
    /// [`TopError::NonFinite`] for non-finite angles or rates; [`TopError::Chart`] ([`crate::rigid::ChartError::SingularChart`]) at
    /// the chart's gimbal lock (`|det B(q)|` below [`crate::rigid::SINGULAR_DET`]): integrate through
    /// it with [`super::ChartedTop`] or [`super::EulerianTop`]; [`TopError::NonFiniteResult`]
    /// if q̈ is not finite all the same (a NaN field or torque, or an overflow).
    fn accelerations_in(
        &self,
        seq: AngleSequence,
        t: f64,
        state: &[f64; 6],
    ) -> Result<[f64; 3], TopError> {
        self.check_all()?;
        check_state(state)?;
        let q = [state[0], state[1], state[2]];
        check_chart(seq, &self.rate_matrix_in(seq, &q), &q)?;
        let a = self.accelerations_unchecked_in(seq, t, state);
        if a.iter().all(|v| v.is_finite()) {
            Ok(a)
        } else {
            Err(TopError::NonFiniteResult {
                quantity: "q̈",
                values: a.to_vec(),
            })
        }
    }

    /// The energy T + V in [`TopDynamics::SEQUENCE`].
    fn energy(&self, q: &[f64; 3], q_dot: &[f64; 3]) -> f64 {
        self.energy_in(Self::SEQUENCE, &angle_state(q, q_dot))
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

/// Checks that the angles and rates of an angle-form state are finite.
///
/// # Errors
/// [`TopError::NonFinite`] naming the angles q or the rates q̇.
pub(crate) fn check_state(state: &[f64; 6]) -> Result<(), TopError> {
    for (quantity, part) in [("angles q", &state[..3]), ("rates q̇", &state[3..])] {
        if !part.iter().all(|v| v.is_finite()) {
            return Err(TopError::NonFinite {
                quantity,
                values: part.to_vec(),
            });
        }
    }
    Ok(())
}
