//! Validation of a numeric description: one function per rule, the reason in its doc line.
//! The derive macro runs the same rules at compile time on literal bodies, and the code it
//! generates for parametric bodies runs them at run time through `RigidBody::validate`.

use nalgebra::Matrix3;

use super::algebra::Numeric;
use super::error::BodyError;
use super::mass::{MassProperties, mass_properties};
use super::orientation::Orientation;
use super::principal::{Principal, principal_frame};
use super::shape::{Description, Part, Shape};

/// Relative tolerance of the tensor checks (symmetry, definiteness, triangle inequality),
/// relative to the largest entry |I_ij| of the tensor checked ([`check_inertia`]).
pub const INERTIA_TOLERANCE: f64 = 1e-12;
const TOL: f64 = INERTIA_TOLERANCE;

/// How far a rotation matrix's RᵀR may be from the identity, entry by entry: loose enough
/// for a matrix written with 10 digits or computed in `f64`, tight enough that the tensor it
/// turns is off by no more than about this much, relative.
pub const ORTHONORMAL_TOLERANCE: f64 = 1e-9;

impl Description<f64> {
    /// Checks every rule, then computes the mass properties and the principal frame about
    /// the reference point.
    ///
    /// # Errors
    /// The first rule broken, as a [`BodyError`] carrying the numbers.
    pub fn analyse(&self) -> Result<(MassProperties<f64>, Principal), BodyError> {
        for (index, part) in self.parts.iter().enumerate() {
            check_part(index, part)?;
        }
        if let Some(p) = &self.pivot {
            finite_pivot(p)?;
        }
        let props = mass_properties(&mut Numeric, self)?;
        // Finite values must give finite mass properties: anything else is an overflow of f64
        // (say so, rather than let ∞ reach the moment checks and pass for a zero moment).
        props.check_finite(|v| v)?;
        let principal = principal_frame(&matrix(&props.inertia));
        normal_moments(self, &principal)?;
        no_zero_moment(&principal)?;
        Ok((props, principal))
    }

    /// Checks every rule (see [`Description::analyse`]).
    ///
    /// # Errors
    /// The first rule broken.
    pub fn validate(&self) -> Result<(), BodyError> {
        self.analyse().map(|_| ())
    }
}

/// A tensor as rows to a nalgebra matrix.
pub fn matrix(t: &[[f64; 3]; 3]) -> Matrix3<f64> {
    Matrix3::from_fn(|i, j| t[i][j])
}

/// Checks one part: finite values, positive mass and dimensions, a consistent tube, and a
/// physical explicit tensor.
///
/// # Errors
/// The first rule the part breaks.
pub fn check_part(index: usize, part: &Part<f64>) -> Result<(), BodyError> {
    let kind = part.shape.kind();
    let mass = *part.shape.mass();
    finite(index, kind, "mass", mass)?;
    for &(key, &value) in &part.shape.dimensions() {
        finite(index, kind, key, value)?;
    }
    for &x in &part.at {
        finite(index, kind, "at", x)?;
    }
    // A mass must be positive: a zero or negative mass has no inertia to speak of.
    if mass.is_nan() || mass <= 0.0 {
        return Err(BodyError::NonPositiveMass {
            part: index,
            kind,
            value: mass,
        });
    }
    // Lengths and radii must be positive: a zero one degenerates the solid.
    for (key, &value) in part.shape.dimensions() {
        if value <= 0.0 {
            return Err(BodyError::NonPositiveDimension {
                part: index,
                kind,
                key,
                value,
            });
        }
    }
    match &part.shape {
        Shape::Tube { inner, outer, .. } => {
            finite(index, kind, "inner", *inner)?;
            // The hole must fit inside the tube (inner 0 is a solid cylinder).
            if !(*inner >= 0.0 && inner < outer) {
                return Err(BodyError::TubeRadii {
                    part: index,
                    inner: *inner,
                    outer: *outer,
                });
            }
        }
        Shape::Explicit { inertia, .. } => check_inertia(index, inertia, Definiteness::Positive)?,
        _ => {}
    }
    if let Some(o) = &part.orientation {
        check_orientation(index, kind, o)?;
    }
    Ok(())
}

