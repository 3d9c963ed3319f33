//! Animations of the scenes' runs in one call: a top about its pivot, a body on a table.

use precess_core::body::{RigidBody, Shape};
use precess_core::contact::{
    ContactDynamics, ContactValues, STATE_LEN, SurfaceKind, attitude_of, layout,
};
use precess_core::nalgebra::{UnitQuaternion, Vector3};
use precess_core::ode::{HybridState, Trajectory};

use crate::animation::{Animation, Pose};
use crate::error::AnimateError;
use crate::geometry::{self, Halves, Split, Tri};
use crate::parts::{Group, PALETTE, body_size, complement, part_groups};

/// What to draw beside the bodies, and how fast to play.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Seconds shown per second simulated (default 1; 10 is a tenfold slow motion).
    pub time_scale: f64,
    /// Whether to draw the traces: a top's figure-axis apex, a body's contact point on the
    /// table (default true).
    pub traces: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            time_scale: 1.0,
            traces: true,
        }
    }
}

/// The colour of the traces: dark red.
pub const TRACE: [f32; 3] = [0.6, 0.05, 0.1];

/// A top's run: the body drawn from its declared parts, turning about its pivot fixed at the
/// space origin by `attitude` (description → space) of each state, the pivot as a dark ball,
/// and the path of the figure axis's apex: the body-fixed point on the line from the pivot
/// through the centre of mass, at the body's reach along it.
///
/// `attitude` is what the state's form gives: for the Euler-angle form,
/// `UnitQuaternion::from_matrix(&top.rotation_in(seq, &[y[0], y[1], y[2]]))`; for the
/// Eulerian form, the state's quaternion.
///
/// # Errors
/// [`AnimateError::BadPart`] for a part that cannot be drawn, and the errors of
/// [`Animation::add_body`] and [`Animation::with_time_scale`].
pub fn top<B: RigidBody, St>(
    body: &B,
    trajectory: &Trajectory<St>,
    attitude: impl Fn(&St) -> UnitQuaternion<f64>,
    options: Options,
) -> Result<Animation, AnimateError> {
    let description = body.description();
    let pivot = body.reference_point();
    let size = body_size(&description.parts, pivot.into());
    let groups = part_groups(&description.parts, description.pivot, size)?;
    let samples = trajectory
        .times()
        .iter()
        .zip(trajectory.states())
        .map(|(t, y)| {
            let r = attitude(y);
            let pose = Pose {
                position: -(r * pivot),
                attitude: r,
            };
            (*t, pose)
        });
    let mut animation = Animation::new().with_time_scale(options.time_scale)?;
    let k = animation.add_body("top", groups.clone(), samples)?;
    animation.add_pivot([0.0; 3], 0.06 * size);
    if options.traces && trajectory.len() >= 2 {
        let arm = body.center_of_mass() - pivot;
        if arm.norm() > 0.0 {
            let u = arm / arm.norm();
            let reach = groups
                .iter()
                .flat_map(|g| g.triangles.iter().flatten())
                .map(|p| (Vector3::from(*p) - pivot).dot(&u))
                .fold(0.0, f64::max);
            let apex = u * reach;
            let track = &animation.tracks[k];
            let points = track
                .poses
                .iter()
                .map(|p| (p.attitude * apex).into())
                .collect();
            animation.add_trace("figure axis apex", TRACE, points)?;
        }
    }
    Ok(animation)
}

/// A sample of a body on a table: the state array of [`precess_core::contact::layout`],
/// alone or in the run loop's [`HybridState`] (what `ContactRun` records, with its phase).
pub trait TableState {
    /// The state array.
    fn table_state(&self) -> &[f64; STATE_LEN];
}

impl TableState for [f64; STATE_LEN] {
    fn table_state(&self) -> &[f64; STATE_LEN] {
        self
    }
}

impl<M> TableState for HybridState<M, [f64; STATE_LEN]> {
    fn table_state(&self) -> &[f64; STATE_LEN] {
        &self.x
    }
}

