//! Typed errors of the contact scene: bad parameters, bad states (a quaternion that names no
//! attitude, a rolling state that slips, a contact the surface's support map cannot place),
//! and the failures of the steppers the runs are made of.

use thiserror::Error;

use super::scene::Phase;
use crate::body::BodyError;
use crate::codegen::BindingError;
use crate::ode::OdeError;
use crate::sym::SymError;

/// Why a body on a table could not be derived, set up, evaluated or integrated.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ContactError {
    /// A part of a state holds NaN or ±∞.
    #[error("non-finite {quantity}: {values:?}")]
    NonFinite {
        /// Which part: the position, the velocity, the attitude quaternion or ω.
        quantity: &'static str,
        /// Its values.
        values: Vec<f64>,
    },
    /// The attitude quaternion of a state is zero or far off the unit sphere.
    #[error(
        "the attitude quaternion {quaternion:?} has norm {norm}; a state needs a unit \
         quaternion (within {tolerance:e})"
    )]
    BadQuaternion {
        /// The quaternion as stored, `[w, x, y, z]`.
        quaternion: [f64; 4],
        /// Its norm.
        norm: f64,
        /// The allowed distance of the norm from 1.
        tolerance: f64,
    },
    /// A rolling state whose horizontal velocity is not the one rolling without slip gives.
    #[error(
        "the rolling state slips: its horizontal velocity is {velocity:?} but rolling without \
         slip gives {rolling:?} (difference {slip:e} m/s, allowed {tolerance:e}); build rolling \
         states with ContactModel::rolling_state"
    )]
    RollingConstraint {
        /// The state's (vx, vy).
        velocity: [f64; 2],
        /// The (vx, vy) the constraint gives, −R(ω × r) horizontally.
        rolling: [f64; 2],
        /// |velocity − rolling|.
        slip: f64,
        /// The tolerance: 1e-9 of (|ω| |r| + |v|), at least 1e-12 m/s.
        tolerance: f64,
    },
    /// The disk rim (or torus) lies flat on the table: its support point is not unique.
    #[error(
        "the {surface} lies flat: its axis is {tilt:e} rad from the vertical, below \
         {minimum:e}, where the contact point is not unique"
    )]
    FlatDisk {
        /// `disk_rim` or `torus`.
        surface: &'static str,
        /// The angle between the disk's axis and the vertical (either way).
        tilt: f64,
        /// The smallest angle allowed.
        minimum: f64,
    },
    /// The paraboloid would touch the table past its rim: the downward normal needs n₃ < 0.
    #[error(
        "the paraboloid cannot touch the table: the table's normal in body axes has n₃ = \
         {n3} (it must be below {maximum}: the bowl must face the table)"
    )]
    PastParaboloidRim {
        /// The body-axis z component of the outward normal at the contact, −γ₃.
        n3: f64,
        /// The largest allowed.
        maximum: f64,
    },
    /// A friction coefficient (μ, c, a resistance) that is negative or NaN.
    #[error("`{name}` is {value}: a friction coefficient must be finite and ≥ 0")]
    NegativeCoefficient {
        /// The coefficient: `mu`, `viscous`, `rolling_resistance`, `spin_resistance`.
        name: &'static str,
        /// Its value.
        value: f64,
    },
    /// A length of the surface (radius, semi-axis, tube) that is not finite and > 0, or a
    /// torus tube larger than its centre line's radius (not convex).
    #[error("the {surface}'s {name} is {value}: it must be {rule}")]
    BadSurface {
        /// The surface's name.
        surface: &'static str,
        /// The length: `radius`, `semi-axis a`, `tube` …
        name: &'static str,
        /// Its value.
        value: f64,
        /// What is allowed.
        rule: &'static str,
    },
    /// The centre of mass lies outside the body's contact surface.
    #[error(
        "the centre of mass {center:?} lies outside the {surface} (measure {measure}, must be \
         < 1): the contact model needs the centre of mass inside the surface it rolls on"
    )]
    CenterOutsideSurface {
        /// The surface's name.
        surface: &'static str,
        /// The centre of mass, description axes.
        center: [f64; 3],
        /// The surface's implicit measure at the centre (1 on the surface, < 1 inside).
        measure: f64,
    },
    /// The mass or gravity is not finite and positive (gravity may be zero).
    #[error("`{name}` is {value}: it must be {rule}")]
    BadParameter {
        /// `mass` or `gravity`.
        name: &'static str,
        /// Its value.
        value: f64,
        /// What is allowed.
        rule: &'static str,
    },
    /// The equations of the phase asked for were not derived for the scene's law (the
    /// sliding equations of a rolling body, say).
    #[error("the {phase:?} equations were not derived: the contact law is {law}")]
    PhaseNotDerived {
        /// The phase asked for.
        phase: Phase,
        /// The scene's law.
        law: &'static str,
    },
    /// The equations gave a non-finite value at a state (a Coulomb sliding state whose
    /// normal-force equation is singular, the Painlevé paradox, or a slip speed of zero).
    #[error("the {phase:?} equations are not finite at t = {t}: {values:?}")]
    NonFiniteResult {
        /// The phase.
        phase: Phase,
        /// The time.
        t: f64,
        /// The right-hand side.
        values: Vec<f64>,
    },
    /// A run was started with the body pulled onto the table: the normal force its phase
    /// needs at the start is negative, so it would leave the table at once. No state with
    /// N < 0 is a state of a body on a table.
    #[error(
        "the normal force at the start is N = {normal} N under {phase:?}: negative, so the \
         body would leave the table at once (a body on a table needs N ≥ 0); start it where \
         the table pushes"
    )]
    NotPressed {
        /// The phase asked for.
        phase: Phase,
        /// The normal force there.
        normal: f64,
    },
    /// A sliding state under Coulomb friction where the normal force has no consistent
    /// value (Painlevé's paradox): the denominator 1 − M (γ × r)·I⁻¹(r × (γ − μ û)) of N is
    /// not positive, so the rigid-body equations give no (or no unique) N.
    #[error(
        "Painlevé's paradox at t = {t}: under Coulomb friction (μ = {mu}) the normal force's \
         denominator is {denominator} ≤ 0, so the rigid body on the table has no consistent \
         normal force (N = {normal} N from the equations); a smaller μ, or a compliant \
         contact, resolves it"
    )]
    Painleve {
        /// When.
        t: f64,
        /// The friction coefficient.
        mu: f64,
        /// The denominator of N.
        denominator: f64,
        /// What the equations give for N there.
        normal: f64,
    },
    /// Pure Coulomb sliding whose slip reached zero: the law has no direction for the
    /// friction at zero slip, and a body that would stop slipping needs the stick–slip law.
    #[error(
        "the slip stopped at t = {t} (|u| = {slip:e} m/s, at most {threshold:e}) under pure \
         Coulomb sliding, whose friction −μN u/|u| has no direction at zero slip: use the \
         stick–slip law (`stick_slip(mu = ..)`, `ContactLaw::StickSlip`) for a body that may \
         start rolling"
    )]
    SlipStopped {
        /// When.
        t: f64,
        /// The slip speed |u| there.
        slip: f64,
        /// The slip speed taken as zero: 10⁻⁹ of the run's velocity scale.
        threshold: f64,
    },
    /// A resistance declared twice: by the rolling law and by the further torques of
    /// [`ContactScene::derive_with`](super::ContactScene::derive_with).
    #[error(
        "`{name}` is declared twice, by `ContactLaw::Rolling` and by `ContactTorques`: \
         declare it once"
    )]
    DeclaredTwice {
        /// The resistance's name.
        name: &'static str,
    },
    /// A derivation with a user couple given to [`ContactModel::new`](super::ContactModel::new),
    /// which cannot supply it, or a couple given to a derivation without one.
    #[error(
        "the derivation {reads} a user couple but the model was {given}: build it with \
         `ContactModel::with_torque` for a derivation of `ContactTorques {{ user: Some(..) }}`, \
         and with `ContactModel::new` otherwise"
    )]
    UserTorque {
        /// "reads" or "does not read".
        reads: &'static str,
        /// What the model was given.
        given: &'static str,
    },
    /// A sliding start under Coulomb friction (sliding or stick–slip) with no slip: the
    /// friction's direction u/|u| is undefined.
    #[error(
        "a sliding start needs a slip, but |u| = {slip:e} m/s is at most {threshold:e}: \
         Coulomb friction −μN u/|u| has no direction at zero slip; start the body rolling \
         (Phase::Rolling, with `rolling_state`) under stick–slip, which slides where rolling \
         cannot hold"
    )]
    ZeroSlip {
        /// The slip speed |u| of the state.
        slip: f64,
        /// The slip speed taken as zero.
        threshold: f64,
    },
    /// The motion with the spin held at zero was asked of a body without pivoting
    /// friction: no couple holds its spin.
    #[error(
        "the spin can be held only by pivoting friction, and this body's {law} law declares \
         none: declare `pivoting = ℓ_p` (ContactTorques {{ pivoting: Some(..) }})"
    )]
    NoPivoting {
        /// The contact law's name.
        law: &'static str,
    },
    /// The symbolic derivation failed (a division or root the arena refused).
    #[error(transparent)]
    Sym(#[from] SymError),
    /// A parameter of the interpreted [`super::ContactModel`] could not be bound.
    #[error(transparent)]
    Binding(#[from] BindingError),
    /// The body's mass properties break a rule of the body language.
    #[error(transparent)]
    Body(#[from] BodyError),
    /// A stepper failed, or a stop time is not finite or lies in the past.
    #[error(transparent)]
    Ode(#[from] OdeError),
}

impl ContactError {
    /// The error as an [`OdeError`] for [`crate::ode::System::check_parameters`]: a stepper's
    /// error as it is, any other refusal as [`OdeError::InvalidSystemParameter`] naming the
    /// quantity and carrying its value.
    pub fn into_ode_error(self) -> OdeError {
        let named = match &self {
            ContactError::Ode(e) => return e.clone(),
            ContactError::Body(b) => crate::ode::body_quantity(b),
            ContactError::Binding(b) => crate::ode::binding_quantity(b),
            ContactError::BadParameter { name, value, .. }
            | ContactError::NegativeCoefficient { name, value } => ((*name).to_owned(), *value),
            ContactError::BadSurface { name, value, .. } => ((*name).to_owned(), *value),
            ContactError::CenterOutsideSurface { measure, .. } => {
                ("centre of mass".to_owned(), *measure)
            }
            _ => ("parameters".to_owned(), f64::NAN),
        };
        crate::ode::refused(named, &self)
    }
}
