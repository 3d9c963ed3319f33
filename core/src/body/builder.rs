//! Bodies built at run time: the same description and physics the derive macro uses, with
//! `f64` values.

use nalgebra::{Matrix3, Vector3};

use super::error::BodyError;
use super::mass::MassProperties;
use super::principal::Principal;
use super::rigid::RigidBody;
use super::shape::{Description, Part, Shape};
use super::validate::matrix;

/// Builds a [`Body`] part by part.
///
/// ```
/// use approx::assert_relative_eq;
/// use precess_core::body::{Axis, BodyBuilder, RigidBody, Shape};
/// let top = BodyBuilder::new()
///     .part(Shape::Cylinder { mass: 2.0, radius: 0.1, length: 0.4, axis: Axis::Z }, [0.0, 0.0, 0.2])
///     .pivot([0.0, 0.0, 0.0])
///     .build()
///     .unwrap();
/// // I3 = ½ m r²; I1 = m (3 r² + L²)/12 + m (L/2)².
/// assert_relative_eq!(top.principal().moments[2], 0.01, max_relative = 1e-15);
/// assert_relative_eq!(top.principal().moments[0], 0.005 + 0.08 / 3.0 + 0.08, max_relative = 1e-15);
/// ```
#[derive(Clone, Debug, Default)]
pub struct BodyBuilder {
    description: Description<f64>,
}

impl BodyBuilder {
    /// An empty body.
    pub fn new() -> BodyBuilder {
        BodyBuilder {
            description: Description {
                parts: Vec::new(),
                pivot: None,
            },
        }
    }

    /// Adds `shape` at `at` (its centre; a cone's base centre).
    pub fn part(mut self, shape: Shape<f64>, at: [f64; 3]) -> BodyBuilder {
        self.description.parts.push(Part { shape, at });
        self
    }

    /// Declares the pivot, the fixed point the body turns about.
    pub fn pivot(mut self, pivot: [f64; 3]) -> BodyBuilder {
        self.description.pivot = Some(pivot);
        self
    }

    /// The description so far.
    pub fn description(&self) -> &Description<f64> {
        &self.description
    }

    /// Validates the description and computes the body.
    ///
    /// # Errors
    /// The first rule broken, see [`BodyError`].
    pub fn build(self) -> Result<Body, BodyError> {
        Body::new(self.description)
    }
}

/// A body computed at run time: its mass properties, principal frame, and the coefficients of
/// Euler's equations.
#[derive(Clone, Debug)]
pub struct Body {
    description: Description<f64>,
    props: MassProperties<f64>,
    principal: Principal,
    coefficients: Vector3<f64>,
    inverse: Vector3<f64>,
}

impl Body {
    /// Validates `description` and computes the body.
    ///
    /// # Errors
    /// The first rule broken, see [`BodyError`].
    pub fn new(description: Description<f64>) -> Result<Body, BodyError> {
        let (props, principal) = description.analyse()?;
        let m = principal.moments;
        Ok(Body {
            description,
            props,
            principal,
            coefficients: principal.euler_coefficients(),
            inverse: Vector3::new(1.0 / m[0], 1.0 / m[1], 1.0 / m[2]),
        })
    }

    /// The description the body was built from.
    pub fn description(&self) -> &Description<f64> {
        &self.description
    }

    /// The mass properties as computed.
    pub fn properties(&self) -> &MassProperties<f64> {
        &self.props
    }
}

impl RigidBody for Body {
    fn description(&self) -> Description<f64> {
        self.description.clone()
    }
    fn mass(&self) -> f64 {
        self.props.mass
    }
    fn center_of_mass(&self) -> Vector3<f64> {
        Vector3::from(self.props.center)
    }
    fn reference_point(&self) -> Vector3<f64> {
        Vector3::from(self.props.reference)
    }
    fn inertia(&self) -> Matrix3<f64> {
        matrix(&self.props.inertia)
    }
    fn inertia_cm(&self) -> Matrix3<f64> {
        matrix(&self.props.inertia_cm)
    }
    fn principal(&self) -> Principal {
        self.principal
    }
    fn euler_rhs_principal(&self, w: &Vector3<f64>, g: &Vector3<f64>) -> Vector3<f64> {
        let (k, d) = (&self.coefficients, &self.inverse);
        Vector3::new(
            k[0] * w[1] * w[2] + d[0] * g[0],
            k[1] * w[2] * w[0] + d[1] * g[1],
            k[2] * w[0] * w[1] + d[2] * g[2],
        )
    }
}
