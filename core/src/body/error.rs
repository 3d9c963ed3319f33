//! Why a body description is rejected.

use thiserror::Error;

/// A body description that does not describe a physical rigid body.
///
/// Parts are numbered from 0 in the order given; `kind` is the part's name in the attribute
/// language and `key` the offending key, so the derive macro can point at the tokens.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum BodyError {
    /// The description has no part.
    #[error("a body needs at least one part")]
    NoParts,
    /// A value is NaN or infinite.
    #[error("part {part} ({kind}): `{key}` is {value}, but values must be finite")]
    NonFinite {
        /// Index of the part.
        part: usize,
        /// The part's name.
        kind: &'static str,
        /// The key.
        key: &'static str,
        /// The value.
        value: f64,
    },
    /// The pivot has a NaN or infinite coordinate.
    #[error("the pivot coordinate {value} is not finite")]
    NonFinitePivot {
        /// The coordinate.
        value: f64,
    },
    /// A mass that is zero or negative.
    #[error("part {part} ({kind}): mass must be positive, got {value}")]
    NonPositiveMass {
        /// Index of the part.
        part: usize,
        /// The part's name.
        kind: &'static str,
        /// The mass.
        value: f64,
    },
    /// A length or radius that is zero or negative.
    #[error("part {part} ({kind}): `{key}` must be positive, got {value}")]
    NonPositiveDimension {
        /// Index of the part.
        part: usize,
        /// The part's name.
        kind: &'static str,
        /// The key.
        key: &'static str,
        /// The value.
        value: f64,
    },
    /// A tube whose inner radius is negative or not below its outer radius.
    #[error(
        "part {part} (tube): the inner radius {inner} must satisfy 0 ≤ inner < outer = {outer}"
    )]
    TubeRadii {
        /// Index of the part.
        part: usize,
        /// Inner radius.
        inner: f64,
        /// Outer radius.
        outer: f64,
    },
    /// An explicit tensor with `I[row][col] ≠ I[col][row]`.
    #[error(
        "part {part} (body): the inertia tensor must be symmetric, but I[{row}][{col}] = {upper} and I[{col}][{row}] = {lower}"
    )]
    NotSymmetric {
        /// Index of the part.
        part: usize,
        /// Row of the upper entry.
        row: usize,
        /// Column of the upper entry.
        col: usize,
        /// `I[row][col]`.
        upper: f64,
        /// `I[col][row]`.
        lower: f64,
    },
    /// An explicit tensor with a principal moment ≤ 0.
    #[error(
        "part {part} (body): the inertia tensor must be positive definite, but its principal moments are {moments:?}"
    )]
    NotPositiveDefinite {
        /// Index of the part.
        part: usize,
        /// Its principal moments, ascending.
        moments: [f64; 3],
    },
    /// An explicit tensor whose principal moments break I1 + I2 ≥ I3.
    #[error(
        "part {part} (body): principal moments {moments:?} break the triangle inequality I1 + I2 ≥ I3 that every mass distribution satisfies"
    )]
    TriangleInequality {
        /// Index of the part.
        part: usize,
        /// Its principal moments, ascending.
        moments: [f64; 3],
    },
    /// An axis–angle rotation whose axis has no direction: zero, or with a squared length
    /// outside the normal range of `f64`, so that it cannot be normalised.
    #[error(
        "part {part} ({kind}): the rotation axis {axis:?} has no direction: give a non-zero axis such as [0.0, 0.0, 1.0] (its squared length must lie between 2.2e-308 and 1.8e308)"
    )]
    ZeroRotationAxis {
        /// Index of the part.
        part: usize,
        /// The part's name.
        kind: &'static str,
        /// The axis as given.
        axis: [f64; 3],
    },
    /// A rotation matrix whose rows are not orthonormal: RᵀR differs from the identity.
    #[error(
        "part {part} ({kind}): the matrix is not a rotation: its columns are not orthonormal, |RᵀR − E| reaches {deviation:e} (at most 1e-9 is allowed)"
    )]
    NotOrthonormal {
        /// Index of the part.
        part: usize,
        /// The part's name.
        kind: &'static str,
        /// The largest entry of |RᵀR − E|.
        deviation: f64,
    },
    /// An orthonormal matrix with det = −1: a reflection, which turns a right-handed part
    /// into its mirror image.
    #[error(
        "part {part} ({kind}): the matrix is a reflection (det = {determinant}), not a rotation: a rotation has det = +1; negate one column, or swap two"
    )]
    ImproperRotation {
        /// Index of the part.
        part: usize,
        /// The part's name.
        kind: &'static str,
        /// det R.
        determinant: f64,
    },
    /// An explicit tensor given about the pivot, in a description without one.
    #[error("part {part} (body): the tensor is given about the pivot, but no pivot is declared")]
    PivotRequired {
        /// Index of the part.
        part: usize,
    },
    /// The masses add up to zero.
    #[error("the total mass is zero")]
    ZeroTotalMass,
    /// A mass property of a body whose values are all finite is not: it overflows `f64`
    /// (NaN here comes from ∞ − ∞ or 0 · ∞ in the sums).
    #[error(
        "the {quantity} overflows f64 (it evaluates to {value}): the body's values are too large for f64, whose largest finite value is about 1.8e308; express them in larger units"
    )]
    Overflow {
        /// What overflows, e.g. "inertia tensor about the reference point".
        quantity: &'static str,
        /// Its first non-finite value.
        value: f64,
    },
    /// The principal moments underflow `f64`: the body is so light and small that m l² falls
    /// below the smallest normal `f64`, where digits are lost and 1/I can overflow.
    #[error(
        "the principal moments {moments:?} underflow f64: the body's values are too small for f64, whose smallest normal value is about 2.2e-308; express them in smaller units"
    )]
    Underflow {
        /// The principal moments about the reference point, ascending.
        moments: [f64; 3],
    },
    /// A body with parameters whose moment about a description axis is identically zero:
    /// zero whatever values the parameters take.
    #[error(
        "the body's moment about the {axis} axis is zero whatever its parameters: all its mass lies on a line through the reference point"
    )]
    IdenticallyZeroMoment {
        /// The description axis, `x`, `y` or `z`.
        axis: &'static str,
    },
    /// The whole body has a zero principal moment about its reference point: all its mass
    /// lies on a line through it, and Euler's equations divide by that moment.
    #[error(
        "the body has a zero principal moment (moments {moments:?}): all its mass lies on a line through the reference point"
    )]
    ZeroPrincipalMoment {
        /// The principal moments about the reference point, ascending.
        moments: [f64; 3],
    },
}