/// A body on a table: its contact surface and its declared solid parts (an explicit-inertia
/// part is left out here: the surface stands for the body's shape), placed by each state's
/// horizontal position, the height that contact gives, and its attitude; the table under
/// the motion; and the contact point's path on the table.
///
/// # Errors
/// [`AnimateError::BadSurface`] or [`AnimateError::BadPart`] for values that draw nothing,
/// and the errors of [`Animation::add_body`] and [`Animation::with_time_scale`].
pub fn contact<M: ContactDynamics + RigidBody, St: TableState>(
    model: &M,
    trajectory: &Trajectory<St>,
    options: Options,
) -> Result<Animation, AnimateError> {
    let values = model.values();
    let description = model.description();
    let solids: Vec<_> = description
        .parts
        .iter()
        .filter(|p| !matches!(p.shape, Shape::Explicit { .. }))
        .cloned()
        .collect();
    let centre = Vector3::from(values.center);
    let surface = surface_groups(&values)?;
    let size = body_size(&solids, values.center).max(surface.1);
    let mut groups = surface.0;
    groups.extend(part_groups(&solids, description.pivot, size)?);
    let mut animation = Animation::new().with_time_scale(options.time_scale)?;
    let samples = trajectory
        .times()
        .iter()
        .zip(trajectory.states())
        .map(|(t, y)| {
            let y = y.table_state();
            let r = attitude_of(y);
            let at = layout::POSITION;
            let cm = Vector3::new(y[at], y[at + 1], model.contact(y).height);
            let pose = Pose {
                position: cm - r * centre,
                attitude: r,
            };
            (*t, pose)
        });
    animation.add_body("body", groups, samples)?;
    let contacts: Vec<[f64; 3]> = trajectory
        .states()
        .iter()
        .map(|y| (model.contact(y.table_state()).space + Vector3::new(0.0, 0.0, 1e-4)).into())
        .collect();
    let (lo, hi) = contacts.iter().fold(
        ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]),
        |(lo, hi), p| {
            (
                [lo[0].min(p[0]), lo[1].min(p[1])],
                [hi[0].max(p[0]), hi[1].max(p[1])],
            )
        },
    );
    let middle = [(lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0];
    let half = (hi[0] - lo[0]).max(hi[1] - lo[1]) / 2.0 + 3.0 * size;
    animation.add_table(middle, if half.is_finite() { half } else { 3.0 * size });
    if options.traces && contacts.len() >= 2 {
        animation.add_trace("contact point", TRACE, contacts)?;
    }
    Ok(animation)
}

/// The contact surface's triangles in description axes (its halves in the first palette
/// colour and its complement), and the radius it reaches from the centre of mass.
///
/// # Errors
/// [`AnimateError::BadSurface`] for a length that is not positive, or missing.
pub fn surface_groups(values: &ContactValues) -> Result<(Vec<Group>, f64), AnimateError> {
    let surface = values.surface.name();
    let length = |k: usize| -> Result<f64, AnimateError> {
        match values.lengths.get(k) {
            Some((_, v)) if v.is_finite() && *v > 0.0 => Ok(*v),
            _ => Err(AnimateError::BadSurface {
                surface,
                why: "a length is missing or not positive",
            }),
        }
    };
    let (soup, split): (Vec<Tri>, Split) = match values.surface {
        SurfaceKind::Sphere => (geometry::ellipsoid([length(0)?; 3]), Split::Z),
        SurfaceKind::Ellipsoid => (
            geometry::ellipsoid([length(0)?, length(1)?, length(2)?]),
            Split::Z,
        ),
        // A disk rim is a disk: drawn 1/25 of its radius thick.
        SurfaceKind::DiskRim => {
            let r = length(0)?;
            (geometry::tube(0.0, r, -r / 50.0, r / 50.0), Split::X)
        }
        SurfaceKind::Torus => {
            let (r, tube) = (length(0)?, length(1)?);
            let mut soup = geometry::torus(r, tube);
            // The torus's hole closed by a disk, as a coin's face.
            soup.extend(geometry::tube(0.0, r, -tube / 2.0, tube / 2.0));
            (soup, Split::X)
        }
        SurfaceKind::Paraboloid => {
            let rho = length(0)?;
            (geometry::paraboloid(rho, rho / 2.0), Split::X)
        }
    };
    let c = Vector3::from(values.placement);
    let cm = Vector3::from(values.center);
    let place = |t: Vec<Tri>| -> Vec<[[f64; 3]; 3]> {
        t.into_iter()
            .map(|tri| tri.map(|p| (c + Vector3::from(p)).into()))
            .collect()
    };
    let reach = soup
        .iter()
        .flatten()
        .map(|p| (c + Vector3::from(*p) - cm).norm())
        .fold(0.0, f64::max);
    let halves = Halves::split(soup, split);
    let colour = PALETTE[0];
    let groups = vec![
        Group {
            colour,
            triangles: place(halves.first),
        },
        Group {
            colour: complement(colour),
            triangles: place(halves.second),
        },
    ];
    Ok((groups, reach))
}
