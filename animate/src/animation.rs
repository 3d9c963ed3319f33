//! The animation of a run: bodies keyframed over time, fixed fixtures, and traces.

use std::path::Path;

use precess_core::nalgebra::{UnitQuaternion, Vector3};

use crate::error::AnimateError;
use crate::geometry::{self, Halves, Split};
use crate::parts::{Group, Rgb};

/// Where a body is at one instant: the rigid map x ↦ `position` + R x from description axes
/// to space axes, R the rotation of `attitude`.
///
/// For a top about a pivot p (description axes) fixed at the space origin, position = −R p;
/// for a body whose centre of mass c (description axes) is at X in space, position = X − R c.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose {
    /// Where the description frame's origin is, space axes (m).
    pub position: Vector3<f64>,
    /// The rotation from description to space axes.
    pub attitude: UnitQuaternion<f64>,
}

/// One body's mesh and keyframes.
#[derive(Debug, Clone)]
pub(crate) struct Track {
    pub name: String,
    pub groups: Vec<Group>,
    pub times: Vec<f64>,
    pub poses: Vec<Pose>,
}

/// A mesh fixed in space (the table, the pivot).
#[derive(Debug, Clone)]
pub(crate) struct Fixture {
    pub name: String,
    pub groups: Vec<Group>,
}

/// A polyline fixed in space.
#[derive(Debug, Clone)]
pub(crate) struct Trace {
    pub name: String,
    pub colour: Rgb,
    pub points: Vec<[f64; 3]>,
}

/// The colour of the table: a light warm grey.
pub const TABLE: Rgb = [0.80, 0.79, 0.75];
/// The colour of the pivot: dark grey.
pub const PIVOT: Rgb = [0.25, 0.25, 0.25];

/// A run as an animation: bodies whose meshes move by keyframes, fixtures, and traces, all in
/// precess's space axes (z up), written as binary glTF by [`Animation::to_glb`].
///
/// The keyframes' times are the samples' times less the earliest first time of any body,
/// multiplied by the time scale: a scale of 10 plays a 1 s run in 10 s. Build one from a scene
/// with [`crate::top`] or [`crate::contact`], or by hand:
///
/// ```
/// use precess::animate::{Animation, Pose, part_groups};
/// use precess::body::{Part, Shape};
/// use precess::nalgebra::{UnitQuaternion, Vector3};
///
/// let parts = [Part::new(Shape::Sphere { mass: 1.0, radius: 0.1 }, [0.0; 3])];
/// let groups = part_groups(&parts, None, 0.1)?;
/// let samples = (0..=10).map(|k| {
///     let t = 0.1 * k as f64;
///     let pose = Pose {
///         position: Vector3::new(t, 0.0, 0.1),
///         attitude: UnitQuaternion::from_axis_angle(&Vector3::y_axis(), t / 0.1),
///     };
///     (t, pose)
/// });
/// let mut animation = Animation::new().with_time_scale(2.0)?;
/// animation.add_body("ball", groups, samples)?;
/// animation.add_table([0.5, 0.0], 1.0);
/// assert_eq!(animation.duration(), 2.0);
/// let glb = animation.to_glb()?;
/// assert_eq!(&glb[0..4], b"glTF");
/// # Ok::<(), precess::animate::AnimateError>(())
/// ```
#[derive(Debug, Clone)]
pub struct Animation {
    pub(crate) time_scale: f64,
    pub(crate) tracks: Vec<Track>,
    pub(crate) fixtures: Vec<Fixture>,
    pub(crate) traces: Vec<Trace>,
}

impl Default for Animation {
    fn default() -> Self {
        Animation::new()
    }
}

impl Animation {
    /// An empty animation played in real time.
    pub fn new() -> Animation {
        Animation {
            time_scale: 1.0,
            tracks: Vec::new(),
            fixtures: Vec::new(),
            traces: Vec::new(),
        }
    }

    /// The same animation played `scale` times slower (seconds shown per second simulated).
    ///
    /// # Errors
    /// [`AnimateError::BadTimeScale`] unless `scale` is positive and finite.
    pub fn with_time_scale(mut self, scale: f64) -> Result<Animation, AnimateError> {
        if !(scale.is_finite() && scale > 0.0) {
            return Err(AnimateError::BadTimeScale { scale });
        }
        self.time_scale = scale;
        Ok(self)
    }

    /// The time scale (seconds shown per second simulated).
    pub fn time_scale(&self) -> f64 {
        self.time_scale
    }

    /// The simulated time at which playback starts: the earliest first sample of any body.
    pub fn start(&self) -> f64 {
        self.tracks
            .iter()
            .filter_map(|t| t.times.first())
            .fold(f64::INFINITY, |a, b| a.min(*b))
    }

