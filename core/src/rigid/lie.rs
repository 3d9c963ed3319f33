//! Lie-group structure of the rigid-body states: SO(3) × ℝᵏ acted on by its algebra through
//! y · exp(u), and the vector fields of the attitude and rigid-body models on it.

use nalgebra::Vector3;

use super::kinematics::rotate_body;
use super::state::{
    Attitude, AttitudeModel, RigidBodyModel, RigidState, check_attitude, check_rigid,
};
use crate::body::euler_rhs_diagonal;
use crate::ode::{OdeError, check_inertia};

/// An element of the algebra so(3) × ℝᵏ: a rotation part plus a vector part.
pub trait Tangent: Copy {
    /// The zero element.
    fn zero() -> Self;
    /// self += a · x.
    fn axpy(&mut self, a: f64, x: &Self);
    /// The so(3) part as a body rotation vector.
    fn rot(&self) -> Vector3<f64>;
    /// Replaces the so(3) part.
    fn set_rot(&mut self, r: Vector3<f64>);
}

/// A state on SO(3) × ℝᵏ acted on by its algebra through y · exp(u).
pub trait LieState: Copy {
    /// The algebra.
    type Tangent: Tangent;
    /// y · exp(u): the rotation part by the exponential map, the vector part by addition.
    fn exp_act(&self, u: &Self::Tangent) -> Self;
    /// Checks the initial data.
    ///
    /// # Errors
    /// [`OdeError::NonFiniteInitialState`].
    fn check(&self) -> Result<(), OdeError>;
}

/// A vector field on a [`LieState`]: ξ(t, y) with ẏ = y · ξ.
pub trait LieSystem<Y: LieState> {
    /// The generator at (t, y).
    fn xi(&self, t: f64, y: &Y) -> Y::Tangent;
    /// Checks the model's parameters (inertia, mass).
    ///
    /// # Errors
    /// [`OdeError::InvalidInertia`].
    fn check(&self) -> Result<(), OdeError>;
}

/// [`Tangent`] for an algebra element made of `Vector3` fields, one of them `rot` (the so(3)
/// part): the algebra is ℝ³ᵏ, so zero and a·x + y act field by field. One definition for
/// every state's tangent.
macro_rules! vector_tangent {
    ($tangent:ident { $($field:ident),+ }) => {
        impl Tangent for $tangent {
            fn zero() -> Self {
                Self { $($field: Vector3::zeros()),+ }
            }
            fn axpy(&mut self, a: f64, x: &Self) {
                $(self.$field += a * x.$field;)+
            }
            fn rot(&self) -> Vector3<f64> {
                self.rot
            }
            fn set_rot(&mut self, r: Vector3<f64>) {
                self.rot = r;
            }
        }
    };
}

/// Algebra of [`Attitude`]: (body rotation, ω̇).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AttitudeTangent {
    /// Rotation part (body axes).
    pub rot: Vector3<f64>,
    /// Rate of ω.
    pub domega: Vector3<f64>,
}

vector_tangent!(AttitudeTangent { rot, domega });

impl LieState for Attitude {
    type Tangent = AttitudeTangent;
    fn exp_act(&self, u: &AttitudeTangent) -> Self {
        Attitude {
            q: rotate_body(&self.q, &u.rot),
            omega: self.omega + u.domega,
        }
    }
    fn check(&self) -> Result<(), OdeError> {
        check_attitude(self)
    }
}

impl<M: AttitudeModel> LieSystem<Attitude> for M {
    fn xi(&self, t: f64, y: &Attitude) -> AttitudeTangent {
        AttitudeTangent {
            rot: y.omega,
            domega: euler_rhs_diagonal(&self.inertia().into(), &y.omega, &self.torque(t, y)),
        }
    }
    fn check(&self) -> Result<(), OdeError> {
        check_inertia(1.0, self.inertia())
    }
}

/// Algebra of [`RigidState`]: (ẋ, v̇, body rotation, ω̇).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidTangent {
    /// Rate of the centre of mass.
    pub dx: Vector3<f64>,
    /// Acceleration of the centre of mass.
    pub dv: Vector3<f64>,
    /// Rotation part (body axes).
    pub rot: Vector3<f64>,
    /// Rate of ω.
    pub domega: Vector3<f64>,
}

vector_tangent!(RigidTangent {
    dx,
    dv,
    rot,
    domega
});

impl LieState for RigidState {
    type Tangent = RigidTangent;
    fn exp_act(&self, u: &RigidTangent) -> Self {
        RigidState {
            x: self.x + u.dx,
            v: self.v + u.dv,
            q: rotate_body(&self.q, &u.rot),
            omega: self.omega + u.domega,
        }
    }
    fn check(&self) -> Result<(), OdeError> {
        check_rigid(self)
    }
}

impl<M: RigidBodyModel> LieSystem<RigidState> for M {
    fn xi(&self, t: f64, y: &RigidState) -> RigidTangent {
        RigidTangent {
            dx: y.v,
            dv: self.force(t, y) / self.mass(),
            rot: y.omega,
            domega: euler_rhs_diagonal(&self.inertia().into(), &y.omega, &self.torque(t, y)),
        }
    }
    fn check(&self) -> Result<(), OdeError> {
        check_inertia(self.mass(), self.inertia())
    }
}
