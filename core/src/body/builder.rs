//! Bodies built at run time: the same description and physics the derive macro uses, with
//! `f64` values.

use nalgebra::{Matrix3, Vector3};

use super::error::BodyError;
use super::mass::MassProperties;
use super::orientation::Orientation;
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

    /// Adds `shape` at `at` (its centre; a cone's base centre), its axes along the
    /// description axes. `at` is a `Vector3` or `[x, y, z]`.
    pub fn part(mut self, shape: Shape<f64>, at: impl Into<Vector3<f64>>) -> BodyBuilder {
        self.description.parts.push(Part::new(shape, array(at)));
        self
    }

    /// Adds `shape` at `at`, turned about `at` by `orientation`: an [`Orientation`], or a
    /// nalgebra `Rotation3`, `UnitQuaternion` or `Matrix3` (part axes → description axes).
    /// Its tensor about its centre becomes R I Rᵀ.
    ///
    /// ```
    /// use approx::assert_relative_eq;
    /// use precess_core::body::{Axis, BodyBuilder, Orientation, RigidBody, Shape};
    /// let rod = Shape::Rod { mass: 3.0, length: 2.0, axis: Axis::Z };
    /// let ball = Shape::Sphere { mass: 1.0, radius: 0.1 };
    /// // A rod along z turned a quarter turn about y lies along x: no moment about x.
    /// let quarter = Orientation::axis_angle([0.0, 1.0, 0.0], std::f64::consts::FRAC_PI_2);
    /// let body = BodyBuilder::new()
    ///     .rotated_part(rod, [0.0, 0.0, 0.0], quarter)
    ///     .part(ball, [0.0, 0.0, 0.0])
    ///     .build()
    ///     .unwrap();
    /// let i = body.inertia();
    /// let ball_moment = 0.4 * 0.01;
    /// assert_relative_eq!(i[(0, 0)], ball_moment, max_relative = 1e-12);
    /// assert_relative_eq!(i[(1, 1)], 1.0 + ball_moment, max_relative = 1e-15);
    /// assert_relative_eq!(i[(2, 2)], 1.0 + ball_moment, max_relative = 1e-15);
    /// ```
    pub fn rotated_part(
        mut self,
        shape: Shape<f64>,
        at: impl Into<Vector3<f64>>,
        orientation: impl Into<Orientation<f64>>,
    ) -> BodyBuilder {
        let part = Part::new(shape, array(at)).rotated(orientation.into());
        self.description.parts.push(part);
        self
    }

    /// Declares the pivot, the fixed point the body turns about (a `Vector3` or `[x, y, z]`).
    pub fn pivot(mut self, pivot: impl Into<Vector3<f64>>) -> BodyBuilder {
        self.description.pivot = Some(array(pivot));
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

/// The description stores points as arrays, as the symbolic one does.
fn array(v: impl Into<Vector3<f64>>) -> [f64; 3] {
    let v = v.into();
    [v.x, v.y, v.z]
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
