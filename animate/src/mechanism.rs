//! A mechanism's run in one call: each link drawn from its declared parts and keyframed from
//! the derived [`MechanismPoses::link_poses`], its joints as balls, the last link's tip path.

use precess_core::mechanism::{LinkPose, MechanismPoses};
use precess_core::nalgebra::{Rotation3, UnitQuaternion, Vector3};
use precess_core::ode::{HybridState, Trajectory};

use crate::animation::{Animation, PIVOT, Pose};
use crate::error::AnimateError;
use crate::geometry::{self, Tri};
use crate::parts::{Group, body_size, part_groups};
use crate::scenes::{Options, TRACE};

/// The colour of the bars from a link's joint to its parts: mid grey.
pub const BAR: [f32; 3] = [0.45, 0.45, 0.48];

/// A sample of a mechanism's run: the state `[q, q̇]` its `System` integrates (the first N
/// slots are q), alone or in the run loop's [`HybridState`].
pub trait MechanismSample<const N: usize> {
    /// q: the first N numbers, NaN where the array is shorter (which [`mechanism`] reports as
    /// [`AnimateError::NonFinite`]).
    fn coordinates(&self) -> [f64; N];
}

impl<const N: usize, const S: usize> MechanismSample<N> for [f64; S] {
    fn coordinates(&self) -> [f64; N] {
        std::array::from_fn(|k| self.get(k).copied().unwrap_or(f64::NAN))
    }
}

impl<P, const N: usize, const S: usize> MechanismSample<N> for HybridState<P, [f64; S]> {
    fn coordinates(&self) -> [f64; N] {
        self.x.coordinates()
    }
}

/// The pose an animation node takes from a link's: x ↦ o_b + R_b x.
pub fn link_node(pose: &LinkPose) -> Pose {
    let r = Rotation3::from_matrix_unchecked(pose.rotation);
    Pose {
        position: pose.origin,
        attitude: UnitQuaternion::from_rotation_matrix(&r),
    }
}

/// A mechanism's run: every link (bodies `0..L`, in declaration order) drawn from its
/// declared parts with a grey bar from its joint (its frame's origin) to each part, keyframed
/// by x ↦ o_b(q) + R_b(q) x of [`MechanismPoses::link_poses`] at each sample's q; every
/// joint a dark ball at o_p + R_p a (bodies `L..2L`); and, with `options.traces`, the path of
/// the last link's tip (the point of its parts farthest from its joint).
///
/// ```
/// use approx::assert_relative_eq;
/// use precess::animate::{self, Options};
/// use precess::ode::Trajectory;
/// use precess::prelude::*;
///
/// #[derive(Mechanism)]
/// #[mechanism(gravity = 9.81)]
/// #[body(bob, parent = ground, joint = revolute(axis = x), q = theta,
///        parts(particle(mass = 1.0, at = [0.0, 0.0, -2.0])))]
/// struct Pendulum;
///
/// // A small swing θ = 0.2 cos(√(g/l) t), written down.
/// let mut run = Trajectory::new(vec![]);
/// for k in 0..=100 {
///     let t = 0.03 * k as f64;
///     run.push(t, [0.2 * (2.2147f64 * t).cos(), 0.0], &[])?;
/// }
/// let animation = animate::mechanism(&Pendulum, &run, Options::default())?;
/// let keys = animation.keyframes(0).expect("the bob's link");
/// assert_eq!(keys.times.len(), 101);
/// assert!(animation.to_glb()?.len() > 1000);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`AnimateError::BadPart`] for a part that cannot be drawn, [`AnimateError::NonFinite`]
/// for a sample whose q (or a pose from it) is not finite, and the errors of
/// [`Animation::add_body`], [`Animation::with_time_scale`] and [`Animation::add_trace`].
pub fn mechanism<M: MechanismPoses<N>, const N: usize, St: MechanismSample<N>>(
    model: &M,
    trajectory: &Trajectory<St>,
    options: Options,
) -> Result<Animation, AnimateError> {
    let descriptions = model.link_parts();
    let size = descriptions
        .iter()
        .map(|d| body_size(&d.parts, [0.0; 3]))
        .fold(1e-3, f64::max);
    let poses: Vec<Vec<LinkPose>> = trajectory
        .states()
        .iter()
        .map(|s| model.link_poses(&s.coordinates()))
        .collect();
    let times = trajectory.times();
    let mut animation = Animation::new().with_time_scale(options.time_scale)?;
    let ball = geometry::ellipsoid([0.05 * size; 3]);
    let links = descriptions.len();
    for (k, description) in descriptions.iter().enumerate() {
        let mut groups = part_groups(&description.parts, description.pivot, size)?;
        let bars: Vec<Tri> = description
            .parts
            .iter()
            .flat_map(|p| bar(Vector3::from(p.at), 0.015 * size))
            .collect();
        if !bars.is_empty() {
            groups.push(Group {
                colour: BAR,
                triangles: bars,
            });
        }
        let name = poses
            .first()
            .and_then(|p| p.get(k))
            .map_or("link", |p| p.name);
        let samples = times.iter().zip(&poses).map(|(t, p)| (*t, node_at(p, k)));
        animation.add_body(name, groups, samples)?;
    }
    for k in 0..links {
        let name = poses
            .first()
            .and_then(|p| p.get(k))
            .map_or("link", |p| p.name);
        let groups = vec![Group {
            colour: PIVOT,
            triangles: ball.clone(),
        }];
        let samples = times.iter().zip(&poses).map(|(t, p)| {
            let at = p.get(k).map_or(Vector3::repeat(f64::NAN), |l| l.joint);
            let pose = Pose {
                position: at,
                attitude: UnitQuaternion::identity(),
            };
            (*t, pose)
        });
        animation.add_body(format!("joint of {name}"), groups, samples)?;
    }
    if options.traces && poses.len() >= 2 && links > 0 {
        let last = links - 1;
        let tip = descriptions[last]
            .parts
            .iter()
            .map(|p| Vector3::from(p.at))
            .max_by(|a, b| a.norm().total_cmp(&b.norm()))
            .unwrap_or_else(Vector3::zeros);
        let points = poses
            .iter()
            .map(|p| {
                let n = node_at(p, last);
                (n.position + n.attitude * tip).into()
            })
            .collect();
        animation.add_trace("last link's tip", TRACE, points)?;
    }
    Ok(animation)
}

/// Link `k`'s node pose among `poses`, NaN (an error in `add_body`) if there is none.
fn node_at(poses: &[LinkPose], k: usize) -> Pose {
    poses.get(k).map_or(
        Pose {
            position: Vector3::repeat(f64::NAN),
            attitude: UnitQuaternion::identity(),
        },
        link_node,
    )
}

/// A thin cylinder of `radius` from the origin to `to`, none when `to` is the origin.
fn bar(to: Vector3<f64>, radius: f64) -> Vec<Tri> {
    let length = to.norm();
    // Also none for a NaN length (`part_groups` has refused a non-finite part already).
    if length.is_nan() || length <= 1e-9 * radius {
        return Vec::new();
    }
    let turn = UnitQuaternion::rotation_between(&Vector3::z(), &to).unwrap_or_else(|| {
        UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI)
    });
    geometry::tube(0.0, radius, 0.0, length)
        .into_iter()
        .map(|t| t.map(|p| (turn * Vector3::from(p)).into()))
        .collect()
}
