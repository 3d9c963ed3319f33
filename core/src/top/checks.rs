//! A top's checks, in one place: the scalar and vector settings of its scene and the one rule
//! function that judges them (the derive calls it on literal values while it expands, a
//! compile error, and the generated [`super::TopDynamics::check_parameters`] on field values
//! at run time, a [`TopError`], so a value is accepted or refused alike whichever way it was
//! written); the driven rotors' rule; and the checks of a state and of the q̈ it gives, which
//! the derived and the interpreted tops share.

use nalgebra::{Matrix3, Vector3};

use super::dynamics::TopDynamics;
use super::error::TopError;
use crate::rigid::{AngleSequence, check_chart, first_non_finite_motor};

/// The values of a top's declared torque settings (`None`: not declared), as
/// `#[top(...)]` takes them from literals or fields.
///
/// Sign conventions: `gravity` is the magnitude g ≥ 0 of a uniform field pointing along −z in
/// space (write 9.81, not −9.81); `damping` is the coefficient k ≥ 0 of the torque −k ω;
/// the two constant torques are any finite vectors, `body_torque` in body axes and
/// `space_torque` in space axes.
///
/// # Examples
///
/// A gravity given with the sign of its direction is refused by name:
///
/// ```
/// use precess::top::{TopError, TopParameters};
///
/// let upright = TopParameters { gravity: Some(9.81), damping: Some(0.02), ..Default::default() };
/// assert_eq!(upright.check(), Ok(()));
///
/// let signed = TopParameters { gravity: Some(-9.81), ..Default::default() };
/// assert_eq!(signed.check(), Err(TopError::NegativeGravity { value: -9.81 }));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TopParameters {
    /// The magnitude g of gravity along −z (space).
    pub gravity: Option<f64>,
    /// The coefficient k of the damping torque −k ω.
    pub damping: Option<f64>,
    /// A constant torque fixed in the body, body axes.
    pub body_torque: Option<Vector3<f64>>,
    /// A constant torque fixed in space, space axes.
    pub space_torque: Option<Vector3<f64>>,
}

impl TopParameters {
    /// Checks every declared value, in the order of the fields.
    ///
    /// Gravity and damping must be finite and ≥ 0 (a zero gravity or damping is the torque
    /// left out, which is physics, so it is allowed); torque components must be finite.
    ///
    /// # Errors
    /// [`TopError::NonFiniteParameter`] naming the setting and its NaN or infinite value;
    /// [`TopError::NegativeGravity`] for g < 0 (a gravity written with the sign of its
    /// direction would pull the top up); [`TopError::NegativeDamping`] for k < 0 (a negative
    /// damping feeds energy in).
    pub fn check(&self) -> Result<(), TopError> {
        if let Some(value) = self.gravity {
            finite("gravity", value)?;
            if value < 0.0 {
                return Err(TopError::NegativeGravity { value });
            }
        }
        if let Some(value) = self.damping {
            finite("damping", value)?;
            if value < 0.0 {
                return Err(TopError::NegativeDamping { value });
            }
        }
        for (parameter, torque) in [
            ("body_torque", &self.body_torque),
            ("space_torque", &self.space_torque),
        ] {
            for &value in torque.iter().flatten() {
                finite(parameter, value)?;
            }
        }
        Ok(())
    }
}

/// A setting must be finite: NaN and ∞ propagate into every acceleration.
fn finite(parameter: &'static str, value: f64) -> Result<(), TopError> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(TopError::NonFiniteParameter { parameter, value })
    }
}

impl TopError {
    /// The driven rotors' rule: the top's inertia about the pivot stays positive definite as
    /// each wheel's axial moment is taken out, I − Σⱼ≤ₖ Jⱼ âⱼ âⱼᵀ; each rotor is (its index
    /// among every rotor declared, its axis, its J). The derive's `check_parameters` calls it
    /// for field values.
    ///
    /// # Errors
    /// [`TopError::DrivenInertia`] naming the first rotor at which it fails.
    pub fn check_driven_inertia(
        inertia: &nalgebra::Matrix3<f64>,
        rotors: &[(usize, [f64; 3], f64)],
    ) -> Result<(), TopError> {
        crate::rigid::check_driven_inertia(inertia, rotors, |rotor, smallest| {
            TopError::DrivenInertia { rotor, smallest }
        })
    }
}

