//! The `RigidBody` trait: what every body, derived or built at run time, provides.

use nalgebra::{Matrix3, Vector3};

use super::error::BodyError;
use super::principal::Principal;
use super::shape::Description;

/// A rigid body's mass properties and its equations of motion.
///
/// Frames: the description frame is the one the body was described in; "reference point" is
/// the pivot if one is declared, else the centre of mass. Every method works in description
/// axes except the one whose name says `_principal`: [`RigidBody::euler_rhs_principal`] takes
/// and returns principal-axis components ([`RigidBody::principal`] gives the rotation between
/// the two). Vectors are [`Vector3`]s, tensors [`Matrix3`]s (see docs/conventions.md).
pub trait RigidBody {
    /// Total mass M.
    fn mass(&self) -> f64;

    /// Centre of mass G, in the description frame.
    fn center_of_mass(&self) -> Vector3<f64>;

    /// The reference point: the pivot if declared, else G.
    fn reference_point(&self) -> Vector3<f64>;

    /// Inertia tensor about the reference point, description axes.
    fn inertia(&self) -> Matrix3<f64>;

    /// Inertia tensor about the centre of mass, description axes.
    fn inertia_cm(&self) -> Matrix3<f64>;

    /// Principal moments about the reference point and the rotation from principal to
    /// description axes (deterministic: closest to the description axes, right-handed).
    fn principal(&self) -> Principal;

    /// Euler's equations in the principal frame: ω̇ with
    /// I1 ω̇1 = (I2 − I3) ω2 ω3 + G1 (and cyclic), for body angular velocity ω and torque G
    /// about the reference point, both in principal axes.
    fn euler_rhs_principal(&self, omega: &Vector3<f64>, torque: &Vector3<f64>) -> Vector3<f64>;

    /// Kinetic energy of rotation about the reference point, ½ ωᵀ I ω (ω in description
    /// axes).
    fn kinetic_energy(&self, omega: &Vector3<f64>) -> f64 {
        0.5 * omega.dot(&(self.inertia() * omega))
    }

    /// Angular momentum about the reference point, I ω (ω in description axes).
    fn angular_momentum(&self, omega: &Vector3<f64>) -> Vector3<f64> {
        self.inertia() * omega
    }

    /// Angular momentum of the freely moving body about any point O:
    /// L_O = J_cm + R × P, with J_cm = I_cm ω, R the centre of mass relative to O and
    /// P = M V the linear momentum (V the velocity of the centre of mass).
    fn angular_momentum_about(
        &self,
        omega: &Vector3<f64>,
        r: &Vector3<f64>,
        v: &Vector3<f64>,
    ) -> Vector3<f64> {
        self.inertia_cm() * omega + r.cross(&(v * self.mass()))
    }

    /// Kinetic energy of the freely moving body, T = T_cm + ½ M V², with
    /// T_cm = ½ ωᵀ I_cm ω and V the velocity of the centre of mass.
    fn kinetic_energy_free(&self, omega: &Vector3<f64>, v: &Vector3<f64>) -> f64 {
        0.5 * omega.dot(&(self.inertia_cm() * omega)) + 0.5 * self.mass() * v.norm_squared()
    }

    /// The body's description with the current values: its parts and pivot. Building a
    /// [`Body`](super::Body) from it precomputes what a parametric body recomputes per call
    /// (for one whose tensor is not diagonal, the principal frame).
    fn description(&self) -> Description<f64>;

    /// Checks the description's rules for the current parameter values (derived bodies of
    /// literals are checked at compile time and return `Ok` at once).
    ///
    /// The body only: each scene checks its own settings (a top's gravity, damping and
    /// torques) with its body, in the `check_all` of the trait its derive implements.
    ///
    /// # Errors
    /// The first rule broken, see [`BodyError`].
    fn validate(&self) -> Result<(), BodyError> {
        self.description().validate()
    }

    /// `self`, if it passes [`RigidBody::validate`]: a checked constructor for parametric
    /// bodies, `Body { m: 1.0, r: 0.1 }.validated()?`.
    ///
    /// # Errors
    /// As [`RigidBody::validate`].
    fn validated(self) -> Result<Self, BodyError>
    where
        Self: Sized,
    {
        self.validate()?;
        Ok(self)
    }
}

/// Euler's equations for principal moments `moments`, the generic form
/// I⁻¹ (G − ω × I ω) with I diagonal.
pub fn euler_rhs_diagonal(
    moments: &Vector3<f64>,
    omega: &Vector3<f64>,
    torque: &Vector3<f64>,
) -> Vector3<f64> {
    let i = moments;
    let w = omega;
    Vector3::new(
        ((i[1] - i[2]) * w[1] * w[2] + torque[0]) / i[0],
        ((i[2] - i[0]) * w[2] * w[0] + torque[1]) / i[1],
        ((i[0] - i[1]) * w[0] * w[1] + torque[2]) / i[2],
    )
}
