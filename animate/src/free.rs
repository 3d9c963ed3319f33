//! A free body's run in one call: the body flying and tumbling in space, the path of its
//! centre of mass.

use precess_core::free::{FreeDynamics, FreeState};
use precess_core::ode::{HybridState, Trajectory};

use crate::animation::{Animation, Pose};
use crate::error::AnimateError;
use crate::parts::{body_size, part_groups};
use crate::scenes::{Options, TRACE};

/// A sample of a free body's run: a [`FreeState`], the state array the free steppers
/// integrate (`precess_core::free::layout`: position, velocity, the quaternion `[w, x, y, z]`
/// from principal to space axes, ω; a driven body's rotor rates after them), or that array
/// in the run loop's [`HybridState`].
pub trait FreeSample {
    /// The state, its quaternion normalised: NaN where the array is too short or its
    /// quaternion zero, which [`free`] reports as [`AnimateError::NonFinite`].
    fn free_state(&self) -> FreeState;
}

impl FreeSample for FreeState {
    fn free_state(&self) -> FreeState {
        *self
    }
}

impl<const N: usize> FreeSample for [f64; N] {
    fn free_state(&self) -> FreeState {
        FreeState::from_array_unchecked(self)
    }
}

impl<M, const N: usize> FreeSample for HybridState<M, [f64; N]> {
    fn free_state(&self) -> FreeState {
        FreeState::from_array_unchecked(&self.x)
    }
}

/// A free body's run: the body drawn from its declared parts, its centre of mass at each
/// state's position and its description axes turned by the state's attitude, and (when it
/// moves) the path of its centre of mass.
///
/// The state's attitude q turns principal axes (about the centre of mass) into space
/// axes; the body's description axes are the constant rotation P (principal → description,
/// `principal_cm`) away, so the drawn map is x ↦ X + R (x − c) with R = q P⁻¹, X the
/// state's position and c the centre of mass in description axes.
///
/// To watch a body tumble without its flight, give it states whose position is zero (the
/// motion seen from its centre of mass).
///
/// ```
/// use approx::assert_relative_eq;
/// use precess::animate::{self, Options};
/// use precess::free::FreeState;
/// use precess::nalgebra::{UnitQuaternion, Vector3};
/// use precess::ode::Trajectory;
/// use precess::prelude::*;
///
/// /// A brick, free in space.
/// #[derive(RigidBody)]
/// #[rigid(cuboid(mass = 1.0, size = [0.1, 0.2, 0.3]))]
/// #[free]
/// struct Brick;
///
/// // Turning at 2 rad/s about its z axis while falling freely.
/// let mut run = Trajectory::new(vec![]);
/// for k in 0..=50 {
///     let t = 0.02 * k as f64;
///     let state = FreeState {
///         position: Vector3::new(0.0, 0.0, -4.905 * t * t),
///         velocity: Vector3::new(0.0, 0.0, -9.81 * t),
///         attitude: UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 2.0 * t),
///         omega_principal: Vector3::new(0.0, 0.0, 2.0),
///     };
///     run.push(t, state, &[])?;
/// }
/// let animation = animate::free(&Brick, &run, Options::default())?;
/// let keys = animation.keyframes(0).expect("one body");
/// assert_eq!(keys.times.len(), 51);
/// // The last keyframe: ½ g t² = 4.905 m down at t = 1 s.
/// assert_relative_eq!(keys.translations[50][2], -4.905f32, max_relative = 1e-6);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`AnimateError::BadPart`] for a part that cannot be drawn,
/// [`AnimateError::NonFinite`] for a state with a NaN or infinite position or attitude (a
/// zero quaternion, an array shorter than 13), and the errors of [`Animation::add_body`],
/// [`Animation::with_time_scale`] and [`Animation::add_trace`].
pub fn free<B: FreeDynamics<N>, const N: usize, St: FreeSample>(
    body: &B,
    trajectory: &Trajectory<St>,
    options: Options,
) -> Result<Animation, AnimateError> {
    let description = body.description();
    let centre = body.center_of_mass();
    let size = body_size(&description.parts, centre.into());
    let groups = part_groups(&description.parts, description.pivot, size)?;
    let principal = body.principal_cm();
    let states: Vec<FreeState> = trajectory.states().iter().map(|s| s.free_state()).collect();
    let samples = trajectory.times().iter().zip(&states).map(|(t, s)| {
        let r = s.attitude_description(&principal);
        let pose = Pose {
            position: s.position - r * centre,
            attitude: r,
        };
        (*t, pose)
    });
    let mut animation = Animation::new().with_time_scale(options.time_scale)?;
    animation.add_body("body", groups, samples)?;
    let path: Vec<[f64; 3]> = states.iter().map(|s| s.position.into()).collect();
    let moves = states
        .iter()
        .any(|s| (s.position - states[0].position).norm() > 1e-3 * size);
    if options.traces && moves {
        animation.add_trace("centre of mass", TRACE, path)?;
    }
    Ok(animation)
}
