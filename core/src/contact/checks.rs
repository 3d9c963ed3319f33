//! The run-time checks of a body on a table, written once for every implementation of
//! `ContactDynamics` (whose default methods call them with what they read of the body): a
//! state's finiteness, quaternion, placeable contact and rolling constraint, and the
//! parameter values' rules.

use nalgebra::Vector3;

use super::error::ContactError;
use super::scene::{LawKind, Phase};
use super::state::{STATE_LEN, attitude_of, layout};
use super::surface::SurfaceKind;
use crate::body::{Definiteness, check_inertia};

/// How far |q| may be from 1 in a state handed in.
pub const QUATERNION_TOLERANCE: f64 = 1e-9;

/// The one flatness limit of every rolling surface, shared with a mechanism's wheels
/// ([`crate::rigid::MIN_TILT`], where its value is argued).
pub use crate::rigid::MIN_TILT;

/// The slip a rolling state may have, relative to |ω| |r| + |v|.
pub const ROLLING_TOLERANCE: f64 = 1e-9;

/// The law derives `phase`'s equations.
///
/// # Errors
/// [`ContactError::PhaseNotDerived`].
pub(crate) fn check_law(law: LawKind, phase: Phase) -> Result<(), ContactError> {
    if law.has(phase) {
        Ok(())
    } else {
        Err(ContactError::PhaseNotDerived {
            phase,
            law: law.name(),
        })
    }
}

/// The attitude quaternion is a unit one, within [`QUATERNION_TOLERANCE`].
///
/// # Errors
/// [`ContactError::BadQuaternion`].
pub(crate) fn check_quaternion(y: &[f64; STATE_LEN]) -> Result<(), ContactError> {
    let at = layout::QUATERNION;
    let quaternion = [y[at], y[at + 1], y[at + 2], y[at + 3]];
    let norm = quaternion.iter().map(|c| c * c).sum::<f64>().sqrt();
    if (norm - 1.0).abs() > QUATERNION_TOLERANCE {
        return Err(ContactError::BadQuaternion {
            quaternion,
            norm,
            tolerance: QUATERNION_TOLERANCE,
        });
    }
    Ok(())
}

/// A rolling state does not slip: `velocity` is the contact point's velocity from the state
/// and `arm` the vector r from the centre of mass to the contact, body axes (the contact
/// point of the body's support map at `y`).
///
/// # Errors
/// [`ContactError::RollingConstraint`], for a NaN slip too (a contact the map could not
/// place).
pub(crate) fn check_rolling(
    y: &[f64; STATE_LEN],
    velocity: &Vector3<f64>,
    arm: &Vector3<f64>,
) -> Result<(), ContactError> {
    // The contact velocity from the state is v_state + R(ω × r) horizontally: zero when the
    // state rolls.
    let state_velocity = [y[layout::VELOCITY], y[layout::VELOCITY + 1]];
    let rolling = [
        state_velocity[0] - velocity.x,
        state_velocity[1] - velocity.y,
    ];
    let slip = velocity.x.hypot(velocity.y);
    let omega = Vector3::new(y[layout::OMEGA], y[layout::OMEGA + 1], y[layout::OMEGA + 2]);
    let scale = omega.norm() * arm.norm() + state_velocity[0].hypot(state_velocity[1]);
    let tolerance = (ROLLING_TOLERANCE * scale).max(1e-12);
    if slip.is_nan() || slip > tolerance {
        return Err(ContactError::RollingConstraint {
            velocity: state_velocity,
            rolling,
            slip,
            tolerance,
        });
    }
    Ok(())
}