    /// The playback's length in seconds: the span of the samples times the time scale.
    pub fn duration(&self) -> f64 {
        let end = self
            .tracks
            .iter()
            .filter_map(|t| t.times.last())
            .fold(f64::NEG_INFINITY, |a, b| a.max(*b));
        if end.is_finite() {
            (end - self.start()) * self.time_scale
        } else {
            0.0
        }
    }

    /// Adds a body drawn as `groups` (in description axes, see [`crate::part_groups`]) at the
    /// poses of `samples`, `(t, pose)` in time order; returns its index.
    ///
    /// # Errors
    /// [`AnimateError::NoSamples`], [`AnimateError::NonFinite`] for a NaN or infinite time
    /// or pose, [`AnimateError::DecreasingTime`] for a time before the previous one.
    pub fn add_body(
        &mut self,
        name: impl Into<String>,
        groups: Vec<Group>,
        samples: impl IntoIterator<Item = (f64, Pose)>,
    ) -> Result<usize, AnimateError> {
        let name = name.into();
        let (mut times, mut poses) = (Vec::new(), Vec::new());
        for (index, (t, pose)) in samples.into_iter().enumerate() {
            let q = pose.attitude.quaternion();
            let finite = t.is_finite()
                && pose.position.iter().all(|v| v.is_finite())
                && q.coords.iter().all(|v| v.is_finite());
            if !finite {
                return Err(AnimateError::NonFinite {
                    body: name,
                    index,
                    t,
                });
            }
            if let Some(&previous) = times.last()
                && t < previous
            {
                return Err(AnimateError::DecreasingTime {
                    body: name,
                    index,
                    t,
                    previous,
                });
            }
            times.push(t);
            poses.push(pose);
        }
        if times.is_empty() {
            return Err(AnimateError::NoSamples { body: name });
        }
        self.tracks.push(Track {
            name,
            groups,
            times,
            poses,
        });
        Ok(self.tracks.len() - 1)
    }

    /// Adds the table: a square of half-width `half` (m) in the plane z = 0 about `centre`
    /// (x, y), seen from above, 1 mm thick below the plane.
    pub fn add_table(&mut self, centre: [f64; 2], half: f64) {
        let slab = geometry::cuboid([2.0 * half, 2.0 * half, 1e-3])
            .into_iter()
            .map(|t| t.map(|p| [p[0] + centre[0], p[1] + centre[1], p[2] - 0.5e-3]))
            .collect();
        self.fixtures.push(Fixture {
            name: "table".into(),
            groups: vec![Group {
                colour: TABLE,
                triangles: slab,
            }],
        });
    }

    /// Adds the pivot: a dark sphere of `radius` (m) at `at` (space axes).
    pub fn add_pivot(&mut self, at: [f64; 3], radius: f64) {
        let halves = Halves::split(geometry::ellipsoid([radius; 3]), Split::Z);
        let ball = [halves.first, halves.second]
            .concat()
            .into_iter()
            .map(|t| t.map(|p| [p[0] + at[0], p[1] + at[1], p[2] + at[2]]))
            .collect();
        self.fixtures.push(Fixture {
            name: "pivot".into(),
            groups: vec![Group {
                colour: PIVOT,
                triangles: ball,
            }],
        });
    }

    /// Adds a trace: the polyline through `points` (space axes), drawn as a line strip.
    ///
    /// # Errors
    /// [`AnimateError::BadTrace`] for fewer than two points or a non-finite one.
    pub fn add_trace(
        &mut self,
        name: impl Into<String>,
        colour: Rgb,
        points: Vec<[f64; 3]>,
    ) -> Result<(), AnimateError> {
        let name = name.into();
        let len = points.len();
        if let Some(index) = points.iter().position(|p| p.iter().any(|v| !v.is_finite())) {
            return Err(AnimateError::BadTrace {
                trace: name,
                index,
                len,
            });
        }
        if len < 2 {
            return Err(AnimateError::BadTrace {
                trace: name,
                index: len,
                len,
            });
        }
        self.traces.push(Trace {
            name,
            colour,
            points,
        });
        Ok(())
    }

    /// Writes [`Animation::to_glb`] to `path`.
    ///
    /// # Errors
    /// As [`Animation::to_glb`], and [`AnimateError::Io`] if the file cannot be written.
    pub fn write_glb(&self, path: impl AsRef<Path>) -> Result<(), AnimateError> {
        let path = path.as_ref();
        std::fs::write(path, self.to_glb()?).map_err(|source| AnimateError::Io {
            path: path.to_path_buf(),
            source,
        })
    }
}
