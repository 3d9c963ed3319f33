//! Rigid-body motion shared by the scenes: every rolling surface and its support map, with
//! the one flatness limit ([`Surface`], [`MIN_TILT`]); Euler-angle sequences with their rotation and
//! rate matrices and their charts (the singularity rule and the chart switch's pieces,
//! [`charts`]), attitude kinematics on the unit quaternions (the exponential map), the
//! states and the models that drive them, the Runge–Kutta–Munthe-Kaas Lie-group stepper, and
//! the geometric splittings (free body, body under a potential).
//!
//! The generic steppers these build on are in [`crate::ode`]; the exact free-body flow is in
//! [`crate::exact`].

mod angles;
pub mod charts;
mod kinematics;
mod lie;
mod projection;
mod quaternion_expr;
pub(crate) mod refusal;
mod rkmk4;
mod rotor;
mod splitting;
mod state;
mod surface;

pub use angles::{AngleSequence, angles_from_rotation, elementary};
pub use charts::{
    ChartConfig, ChartError, ROTATION_TOLERANCE, SINGULAR_DET, check_chart, check_rotation,
    joint_rate_matrix, joint_rotation, map_to_partner, rates_from_omega,
};
pub use kinematics::{dexpinv_right, exp_rotation, rotate_body};
pub use lie::{AttitudeTangent, LieState, LieSystem, RigidTangent, Tangent};
pub use projection::normalise_quaternion;
pub use quaternion_expr::{quaternion_rate, rotation_of_quaternion};
pub use rkmk4::Rkmk4;
pub use rotor::{
    DRIVEN_ROUNDING, DrivenRotor, Rotor, check_driven_inertia, first_non_finite_motor,
    first_singular_driven, motor_input_error, rotor_quantity, singular_driven_step, total_momentum,
};
pub use splitting::{
    ExactFreeFlow, FreeBodySplitting, FreeFlow, Gravity, Potential, PotentialSplitting,
    SplittingOrder,
};
pub use state::{Attitude, AttitudeModel, BodyMomentum, RigidBodyModel, RigidState};
pub use surface::{MIN_TILT, Rim, Surface, SurfaceError, SurfaceKind};
