//! The top scene's one error at run time: a state a chart cannot represent, settings out of
//! range, the chart-switching driver, and the interpreted model's parameters.
//!
//! The rotor refusals ([`TopError::InvalidRotor`], [`TopError::DrivenInertia`]) stay this
//! enum's own variants, so a user's `match` names them as it names every other refusal of the
//! scene; the rule behind them is written once in [`crate::rigid`]
//! ([`crate::rigid::check_driven_inertia`], [`crate::rigid::rotor_quantity`]) and shared with
//! the free body, as are their messages and the conversion to the integrators' error
//! ([`TopError::into_ode_error`]). (Wrapping one shared rotor error instead would have made the
//! match two levels deep, and the derive's generated checks build these variants by name.)

use thiserror::Error;

use crate::body::BodyError;
use crate::codegen::BindingError;
use crate::ode::OdeError;
use crate::rigid::ChartError;
use crate::rigid::refusal::{Refusal, invalid_rotor, non_finite_motor, scene_ode_error};

use super::theory::TheoryError;

/// What a top refuses: a state its angle or Eulerian form cannot take, settings out of range,
/// a body that breaks a rule, the chart switch's and the interpreted model's failures.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TopError {
    /// An input holds NaN or ±∞.
    #[error("non-finite {quantity}: {values:?}")]
    NonFinite {
        /// What the values are: the angles q, the rates q̇, the body angular velocity ω, …
        quantity: &'static str,
        /// The offending values.
        values: Vec<f64>,
    },
    /// A finite state in a regular chart gave a non-finite result: a parameter or the user
    /// torque is NaN or infinite, or the result overflows f64.
    #[error(
        "{quantity} = {values:?} is not finite at a finite state in a regular chart \
         (a NaN or infinite parameter or torque, or an overflow)"
    )]
    NonFiniteResult {
        /// The quantity computed: q̈ or the rates q̇.
        quantity: &'static str,
        /// Its values.
        values: Vec<f64>,
    },
    /// A declared setting of the scene (`#[top(gravity = g)]`, `damping`, a constant torque)
    /// is NaN or infinite.
    #[error("the top's `{parameter}` is {value}: it must be finite")]
    NonFiniteParameter {
        /// The setting, as `#[top(...)]` names it.
        parameter: &'static str,
        /// Its value.
        value: f64,
    },
    /// The gravity is negative. It is the magnitude g ≥ 0 of a field along −z in space, so a
    /// gravity written with the sign of its direction would pull the top up.
    #[error(
        "the top's `gravity` is {value}: it must be zero or positive, the magnitude g of \
         gravity along −z (write 9.81, not −9.81)"
    )]
    NegativeGravity {
        /// The value given.
        value: f64,
    },
    /// The damping coefficient is negative: the torque −k ω would feed energy in.
    #[error(
        "the top's `damping` is {value}: it must be zero or positive (the torque is −k ω; a \
         negative k feeds energy in)"
    )]
    NegativeDamping {
        /// The value given.
        value: f64,
    },
    /// A rotor's axial moment is not finite and positive, or its axis not finite and
    /// non-zero, for the current field values: the rule literals meet at compile time.
    #[error("{}", invalid_rotor(*.rotor, *.inertia, *.axis_norm))]
    InvalidRotor {
        /// The rotor's index, in the order declared.
        rotor: usize,
        /// Its axial moment of inertia.
        inertia: f64,
        /// The length of its axis.
        axis_norm: f64,
    },
    /// With its driven wheels turning freely the body keeps the inertia I − Σ J â âᵀ about the
    /// pivot, which must be positive definite: a wheel's J at least the body's own moment
    /// about the wheel's axis leaves it none (the rule literals meet at compile time).
    #[error(
        "rotor {rotor}'s inertia is too large for the body: with its driven wheels turning freely the body keeps I − Σ J â âᵀ about the pivot, whose smallest principal moment is {smallest}; it must be positive"
    )]
    DrivenInertia {
        /// The first driven rotor, by its index among every rotor declared, at which the
        /// inertia stops being positive definite.
        rotor: usize,
        /// The smallest eigenvalue of I − Σ J â âᵀ up to that rotor (NaN if not finite).
        smallest: f64,
    },
    /// A driven rotor's motor function returned NaN or ±∞: checked by the methods that call
    /// the motors ([`super::TopDynamics::accelerations_in`], and a run's stepper when f is
    /// not finite).
    #[error("{}", non_finite_motor(.rotor, .motor, *.t, *.value))]
    NonFiniteMotor {
        /// The driven rotor, by its name in [`super::TopDynamics::DRIVEN_ROTORS`] (`rotor_j`).
        rotor: &'static str,
        /// The motor function, as `rotor(torque = path)` writes its path.
        motor: &'static str,
        /// The time it was called at.
        t: f64,
        /// The value it returned.
        value: f64,
    },
    /// [`super::ChartedTop::with_rotor_rates`] was given a number of driven rotors' rates
    /// other than the top's, or one that is not finite.
    #[error(
        "the top has {expected} driven rotor(s), so it starts from {expected} finite rotor rate(s), but was given {given:?}"
    )]
    RotorRates {
        /// How many driven rotors the top has.
        expected: usize,
        /// The rates given.
        given: Vec<f64>,
    },
    /// A method over the angles and rates `(q, q̇)` alone was asked of a top with driven
    /// rotors, whose equations read the wheels' rates too.
    #[error(
        "`{method}` takes the angles and rates alone, but this top has {rotors} driven rotor(s) whose rates are part of its state: use `{method}_in` with the whole state [q, q̇, Ω]"
    )]
    DrivenState {
        /// The method asked.
        method: &'static str,
        /// How many driven rotors the top has.
        rotors: usize,
    },
    /// [`super::FastTop::of_top`] was asked of a top with more than gravity: the splitting
    /// models the weight alone (no rotor, damping or constant torque).
    #[error(
        "the fast-top splitting models a top under gravity alone, but this one also declares {declared}: integrate it with TopChart, ChartedTop or EulerianTop"
    )]
    FastTopBeyondGravity {
        /// What else it declares: "a rotor", or the `#[top]` name of a torque (`damping`,
        /// `body_torque`, `space_torque`, `torque`).
        declared: &'static str,
    },
    /// The body of a top breaks a rule of its description (a field-valued mass, say), found
    /// by [`super::TopDynamics::check_all`].
    #[error(transparent)]
    Body(#[from] BodyError),
    /// The attitude quaternion of an Eulerian state is zero, so it names no attitude.
    #[error(
        "the attitude quaternion {quaternion:?} is zero; a state needs a non-zero quaternion \
         (EulerianTop::state builds one from a UnitQuaternion)"
    )]
    ZeroQuaternion {
        /// The quaternion as stored, `[w, x, y, z]`.
        quaternion: [f64; 4],
    },
    /// The angles are at a chart's gimbal lock ([`ChartError::SingularChart`], the one
    /// rule of [`crate::rigid::check_chart`]), or the chart switch of
    /// [`super::ChartedTop`] cannot start (an attitude that is not a rotation, a bad
    /// `switch_below`, two charts of one sequence).
    #[error(transparent)]
    Chart(#[from] ChartError),
    /// A parameter of the interpreted [`super::TopModel`] could not be bound (unknown, unset,
    /// not finite, or a run-time input the interpreter cannot supply).
    #[error(transparent)]
    Binding(#[from] BindingError),
    /// The stepper of a driver failed, or a stop time is not finite or lies in the past.
    #[error(transparent)]
    Ode(#[from] OdeError),
    /// The closed forms do not apply to this top ([`super::TopDynamics::theory`]: not
    /// symmetric about its z axis, a centre off it, no gravity, other torques).
    #[error(transparent)]
    Theory(#[from] TheoryError),
}

impl TopError {
    /// This refusal as the integrators report it, from
    /// [`System::check_parameters`](crate::ode::System::check_parameters): a bad setting
    /// (`gravity`, `damping`, a parameter) is [`OdeError::InvalidSystemParameter`] naming it
    /// with its value and this error's message; [`TopError::Ode`] is passed on as it is,
    /// [`TopError::NonFiniteMotor`] becomes [`OdeError::NonFiniteInput`] naming the motor, and
    /// the body's, a binding's and a rotor's refusals are named as the free body names them.
    ///
    /// ```
    /// use precess::ode::OdeError;
    /// use precess::top::TopError;
    /// let e = TopError::NegativeGravity { value: -9.81 }.into_ode_error();
    /// let OdeError::InvalidSystemParameter { quantity, value, message } = e else {
    ///     panic!("{e:?}");
    /// };
    /// assert_eq!((quantity.as_str(), value), ("gravity", -9.81));
    /// assert_eq!(message, TopError::NegativeGravity { value: -9.81 }.to_string());
    /// ```
    pub fn into_ode_error(self) -> OdeError {
        // The variants in the order the enum declares them.
        let refusal = match &self {
            TopError::NonFiniteParameter { parameter, value } => Refusal::named(parameter, *value),
            TopError::NegativeGravity { value } => Refusal::named("gravity", *value),
            TopError::NegativeDamping { value } => Refusal::named("damping", *value),
            TopError::InvalidRotor {
                inertia, axis_norm, ..
            } => Refusal::Rotor(*inertia, *axis_norm),
            TopError::DrivenInertia { smallest, .. } => Refusal::DrivenInertia(*smallest),
            TopError::NonFiniteMotor {
                rotor,
                motor,
                t,
                value,
            } => Refusal::Motor(rotor, motor, *t, *value),
            TopError::Body(b) => Refusal::Body(b),
            TopError::Binding(b) => Refusal::Binding(b),
            TopError::Ode(e) => Refusal::Ode(e),
            _ => Refusal::named("parameters", f64::NAN),
        };
        scene_ode_error(refusal, &self)
    }
}