/// Checks a part's rotation: finite values, an axis with a direction, and a matrix that is a
/// rotation (orthonormal to [`ORTHONORMAL_TOLERANCE`], det = +1).
///
/// # Errors
/// [`BodyError::NonFinite`] (key `rotate`), [`BodyError::ZeroRotationAxis`],
/// [`BodyError::NotOrthonormal`] or [`BodyError::ImproperRotation`].
pub fn check_orientation(
    part: usize,
    kind: &'static str,
    o: &Orientation<f64>,
) -> Result<(), BodyError> {
    for &value in o.values() {
        finite(part, kind, "rotate", value)?;
    }
    match o {
        Orientation::AxisAngle { axis, .. } => {
            // The axis is normalised by |k|² and |k|: both must be normal, non-zero f64.
            let norm2: f64 = axis.iter().map(|k| k * k).sum();
            if !(norm2 >= f64::MIN_POSITIVE && norm2.is_finite()) {
                return Err(BodyError::ZeroRotationAxis {
                    part,
                    kind,
                    axis: *axis,
                });
            }
        }
        Orientation::Matrix(rows) => {
            // A non-orthonormal matrix stretches the part: R I Rᵀ is then not its tensor.
            let r = matrix(rows);
            let gram = r.transpose() * r - Matrix3::identity();
            // The largest |entry|, NaN kept (huge entries give ∞ − ∞).
            let deviation = gram.iter().fold(0.0f64, |m, x| {
                if x.is_nan() || x.abs() > m {
                    x.abs()
                } else {
                    m
                }
            });
            if deviation.is_nan() || deviation > ORTHONORMAL_TOLERANCE {
                return Err(BodyError::NotOrthonormal {
                    part,
                    kind,
                    deviation,
                });
            }
            // det = −1 mirrors the part: a cone's apex or a box's handedness would flip.
            let determinant = r.determinant();
            if determinant < 0.0 {
                return Err(BodyError::ImproperRotation {
                    part,
                    kind,
                    determinant,
                });
            }
        }
        // Any finite angles make a rotation.
        Orientation::Sequence(_) => {}
    }
    Ok(())
}

/// A value must be finite: NaN and ∞ propagate into every result.
fn finite(part: usize, kind: &'static str, key: &'static str, value: f64) -> Result<(), BodyError> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(BodyError::NonFinite {
            part,
            kind,
            key,
            value,
        })
    }
}

/// The pivot must be finite.
fn finite_pivot(p: &[f64; 3]) -> Result<(), BodyError> {
    match p.iter().find(|x| !x.is_finite()) {
        Some(&value) => Err(BodyError::NonFinitePivot { value }),
        None => Ok(()),
    }
}

/// What an inertia tensor checked by [`check_inertia`] may have for its smallest principal
/// moment.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Definiteness {
    /// Every principal moment positive: an explicit part's tensor, which the equations of a
    /// body divide by.
    Positive,
    /// Zero moments allowed: a body's total tensor about its centre, where point masses and
    /// thin rods have them (a body with no inertia at all is the mass matrix's concern).
    SemiPositive,
}

