//! How a rigid scene's refusal reaches the integrators: the conversion the scenes' errors
//! share (each scene's `into_ode_error`), so that a motor, a rotor, the body and a binding
//! are reported the same way whichever scene refused them.

use core::fmt::Display;

use crate::body::BodyError;
use crate::codegen::BindingError;
use crate::ode::{OdeError, binding_quantity, body_quantity, refused};

use super::rotor::{motor_input_error, rotor_quantity};

/// The message of a rotor refused for its numbers (the top's and the free body's
/// `InvalidRotor`): an axial moment not finite and positive, or an axis not finite and
/// non-zero.
pub(crate) fn invalid_rotor(rotor: usize, inertia: f64, axis_norm: f64) -> String {
    format!(
        "rotor {rotor}: its inertia must be finite and > 0 and its axis finite and non-zero: \
         inertia = {inertia}, |axis| = {axis_norm}"
    )
}

/// The message of a motor whose torque is NaN or ±∞ (the top's and the free body's
/// `NonFiniteMotor`), naming the motor as [`motor_input_error`] names it to the integrators.
pub(crate) fn non_finite_motor(rotor: &str, motor: &str, t: f64, value: f64) -> String {
    format!(
        "the motor `{motor}` of {rotor} returned {value} at t = {t}: a motor's torque must be finite"
    )
}

/// A scene error's variant as [`scene_ode_error`] reads it: one of the kinds every rigid
/// scene has, or the scene's own quantity and value.
pub(crate) enum Refusal<'a> {
    /// A stepper's error, passed on as it is.
    Ode(&'a OdeError),
    /// A motor's torque that is not finite: the rotor, the motor function, the time and the
    /// value.
    Motor(&'a str, &'a str, f64, f64),
    /// The body's description.
    Body(&'a BodyError),
    /// A parameter binding of an interpreted model.
    Binding(&'a BindingError),
    /// A rotor's inertia and the norm of its axis, one of them bad.
    Rotor(f64, f64),
    /// The smallest principal moment of the body without its driven wheels' axial moments.
    DrivenInertia(f64),
    /// The scene's own refusal: the quantity it names and its value.
    Named(String, f64),
}

impl Refusal<'_> {
    /// The scene's own refusal of `quantity` at `value`.
    pub(crate) fn named(quantity: &str, value: f64) -> Self {
        Refusal::Named(quantity.to_owned(), value)
    }
}

/// `error`, whose variant `refusal` reads, as the integrators report it from
/// [`System::check_parameters`](crate::ode::System::check_parameters): a stepper's error is
/// passed on as it is, a motor's torque becomes [`OdeError::NonFiniteInput`] naming the motor
/// ([`motor_input_error`]), every other refusal [`OdeError::InvalidSystemParameter`] naming
/// the quantity (the body's part, the binding's parameter, `rotor inertia`, `rotor axis`, the
/// scene's own) with its value and `error`'s message.
pub(crate) fn scene_ode_error(refusal: Refusal<'_>, error: &impl Display) -> OdeError {
    let named = match refusal {
        Refusal::Ode(e) => return e.clone(),
        Refusal::Motor(rotor, motor, t, value) => return motor_input_error(rotor, motor, t, value),
        Refusal::Body(b) => body_quantity(b),
        Refusal::Binding(b) => binding_quantity(b),
        Refusal::Rotor(inertia, axis_norm) => rotor_quantity(inertia, axis_norm),
        Refusal::DrivenInertia(smallest) => ("rotor inertia".to_owned(), smallest),
        Refusal::Named(quantity, value) => (quantity, value),
    };
    refused(named, error)
}