/// Every part of `y` finite.
///
/// # Errors
/// [`ContactError::NonFinite`] naming the first part that is not.
pub(crate) fn check_finite_parts(y: &[f64; STATE_LEN]) -> Result<(), ContactError> {
    let parts: [(&'static str, usize, usize); 4] = [
        ("position", layout::POSITION, 2),
        ("velocity", layout::VELOCITY, 2),
        ("attitude quaternion", layout::QUATERNION, 4),
        ("omega", layout::OMEGA, 3),
    ];
    for (quantity, at, len) in parts {
        let values = &y[at..at + len];
        if values.iter().any(|v| !v.is_finite()) {
            return Err(ContactError::NonFinite {
                quantity,
                values: values.to_vec(),
            });
        }
    }
    Ok(())
}

/// Whether the support map can place the contact at `y`'s attitude: a disk rim or torus not
/// lying flat, a paraboloid whose bowl faces the table.
///
/// # Errors
/// [`ContactError::FlatDisk`], [`ContactError::PastParaboloidRim`].
pub(crate) fn check_placement(
    surface: SurfaceKind,
    y: &[f64; STATE_LEN],
) -> Result<(), ContactError> {
    let gamma = attitude_of(y).inverse_transform_vector(&Vector3::z());
    match surface {
        kind @ (SurfaceKind::DiskRim | SurfaceKind::Torus) => {
            let tilt = gamma.x.hypot(gamma.y).min(1.0).asin();
            if tilt < MIN_TILT {
                return Err(ContactError::FlatDisk {
                    surface: kind.name(),
                    tilt,
                    minimum: MIN_TILT,
                });
            }
        }
        SurfaceKind::Paraboloid if gamma.z <= 0.0 => {
            return Err(ContactError::PastParaboloidRim {
                n3: -gamma.z,
                maximum: 0.0,
            });
        }
        _ => {}
    }
    Ok(())
}

/// The numbers a contact scene's rules are checked on: what an implementation of
/// [`ContactDynamics::check_parameters`] gathers from its parameters (the interpreted model
/// from its bindings, `#[contact(...)]` from the struct's fields) and hands to
/// [`ContactValues::check`].
///
/// [`ContactDynamics::check_parameters`]: crate::contact::ContactDynamics::check_parameters
#[derive(Clone, Debug, PartialEq)]
pub struct ContactValues {
    /// The mass M.
    pub mass: f64,
    /// The centre of mass, description axes.
    pub center: [f64; 3],
    /// The inertia about the centre of mass, description axes.
    pub inertia: [[f64; 3]; 3],
    /// Gravity g (along −z).
    pub gravity: f64,
    /// The surface's kind.
    pub surface: SurfaceKind,
    /// The surface's centre (vertex of a paraboloid).
    pub placement: [f64; 3],
    /// The surface's lengths by name, in [`super::Surface::dimensions`] order.
    pub lengths: Vec<(&'static str, f64)>,
    /// The law's coefficients by name (`mu`, `viscous`, `rolling_resistance`,
    /// `spin_resistance`).
    pub coefficients: Vec<(&'static str, f64)>,
}

impl ContactValues {
    /// Checks the rules of [`ContactDynamics::check_parameters`].
    ///
    /// # Errors
    /// As [`ContactDynamics::check_parameters`].
    ///
    /// [`ContactDynamics::check_parameters`]: crate::contact::ContactDynamics::check_parameters
    pub fn check(&self) -> Result<(), ContactError> {
        check_values(self)
    }
}

/// As `ContactDynamics::check_parameters`, on the values.
fn check_values(v: &ContactValues) -> Result<(), ContactError> {
    if !(v.mass.is_finite() && v.mass > 0.0) {
        return Err(ContactError::BadParameter {
            name: "mass",
            value: v.mass,
            rule: "finite and > 0",
        });
    }
    if !(v.gravity.is_finite() && v.gravity >= 0.0) {
        return Err(ContactError::BadParameter {
            name: "gravity",
            value: v.gravity,
            rule: "finite and ≥ 0 (it points along −z)",
        });
    }
    check_inertia(0, &v.inertia, Definiteness::Positive)?;
    for &(name, value) in &v.coefficients {
        if !(value.is_finite() && value >= 0.0) {
            return Err(ContactError::NegativeCoefficient { name, value });
        }
    }
    let surface = v.surface.name();
    for &(name, value) in &v.lengths {
        if !(value.is_finite() && value > 0.0) {
            return Err(ContactError::BadSurface {
                surface,
                name,
                value,
                rule: "finite and > 0",
            });
        }
    }
    if let (SurfaceKind::Torus, [(_, big), (_, tube)]) = (v.surface, v.lengths.as_slice())
        && tube > big
    {
        return Err(ContactError::BadSurface {
            surface,
            name: "tube",
            value: *tube,
            rule: "at most the radius of the centre line (a larger tube makes the torus cross itself)",
        });
    }
    let measure = inside_measure(v);
    if measure.is_nan() || measure >= 1.0 {
        return Err(ContactError::CenterOutsideSurface {
            surface,
            center: v.center,
            measure,
        });
    }
    Ok(())
}

/// The surface's implicit measure at the centre of mass: < 1 strictly inside its convex
/// hull, 1 on it (for a disk rim: the distance from the axis over the radius).
fn inside_measure(v: &ContactValues) -> f64 {
    let d = Vector3::from(v.center) - Vector3::from(v.placement);
    let len = |k: usize| v.lengths.get(k).map_or(f64::NAN, |&(_, l)| l);
    match v.surface {
        SurfaceKind::Sphere => d.norm() / len(0),
        SurfaceKind::Ellipsoid => Vector3::new(d.x / len(0), d.y / len(1), d.z / len(2)).norm(),
        SurfaceKind::DiskRim => d.x.hypot(d.y) / len(0),
        SurfaceKind::Torus => {
            let (big, tube) = (len(0), len(1));
            let across = (tube * tube - d.z * d.z).max(0.0).sqrt();
            (d.z.abs() / tube).max(d.x.hypot(d.y) / (big + across))
        }
        SurfaceKind::Paraboloid => {
            let rise = d.x.hypot(d.y).powi(2) / (2.0 * len(0));
            if d.z > 0.0 { rise / d.z } else { f64::INFINITY }
        }
    }
}