/// The one rule for an inertia tensor, used by every scene (an explicit part of a body's
/// description, a mechanism body's inertia made of parameters): finite, symmetric, its
/// principal moments I1 ≤ I2 ≤ I3 positive (or not negative) and meeting I1 + I2 ≥ I3, each
/// to a relative [`INERTIA_TOLERANCE`] of the largest entry |I_ij|. Every mass distribution's
/// tensor passes (Σ m (r² E − x xᵀ) is symmetric, and I1 + I2 − I3 = 2 Σ m x3² ≥ 0); errors
/// number the part `part`.
///
/// # Errors
/// [`BodyError::NonFinite`] for a NaN or infinite entry, [`BodyError::NotSymmetric`],
/// [`BodyError::NotPositiveDefinite`] for a moment at or below zero (below −tolerance for
/// [`Definiteness::SemiPositive`]), [`BodyError::TriangleInequality`].
///
/// # Examples
///
/// A thin rod's tensor diag(0, 1, 1) is a body's total but no explicit part's:
///
/// ```
/// use precess_core::body::{BodyError, Definiteness, check_inertia};
/// let rod = [[0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// assert_eq!(check_inertia(0, &rod, Definiteness::SemiPositive), Ok(()));
/// assert!(matches!(
///     check_inertia(0, &rod, Definiteness::Positive),
///     Err(BodyError::NotPositiveDefinite { .. })
/// ));
/// ```
pub fn check_inertia(
    part: usize,
    t: &[[f64; 3]; 3],
    definiteness: Definiteness,
) -> Result<(), BodyError> {
    for &v in t.iter().flatten() {
        finite(part, "body", "inertia", v)?;
    }
    let scale = t.iter().flatten().fold(0.0f64, |s, v| s.max(v.abs()));
    let tol = INERTIA_TOLERANCE * scale;
    for (row, col) in [(0, 1), (0, 2), (1, 2)] {
        let (upper, lower) = (t[row][col], t[col][row]);
        if (upper - lower).abs() > tol {
            return Err(BodyError::NotSymmetric {
                part,
                row,
                col,
                upper,
                lower,
            });
        }
    }
    let moments = ascending(&principal_frame(&matrix(t)));
    let definite = match definiteness {
        Definiteness::Positive => moments[0] > tol,
        Definiteness::SemiPositive => moments[0] >= -tol,
    };
    if !definite {
        return Err(BodyError::NotPositiveDefinite { part, moments });
    }
    if moments[0] + moments[1] < moments[2] - tol {
        return Err(BodyError::TriangleInequality { part, moments });
    }
    Ok(())
}

/// The principal moments must be finite and, unless they are truly zero, normal `f64`s:
/// a moment below 2.2e-308 has lost digits to underflow (and 1/I may overflow).
///
/// All moments are exactly zero only when every part is a particle at one point, which is
/// the reference point (then [`no_zero_moment`] says so); a body with extent whose largest
/// moment is below the normal range has underflowed, as has a smallest moment that is not
/// negligible against the largest yet subnormal.
fn normal_moments(d: &Description<f64>, p: &Principal) -> Result<(), BodyError> {
    let moments = ascending(p);
    if let Some(&value) = moments.iter().find(|m| !m.is_finite()) {
        return Err(BodyError::Overflow {
            quantity: "principal moments",
            value,
        });
    }
    let solid = d
        .parts
        .iter()
        .any(|part| !matches!(part.shape, Shape::Particle { .. }));
    let first = d.parts.first().map(|part| part.at);
    let spread = d.parts.iter().any(|part| Some(part.at) != first);
    let off_pivot = d.pivot.is_some() && d.pivot != first;
    let extent = solid || spread || off_pivot;
    let all_underflow = extent && moments[2] < f64::MIN_POSITIVE;
    let smallest_underflows = moments[0] > TOL * moments[2] && moments[0] < f64::MIN_POSITIVE;
    if all_underflow || smallest_underflows {
        return Err(BodyError::Underflow { moments });
    }
    Ok(())
}

/// The body's principal moments about the reference point must all be positive: Euler's
/// equations divide by each (a zero moment means all mass on a line through the point).
fn no_zero_moment(p: &Principal) -> Result<(), BodyError> {
    let moments = ascending(p);
    let positive = moments[0] > TOL * moments[2];
    if !positive {
        return Err(BodyError::ZeroPrincipalMoment { moments });
    }
    Ok(())
}

fn ascending(p: &Principal) -> [f64; 3] {
    let mut m = [p.moments[0], p.moments[1], p.moments[2]];
    m.sort_by(f64::total_cmp);
    m
}
