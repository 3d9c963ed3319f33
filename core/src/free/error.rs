//! Typed errors of the free-body scene: bad states, bad parameters, a derivation that cannot
//! be formed, and the failures of the steppers and exact flows it runs on.
//!
//! The rotor refusals ([`FreeError::InvalidRotor`], [`FreeError::DrivenInertia`]) stay this
//! enum's own variants, so a user's `match` names them as it names every other refusal of the
//! scene; the rule behind them is written once in [`crate::rigid`]
//! ([`crate::rigid::check_driven_inertia`], [`crate::rigid::rotor_quantity`]) and shared with
//! the top, as are their messages and the conversion to the integrators' error
//! ([`FreeError::into_ode_error`]). (Wrapping one shared rotor error instead would have made the
//! match two levels deep, and the derive's generated checks build these variants by name.)

use thiserror::Error;

use crate::body::BodyError;
use crate::codegen::BindingError;
use crate::exact::ExactError;
use crate::ode::OdeError;
use crate::rigid::refusal::{Refusal, invalid_rotor, non_finite_motor, scene_ode_error};

/// Why a free body could not be derived, set up, integrated or answered.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FreeError {
    /// The attitude quaternion of a state is zero, so it names no attitude.
    #[error(
        "the attitude quaternion {quaternion:?} is zero; a state needs a non-zero quaternion \
         (FreeState::to_array builds one from a UnitQuaternion)"
    )]
    ZeroQuaternion {
        /// The quaternion as stored, `[w, x, y, z]`.
        quaternion: [f64; 4],
    },
    /// A part of a state holds NaN or ±∞.
    #[error("non-finite {quantity}: {values:?}")]
    NonFinite {
        /// Which part: the position, the velocity, the attitude quaternion or ω.
        quantity: &'static str,
        /// Its values.
        values: Vec<f64>,
    },
    /// A parameter of the body or of its forces is NaN or ±∞.
    #[error("parameter `{name}` = {value} is not finite")]
    NonFiniteParameter {
        /// The parameter (a field of the struct, or a name of a run-time model).
        name: String,
        /// Its value.
        value: f64,
    },
    /// A part of a wrench — a user function's [`super::AppliedWrench`] or the total — holds
    /// NaN or ±∞.
    #[error("non-finite wrench: the {part} is {values:?}")]
    NonFiniteWrench {
        /// Which part: the force or the torque, and its frame.
        part: &'static str,
        /// Its components.
        values: [f64; 3],
    },
    /// The mass or a principal moment is not finite and positive.
    #[error(
        "mass and principal moments must be finite and > 0: mass = {mass}, moments = {moments:?}"
    )]
    InvalidInertia {
        /// The mass.
        mass: f64,
        /// The principal moments about the centre of mass.
        moments: [f64; 3],
    },
    /// The scene's mass or a principal moment is zero as an expression: the equations of
    /// motion divide by it.
    #[error("the {quantity} is identically zero: the equations of motion divide by it")]
    ZeroInertia {
        /// Which: "mass" or "principal moment I1" …
        quantity: &'static str,
    },
    /// A rotor's axis is zero as an expression: it names no direction to spin about.
    #[error("rotor {rotor} has a zero axis: give a non-zero body-fixed direction")]
    ZeroRotorAxis {
        /// The rotor's index: in the order declared for a derived body; for a run-time
        /// [`super::FreeScene`], in its `rotors`, with its `driven` ones counted after them
        /// (rotor `rotors.len() + k` is `driven[k]`).
        rotor: usize,
    },
    /// A rotor's axial moment is not finite and positive, or its axis not finite and
    /// non-zero, for the current field values: the rule literals meet at compile time.
    #[error("{}", invalid_rotor(*.rotor, *.inertia, *.axis_norm))]
    InvalidRotor {
        /// The rotor's index, counted as [`FreeError::ZeroRotorAxis`] counts it.
        rotor: usize,
        /// Its axial moment of inertia J (kg·m²).
        inertia: f64,
        /// The length |â| of its axis as given.
        axis_norm: f64,
    },
    /// With driven rotors, the body's inertia once its driven wheels turn freely,
    /// I − Σ Jₖ âₖ âₖᵀ, is not positive definite for the current values: a wheel's axial
    /// moment reaches the body's own about that axis (the rule literals meet at compile time).
    #[error(
        "rotor {rotor}: the body without its driven wheels' axial moments, I − Σ J â âᵀ, must be positive definite, but its smallest principal moment is {smallest} (a wheel's J must stay below the body's moment about its axis)"
    )]
    DrivenInertia {
        /// The rotor's index: in the order declared for a derived body, in
        /// [`super::FreeScene::driven`] for a run-time scene.
        rotor: usize,
        /// The smallest eigenvalue of I − Σ J â âᵀ over the wheels up to this one.
        smallest: f64,
    },
    /// A state array too short for the free body: the 13 slots of [`super::layout`] and one
    /// per driven rotor.
    #[error("a state of {len} numbers; this free body's holds {expected}")]
    StateLength {
        /// The length given.
        len: usize,
        /// The length the body's state has.
        expected: usize,
    },
    /// The exact flow was asked of a body under forces other than uniform gravity.
    #[error(
        "the exact flow needs a body under uniform gravity alone, but it also declares {declared}"
    )]
    NotExact {
        /// The other forces and torques declared.
        declared: &'static str,
    },
    /// A drag or damping coefficient below zero, read from a field: the rule a literal meets
    /// at compile time (a negative one feeds energy in).
    #[error("`{name}` is {value}: it must be zero or positive (a negative one feeds energy in)")]
    NegativeCoefficient {
        /// `drag` or `damping`.
        name: &'static str,
        /// Its value.
        value: f64,
    },
    /// A parameter of the interpreted [`super::FreeModel`] could not be bound (unknown,
    /// unset, not finite, or a user force's run-time input the interpreter cannot supply).
    #[error(transparent)]
    Binding(#[from] BindingError),
    /// The body's description breaks a rule for the current parameter values.
    #[error(transparent)]
    Body(#[from] BodyError),
    /// A driven rotor's motor function returned NaN or ±∞: checked by a run's stepper when
    /// f is not finite ([`FreeDynamics::check_motors`](super::FreeDynamics::check_motors)).
    #[error("{}", non_finite_motor(.rotor, .motor, *.t, *.value))]
    NonFiniteMotor {
        /// The driven rotor, by its name in
        /// [`FreeDynamics::DRIVEN_ROTORS`](super::FreeDynamics::DRIVEN_ROTORS) (`rotor_k`).
        rotor: &'static str,
        /// The motor function, as `rotor(torque = path)` writes its path.
        motor: &'static str,
        /// The time it was called at.
        t: f64,
        /// The value it returned.
        value: f64,
    },
    /// A stepper failed, or a stop time is not finite or lies in the past.
    #[error(transparent)]
    Ode(#[from] OdeError),
    /// The exact attitude could not be set up or evaluated.
    #[error(transparent)]
    Exact(#[from] ExactError),
}

impl FreeError {
    /// This refusal as the integrators report it, from
    /// [`System::check_parameters`](crate::ode::System::check_parameters), as every rigid
    /// scene reports its own ([`crate::rigid`] holds the shared conversion): a bad parameter,
    /// coefficient or inertia is [`OdeError::InvalidSystemParameter`] naming it with its
    /// value and this error's message ([`FreeError::Ode`] is passed on,
    /// [`FreeError::NonFiniteMotor`] names the motor in [`OdeError::NonFiniteInput`]); a
    /// [`FreeError::NonFiniteWrench`] is named `wrench: <part>` with its first component that
    /// is not finite.
    ///
    /// ```
    /// use precess::free::FreeError;
    /// use precess::ode::OdeError;
    /// let wrench = FreeError::NonFiniteWrench { part: "torque", values: [0.0, f64::NAN, 1.0] };
    /// let drag = FreeError::NegativeCoefficient { name: "drag", value: -0.1 };
    /// match drag.into_ode_error() {
    ///     OdeError::InvalidSystemParameter { quantity, value, .. } => {
    ///         assert_eq!((quantity.as_str(), value), ("drag", -0.1))
    ///     }
    ///     other => panic!("{other:?}"),
    /// }
    /// assert!(matches!(
    ///     wrench.into_ode_error(),
    ///     OdeError::InvalidSystemParameter { quantity, value, .. } if quantity == "wrench: torque" && value.is_nan()
    /// ));
    /// ```
    pub fn into_ode_error(self) -> OdeError {
        // The variants in the order the enum declares them.
        let refusal = match &self {
            FreeError::NonFiniteParameter { name, value } => Refusal::named(name, *value),
            // The wrench's part and its first component that is not finite: what a user
            // looks for in their force function.
            FreeError::NonFiniteWrench { part, values } => {
                let bad = values.iter().copied().find(|c| !c.is_finite());
                Refusal::Named(format!("wrench: {part}"), bad.unwrap_or(f64::NAN))
            }
            FreeError::InvalidInertia { mass, moments } => {
                if mass.is_finite() && *mass > 0.0 {
                    let smallest = moments.iter().copied().fold(f64::INFINITY, f64::min);
                    Refusal::named("principal moment", smallest)
                } else {
                    Refusal::named("mass", *mass)
                }
            }
            FreeError::InvalidRotor {
                inertia, axis_norm, ..
            } => Refusal::Rotor(*inertia, *axis_norm),
            FreeError::DrivenInertia { smallest, .. } => Refusal::DrivenInertia(*smallest),
            FreeError::NegativeCoefficient { name, value } => Refusal::named(name, *value),
            FreeError::Binding(b) => Refusal::Binding(b),
            FreeError::Body(b) => Refusal::Body(b),
            FreeError::NonFiniteMotor {
                rotor,
                motor,
                t,
                value,
            } => Refusal::Motor(rotor, motor, *t, *value),
            FreeError::Ode(e) => Refusal::Ode(e),
            _ => Refusal::named("parameters", f64::NAN),
        };
        scene_ode_error(refusal, &self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A wrench that is not finite is named by its part and its bad component, not as
    /// "parameters".
    #[test]
    fn a_non_finite_wrench_names_its_part() {
        let e = FreeError::NonFiniteWrench {
            part: "force, description axes",
            values: [0.5, f64::INFINITY, f64::NAN],
        }
        .into_ode_error();
        match e {
            OdeError::InvalidSystemParameter {
                quantity,
                value,
                message,
            } => {
                assert_eq!(quantity, "wrench: force, description axes");
                assert_eq!(value, f64::INFINITY);
                assert!(message.contains("non-finite wrench"), "{message}");
            }
            other => panic!("not a refused parameter: {other:?}"),
        }
    }
}
