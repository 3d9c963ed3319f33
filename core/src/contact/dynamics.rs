//! The trait a derived body on a table implements (the interpreted [`super::ContactModel`]
//! at run time, `#[contact(...)]` at compile time): the right-hand side of each phase of the
//! contact, the reaction, the energy and momenta as straight-line code, with the checked
//! helpers and the runs built on them.

use nalgebra::{UnitQuaternion, Vector3};

use super::checks::{
    ContactValues, check_finite_parts, check_law, check_placement, check_quaternion, check_rolling,
};
use super::error::ContactError;
use super::scene::{LawKind, Phase};
use super::state::{STATE_LEN, layout};
use super::surface::SurfaceKind;

/// The force of the table on the body at the contact point, space axes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reaction {
    /// The normal force N (along +ẑ); a negative value means the body would leave the table.
    pub normal: f64,
    /// The friction force, horizontal.
    pub friction: Vector3<f64>,
}

impl Reaction {
    /// The whole contact force N ẑ + friction.
    pub fn force(&self) -> Vector3<f64> {
        self.friction + Vector3::new(0.0, 0.0, self.normal)
    }
}

/// Where the body touches the table and how the contact point moves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactPoint {
    /// γ = Rᵀ ẑ, the space vertical in body (description) axes.
    pub gamma: Vector3<f64>,
    /// The vector r from the centre of mass to the contact point, body axes.
    pub body: Vector3<f64>,
    /// The contact point in space (its z is 0 to rounding).
    pub space: Vector3<f64>,
    /// The height of the centre of mass above the table, −r·γ.
    pub height: f64,
    /// The velocity of the body's material point at the contact, space axes, from the state's
    /// (vx, vy) and ω: the slip velocity (horizontal; zero under rolling).
    pub velocity: Vector3<f64>,
}

/// The momenta of a body on a table, space axes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactMomenta {
    /// The linear momentum M v of the centre of mass.
    pub linear: Vector3<f64>,
    /// The angular momentum about the centre of mass, L = R I ω.
    pub center: Vector3<f64>,
    /// The angular momentum about the contact point, K = L − M r × v (r from the centre of
    /// mass to the contact point): K·ẑ and |K|² are conserved by the Chaplygin ball.
    pub contact: Vector3<f64>,
}

/// A body on a table, its equations derived symbolically: by [`super::ContactModel`] at run
/// time, by `#[contact(...)]` at compile time.
///
/// The state is the array of [`super::layout`]. The `*_unchecked`-style required methods are
/// straight-line code for the steppers' inner loops (NaN where the checked forms err, and
/// NaN for a phase the law has not derived); the provided methods check.
pub trait ContactDynamics {
    /// The contact law's kind (which phases exist).
    fn law(&self) -> LawKind;

    /// The kind of the contact surface (which states its support map cannot place).
    fn surface_kind(&self) -> SurfaceKind;

    /// Writes ẏ under `phase` at time `t` and state `y` into `dydt`.
    fn phase_rhs(&self, phase: Phase, t: f64, y: &[f64; STATE_LEN], dydt: &mut [f64; STATE_LEN]);

    /// The force of the table on the body under `phase`.
    fn reaction(&self, phase: Phase, y: &[f64; STATE_LEN]) -> Reaction;

    /// The energy ½ M |v|² + ½ ωᵀ I ω + M g z under `phase` (under rolling v is the
    /// constraint's, r × ω; sliding reads the state's (vx, vy)).
    fn energy(&self, phase: Phase, y: &[f64; STATE_LEN]) -> f64;

    /// The momenta under `phase` (its velocity as for [`ContactDynamics::energy`]).
    fn momenta(&self, phase: Phase, y: &[f64; STATE_LEN]) -> ContactMomenta;

    /// The contact point, its height and its velocity.
    fn contact(&self, y: &[f64; STATE_LEN]) -> ContactPoint;

    /// Jellett's quantity λ = −L·r, L = I ω the angular momentum about the centre of mass and
    /// r the vector from it to the contact point: conserved under any contact force by a
    /// spherical surface with the centre of mass on its symmetry axis.
    fn jellett(&self, y: &[f64; STATE_LEN]) -> f64;

    /// The Coulomb coefficient μ of a Coulomb or stick–slip law, `None` for the others.
    fn friction_coefficient(&self) -> Option<f64>;

