//! What a scene's refusal of its parameters names, for
//! [`OdeError::InvalidSystemParameter`]: the quantity and its value, read from the errors
//! the body and the bindings share (each scene reads its own errors and calls these for
//! the parts they wrap).

use super::error::OdeError;
use crate::body::BodyError;
use crate::codegen::BindingError;

/// The quantity and value a body's refusal names (`part 0 (body) mass`, −1). Variants
/// without one number name their most telling one: the smallest principal moment of a
/// tensor that is not positive definite, the largest of one that breaks the triangle
/// inequality, |axis| of a rotation axis with no direction.
pub(crate) fn body_quantity(e: &BodyError) -> (String, f64) {
    use BodyError as B;
    let part = |part: &usize, kind: &str, key: &str| format!("part {part} ({kind}) {key}");
    match e {
        B::NonFinite {
            part: p,
            kind,
            key,
            value,
        }
        | B::NonPositiveDimension {
            part: p,
            kind,
            key,
            value,
        } => (part(p, kind, key), *value),
        B::NonFinitePivot { value } => ("pivot".to_owned(), *value),
        B::NonPositiveMass {
            part: p,
            kind,
            value,
        } => (part(p, kind, "mass"), *value),
        B::TubeRadii { part: p, inner, .. } => (part(p, "tube", "inner radius"), *inner),
        B::NotSymmetric {
            part: p,
            row,
            col,
            upper,
            ..
        } => (part(p, "body", &format!("I[{row}][{col}]")), *upper),
        B::NotPositiveDefinite { part: p, moments } => {
            (part(p, "body", "principal moment"), moments[0])
        }
        B::TriangleInequality { part: p, moments } => {
            (part(p, "body", "principal moment"), moments[2])
        }
        B::ZeroRotationAxis {
            part: p,
            kind,
            axis,
        } => (
            part(p, kind, "rotation axis"),
            axis.iter().map(|a| a * a).sum::<f64>().sqrt(),
        ),
        B::NotOrthonormal {
            part: p,
            kind,
            deviation,
        } => (part(p, kind, "rotation"), *deviation),
        B::ImproperRotation {
            part: p,
            kind,
            determinant,
        } => (part(p, kind, "rotation"), *determinant),
        B::Overflow { quantity, value } => ((*quantity).to_owned(), *value),
        B::Underflow { moments } => ("principal moment".to_owned(), moments[2]),
        B::ZeroPrincipalMoment { moments } => ("principal moment".to_owned(), moments[0]),
        B::ZeroTotalMass | B::IdenticallyZeroMoment { .. } => ("mass".to_owned(), 0.0),
        // No number to name (no part, a pivot missing): the message says what is wrong.
        _ => ("body".to_owned(), f64::NAN),
    }
}

/// The parameter and value a binding's refusal names (NaN where it has none: a parameter
/// unknown or unset).
pub(crate) fn binding_quantity(e: &BindingError) -> (String, f64) {
    match e {
        BindingError::NonFinite { name, value } => (name.clone(), *value),
        BindingError::DuplicateParameter { name, second, .. } => (name.clone(), *second),
        BindingError::UnknownParameter { name, .. }
        | BindingError::UnsetParameter { name, .. }
        | BindingError::RunTimeInput { name, .. } => (name.clone(), f64::NAN),
    }
}

/// [`OdeError::InvalidSystemParameter`] of a quantity, its value and the scene's error.
pub(crate) fn refused(
    (quantity, value): (String, f64),
    scene_error: &impl core::fmt::Display,
) -> OdeError {
    OdeError::InvalidSystemParameter {
        quantity,
        value,
        message: scene_error.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_negative_mass_is_named_with_its_part_and_value() {
        let e = BodyError::NonPositiveMass {
            part: 2,
            kind: "cone",
            value: -0.5,
        };
        let OdeError::InvalidSystemParameter {
            quantity,
            value,
            message,
        } = refused(body_quantity(&e), &e)
        else {
            panic!("not a parameter error");
        };
        assert_eq!(quantity, "part 2 (cone) mass");
        assert_eq!(value, -0.5);
        assert_eq!(message, "part 2 (cone): mass must be positive, got -0.5");
    }
}