/// Checks that the angles, rates and (for a driven top) wheel rates of an angle-form state
/// are finite.
///
/// # Errors
/// [`TopError::NonFinite`] naming the angles q, the rates q̇ or the rotor rates Ω.
pub(crate) fn check_state(state: &[f64]) -> Result<(), TopError> {
    let (angles, rest) = state.split_at(state.len().min(3));
    let (rates, rotors) = rest.split_at(rest.len().min(3));
    for (quantity, part) in [
        ("angles q", angles),
        ("rates q̇", rates),
        ("rotor rates Ω", rotors),
    ] {
        if !part.iter().all(|v| v.is_finite()) {
            return Err(TopError::NonFinite {
                quantity,
                values: part.to_vec(),
            });
        }
    }
    Ok(())
}

/// q̈ as every checked top gives it, derived or interpreted: the state finite
/// ([`check_state`]), the angles away from the chart's gimbal lock (`rate_matrix(q)` is
/// B(q), judged by [`check_chart`]), then `accel()` finite.
///
/// # Errors
/// [`TopError::NonFinite`], [`TopError::Chart`] ([`crate::rigid::ChartError::SingularChart`]),
/// [`TopError::NonFiniteResult`] for a q̈ that holds NaN or ±∞.
pub(crate) fn checked_accelerations(
    seq: AngleSequence,
    state: &[f64],
    rate_matrix: impl FnOnce(&[f64; 3]) -> Matrix3<f64>,
    accel: impl FnOnce() -> [f64; 3],
) -> Result<[f64; 3], TopError> {
    check_state(state)?;
    let q: [f64; 3] = std::array::from_fn(|k| state.get(k).copied().unwrap_or(f64::NAN));
    check_chart(seq, &rate_matrix(&q), &q)?;
    let a = accel();
    if a.iter().all(|v| v.is_finite()) {
        Ok(a)
    } else {
        Err(TopError::NonFiniteResult {
            quantity: "q̈",
            values: a.to_vec(),
        })
    }
}

/// Calls every motor of `top` at `(t, state)`.
///
/// # Errors
/// [`TopError::NonFiniteMotor`] naming the first motor that returned NaN or ±∞.
pub(crate) fn checked_motors<T: TopDynamics<N> + ?Sized, const N: usize>(
    top: &T,
    t: f64,
    state: &[f64; N],
) -> Result<(), TopError> {
    let mut u = vec![0.0; T::MOTORS.len()];
    top.motor_torques(t, state, &mut u);
    match first_non_finite_motor(T::DRIVEN_ROTORS, T::MOTORS, &u) {
        Some((rotor, motor, value)) => Err(TopError::NonFiniteMotor {
            rotor,
            motor,
            t,
            value,
        }),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_rule_names_its_setting() {
        let none = TopParameters::default();
        assert_eq!(none.check(), Ok(()));
        let zero = TopParameters {
            gravity: Some(0.0),
            damping: Some(0.0),
            body_torque: Some(Vector3::zeros()),
            space_torque: Some(Vector3::new(-1.0, 0.0, 2.0)),
        };
        assert_eq!(zero.check(), Ok(()));
        let damped = TopParameters {
            damping: Some(-0.5),
            ..none
        };
        assert_eq!(
            damped.check(),
            Err(TopError::NegativeDamping { value: -0.5 })
        );
        let nan = TopParameters {
            gravity: Some(f64::NAN),
            ..none
        };
        assert!(matches!(
            nan.check(),
            Err(TopError::NonFiniteParameter { parameter: "gravity", value }) if value.is_nan()
        ));
        let torque = TopParameters {
            space_torque: Some(Vector3::new(0.0, f64::INFINITY, 0.0)),
            ..none
        };
        assert_eq!(
            torque.check(),
            Err(TopError::NonFiniteParameter {
                parameter: "space_torque",
                value: f64::INFINITY
            })
        );
        // −0.0 is not below zero: it is the same gravity as 0.
        let minus_zero = TopParameters {
            gravity: Some(-0.0),
            ..none
        };
        assert_eq!(minus_zero.check(), Ok(()));
    }
}