    /// Checks the parameter values: mass, inertia, gravity, the surface's lengths, the
    /// friction coefficients, the centre of mass inside the surface.
    ///
    /// # Errors
    /// [`ContactError::BadParameter`], [`ContactError::Body`] (the inertia),
    /// [`ContactError::BadSurface`], [`ContactError::NegativeCoefficient`],
    /// [`ContactError::CenterOutsideSurface`].
    fn check_parameters(&self) -> Result<(), ContactError>;

    /// The values the parameters' rules are checked on ([`ContactValues`]): the mass, the
    /// centre of mass, the inertia about it, gravity, the surface and the law's
    /// coefficients, read from the parameters as they stand (unchecked: see
    /// [`ContactDynamics::check_parameters`]). A run reads the mass properties from here
    /// once, for the impulse of a slip that stops and the normal force's denominator.
    fn values(&self) -> ContactValues;

    /// Checks a state for `phase`: finite, a unit quaternion (within 1e-9), a contact the
    /// support map can place, and under rolling a horizontal velocity that does not slip.
    ///
    /// # Errors
    /// [`ContactError::PhaseNotDerived`], [`ContactError::NonFinite`],
    /// [`ContactError::BadQuaternion`], [`ContactError::FlatDisk`],
    /// [`ContactError::PastParaboloidRim`], [`ContactError::RollingConstraint`].
    fn check_state(&self, phase: Phase, y: &[f64; STATE_LEN]) -> Result<(), ContactError> {
        check_law(self.law(), phase)?;
        check_finite_parts(y)?;
        check_quaternion(y)?;
        check_placement(self.surface_kind(), y)?;
        if phase == Phase::Rolling {
            let c = self.contact(y);
            check_rolling(y, &c.velocity, &c.body)?;
        }
        Ok(())
    }

    /// ẏ under `phase`, checked: the state as [`ContactDynamics::check_state`] and a finite
    /// result.
    ///
    /// # Errors
    /// As [`ContactDynamics::check_state`]; [`ContactError::NonFiniteResult`].
    fn accelerations(
        &self,
        phase: Phase,
        t: f64,
        y: &[f64; STATE_LEN],
    ) -> Result<[f64; STATE_LEN], ContactError> {
        self.check_state(phase, y)?;
        let mut d = [0.0; STATE_LEN];
        self.phase_rhs(phase, t, y, &mut d);
        if d.iter().all(|v| v.is_finite()) {
            Ok(d)
        } else {
            Err(ContactError::NonFiniteResult {
                phase,
                t,
                values: d.to_vec(),
            })
        }
    }

    /// The state array of a body rolling without slip: (vx, vy) from the constraint,
    /// −R(ω × r) horizontally, at horizontal `position` with `attitude` (description →
    /// space) and `omega` (description axes).
    ///
    /// # Errors
    /// [`ContactError::NonFinite`] for a NaN or infinite position or ω;
    /// [`ContactError::FlatDisk`] for a disk rim or torus lying flat and
    /// [`ContactError::PastParaboloidRim`] for a paraboloid that cannot touch the table at
    /// that attitude (the support map cannot place the contact, so the velocity rolling
    /// needs does not exist).
    fn rolling_state(
        &self,
        position: [f64; 2],
        attitude: &UnitQuaternion<f64>,
        omega: &Vector3<f64>,
    ) -> Result<[f64; STATE_LEN], ContactError> {
        let y = self.rolling_state_unchecked(position, attitude, omega);
        check_placement(self.surface_kind(), &y)?;
        check_finite_parts(&y)?;
        Ok(y)
    }

    /// [`ContactDynamics::rolling_state`] without its checks: NaN velocities where the
    /// support map cannot place the contact.
    fn rolling_state_unchecked(
        &self,
        position: [f64; 2],
        attitude: &UnitQuaternion<f64>,
        omega: &Vector3<f64>,
    ) -> [f64; STATE_LEN] {
        let mut y = [0.0; STATE_LEN];
        y[layout::POSITION..layout::POSITION + 2].copy_from_slice(&position);
        let q = attitude.quaternion();
        y[layout::QUATERNION..layout::QUATERNION + 4].copy_from_slice(&[q.w, q.i, q.j, q.k]);
        y[layout::OMEGA..layout::OMEGA + 3].copy_from_slice(omega.as_slice());
        let c = self.contact(&y);
        // With (vx, vy) = 0 the contact velocity is R(ω × r) + vz ẑ, whose horizontal part
        // the state's velocity must cancel.
        y[layout::VELOCITY] = -c.velocity.x;
        y[layout::VELOCITY + 1] = -c.velocity.y;
        y
    }
}
