//! The rules a joint's axes meet, as one function each: the derive applies them to literal
//! axes while it expands, the generated `check_parameters` and [`super::MechanismModel`] to
//! the values of fields and parameters at run time, and [`super::MechanismScene::validate`]
//! to the constants of a scene, so an axis is refused or accepted the same way whichever
//! way it is written.

use super::error::MechanismError;

/// The smallest sine of the angle between a universal joint's two axes: √ε ≈ 1.5e-8.
///
/// The mass matrix of the joint's two coordinates has a pivot proportional to sin² of the
/// angle, so below √ε that pivot is below the rounding of its neighbours and q̈ carries no
/// correct digit.
pub const PARALLEL_SINE: f64 = 1.490_116_119_384_765_6e-8;

/// An axis has a direction: every component finite and |a|² a normal positive number (the
/// engine divides by |a|² and by |a|).
///
/// # Errors
/// [`MechanismError::NonFiniteParameter`] for a NaN or infinite component (naming `axis[k]`
/// of `joint`), [`MechanismError::ZeroAxis`] with |a|² when it is zero, subnormal or
/// overflows.
///
/// # Examples
///
/// ```
/// use precess_core::mechanism::{MechanismError, check_axis};
/// assert_eq!(check_axis("hinge", "axis", [0.0, 3.0, 4.0]), Ok(()));
/// assert!(matches!(
///     check_axis("hinge", "axis", [0.0, 0.0, 0.0]),
///     Err(MechanismError::ZeroAxis { squared_length: Some(0.0), .. })
/// ));
/// ```
pub fn check_axis(joint: &str, name: &str, axis: [f64; 3]) -> Result<(), MechanismError> {
    if let Some((k, &value)) = axis.iter().enumerate().find(|(_, v)| !v.is_finite()) {
        return Err(MechanismError::NonFiniteParameter {
            owner: format!("joint `{joint}`"),
            quantity: format!("{name}[{k}]"),
            value,
        });
    }
    let squared = axis.iter().map(|c| c * c).sum::<f64>();
    // Not `squared < MIN_POSITIVE`: an overflow to ∞ has no direction either.
    if !(f64::MIN_POSITIVE..f64::INFINITY).contains(&squared) {
        return Err(MechanismError::ZeroAxis {
            joint: joint.to_owned(),
            squared_length: Some(squared),
        });
    }
    Ok(())
}

/// A universal joint's axes each have a direction ([`check_axis`]) and are not parallel:
/// the sine of the angle between them, |a × b| / (|a| |b|), is at least [`PARALLEL_SINE`].
///
/// # Errors
/// As [`check_axis`] for either axis (named `axes[0]`, `axes[1]`);
/// [`MechanismError::ParallelAxes`] with the sine when the axes are parallel or opposite.
///
/// # Examples
///
/// ```
/// use precess_core::mechanism::{MechanismError, check_universal_axes};
/// assert_eq!(check_universal_axes("wrist", [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]), Ok(()));
/// assert!(matches!(
///     check_universal_axes("wrist", [1.0, 0.0, 0.0], [-2.0, 0.0, 0.0]),
///     Err(MechanismError::ParallelAxes { sine: 0.0, .. })
/// ));
/// ```
pub fn check_universal_axes(
    joint: &str,
    outer: [f64; 3],
    inner: [f64; 3],
) -> Result<(), MechanismError> {
    check_axis(joint, "axes[0]", outer)?;
    check_axis(joint, "axes[1]", inner)?;
    let (a, b) = (unit(outer), unit(inner));
    let c = [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ];
    let sine = c.iter().map(|x| x * x).sum::<f64>().sqrt();
    // Not `sine < PARALLEL_SINE`: a NaN sine is no angle either.
    if sine.is_nan() || sine < PARALLEL_SINE {
        return Err(MechanismError::ParallelAxes {
            joint: joint.to_owned(),
            sine,
            minimum: PARALLEL_SINE,
        });
    }
    Ok(())
}

/// `v / |v|` for a vector [`check_axis`] accepted (scaled by its largest component first,
/// so neither the squares nor the norm overflow).
fn unit(v: [f64; 3]) -> [f64; 3] {
    let largest = v.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    let scaled = v.map(|x| x / largest);
    let norm = scaled.iter().map(|x| x * x).sum::<f64>().sqrt();
    scaled.map(|x| x / norm)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sine_is_the_angles_at_every_scale() {
        // Axes at 30° in the xy plane, at lengths from 1e-150 to 1e150: sin = 1/2.
        for scale in [1e-150, 1e-3, 1.0, 1e3, 1e150] {
            let (s, c) = 30f64.to_radians().sin_cos();
            let ok = check_universal_axes("u", [scale, 0.0, 0.0], [c * scale, s * scale, 0.0]);
            assert_eq!(ok, Ok(()), "scale {scale}");
        }
        let near = check_universal_axes("u", [1.0, 0.0, 0.0], [1.0, 1e-9, 0.0]);
        assert!(
            matches!(near, Err(MechanismError::ParallelAxes { sine, .. }) if (sine - 1e-9).abs() < 1e-20),
            "{near:?}"
        );
        assert_eq!(
            check_universal_axes("u", [1.0, 0.0, 0.0], [1.0, 1e-7, 0.0]),
            Ok(())
        );
    }

    #[test]
    fn axes_without_a_direction_are_refused_with_their_cause() {
        let tiny = check_axis("j", "axis", [1e-160, 0.0, 0.0]);
        assert!(
            matches!(tiny, Err(MechanismError::ZeroAxis { squared_length: Some(v), .. }) if v < f64::MIN_POSITIVE)
        );
        let huge = check_axis("j", "axis", [1e200, 0.0, 0.0]);
        assert!(
            matches!(huge, Err(MechanismError::ZeroAxis { squared_length: Some(v), .. }) if v == f64::INFINITY)
        );
        let nan = check_universal_axes("j", [1.0, 0.0, 0.0], [0.0, f64::NAN, 0.0]);
        assert!(
            matches!(&nan, Err(MechanismError::NonFiniteParameter { owner, quantity, value })
                if owner == "joint `j`" && quantity == "axes[1][1]" && value.is_nan()),
            "{nan:?}"
        );
    }
}
