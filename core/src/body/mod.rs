//! Rigid bodies: the description language, inertia tensors, the principal frame and Euler's
//! equations.
//!
//! A body is a [`Description`]: [`Part`]s (a [`Shape`] placed at a point, at any
//! [`Orientation`]) and an optional pivot. The physics is written once over an [`Algebra`], so the same code computes
//! - at run time, with `f64` values: [`BodyBuilder`] → [`Body`];
//! - in the derive macro, with symbolic values in an [`Arena`](crate::sym::Arena):
//!   [`SymbolicBody`], whose constants fold exactly and whose parameters stay symbols.
//!
//! Both implement (or generate) [`RigidBody`]. Conventions (SI, right-handed, principal
//! frame closest to the description axes) are in `docs/bodies.md`.

mod algebra;
mod builder;
mod error;
mod mass;
mod orientation;
mod principal;
mod rigid;
mod shape;
mod symbolic;
mod validate;

pub use algebra::{Algebra, Numeric};
pub use builder::{Body, BodyBuilder};
pub use error::BodyError;
pub use mass::{MassProperties, Tensor, mass_properties, point_tensor};
pub use nalgebra::{Matrix3, Rotation3, Vector3};
pub use orientation::{Orientation, rotate_tensor, rotate_vector, rotation_matrix};
pub use principal::{Principal, principal_frame};
pub use rigid::{RigidBody, euler_rhs_diagonal};
pub use shape::{About, Axis, ClosedForm, Description, Part, Shape, closed_form};
pub use symbolic::{Frame, SymbolicBody, evaluate};
pub use validate::{
    Definiteness, INERTIA_TOLERANCE, ORTHONORMAL_TOLERANCE, check_inertia, check_orientation,
    check_part, matrix,
};
