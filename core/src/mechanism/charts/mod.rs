//! Getting a mechanism through the gimbal lock of its spherical joints: every spherical joint
//! has two angle charts (its declared sequence and the partner, ZXZ ↔ ZYX, never singular at
//! the same attitude), and [`ChartedMechanism`] integrates in one choice of chart per joint,
//! moving a joint to its partner chart between steps when its `|det B_j|` gets small.
//!
//! A chart of the whole mechanism is a [`ChartSet`]: which spherical joints are switched to
//! their partner sequence. Its equations are the scene's with those joints' sequences
//! swapped ([`scene_in_charts`]), derived like any other scene. The state of a switched
//! joint holds the partner's angles and rates in the joint's three slots (ZYX: yaw, pitch,
//! roll), whatever the coordinates are named.
//!
//! Which chart sets exist is [`chart_variants`]'s rule, the same for the run-time
//! [`MechanismCharts`] and for `#[derive(Mechanism)]`: every combination for up to
//! [`MAX_ALL_CHARTS`] switchable joints, otherwise the declared charts and each joint
//! switched alone. A joint with a spring, damper or effort on its angles is not switchable:
//! those loads are defined along one chart's coordinates, and the partner chart would change
//! the physics.

mod model_charts;
mod run;

pub use model_charts::MechanismCharts;
pub use run::{ChartedMechanism, InCharts};

use super::MechanismError;
use super::scene::{JointKind, MechanismScene};
use crate::rigid::AngleSequence;

/// Up to this many switchable spherical joints every combination of charts is available
/// (2ᵏ chart sets); above it, the declared charts and each joint switched alone (k + 1).
pub const MAX_ALL_CHARTS: usize = 2;

/// The most spherical joints a [`ChartSet`] can name (one bit each).
pub const MAX_SPHERICAL_JOINTS: usize = 32;

/// Which spherical joints are in their partner chart: bit j for the j-th spherical joint in
/// body order ([`spherical_joints`]). Zero is every joint in its declared sequence.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct ChartSet(pub u32);

/// A chart set as the mode of a charted mechanism's run: its CSV column `charts` holds the
/// bits.
impl crate::ode::Mode for ChartSet {
    const COLUMN: Option<&'static str> = Some("charts");

    fn number(&self) -> f64 {
        f64::from(self.0)
    }
}

impl ChartSet {
    /// Every joint in its declared sequence.
    pub const DECLARED: ChartSet = ChartSet(0);

    /// Whether spherical joint `j` is switched to its partner sequence.
    pub fn is_switched(self, j: usize) -> bool {
        j < MAX_SPHERICAL_JOINTS && self.0 & (1 << j) != 0
    }

    /// The same set with joint `j` in the other of its two charts (unchanged for j ≥ 32).
    pub fn toggled(self, j: usize) -> ChartSet {
        if j < MAX_SPHERICAL_JOINTS {
            ChartSet(self.0 ^ (1 << j))
        } else {
            self
        }
    }

    /// The sequence joint `j` of declared sequence `declared` uses in this set.
    pub fn sequence(self, j: usize, declared: AngleSequence) -> AngleSequence {
        if self.is_switched(j) {
            declared.other()
        } else {
            declared
        }
    }
}

/// A spherical joint as the chart switch sees it; a free joint's three rotations are one
/// too (its `first` is its first angle, after its three translations).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SphericalJoint {
    /// The joint's name.
    pub name: String,
    /// The index of its first angle in q (its three angles are consecutive).
    pub first: usize,
    /// The sequence it was declared with.
    pub declared: AngleSequence,
    /// False when a load on its angles ties it to the declared chart.
    pub switchable: bool,
}

/// The spherical joints of `scene`, with the rotations of its free joint, in body order
/// (bit j of a [`ChartSet`] is the j-th).
pub fn spherical_joints(scene: &MechanismScene) -> Vec<SphericalJoint> {
    let offsets = scene.coordinate_offsets();
    scene
        .bodies
        .iter()
        .zip(offsets)
        .filter_map(|(body, first)| {
            let (sequence, angle) = body.joint.kind.euler_angles()?;
            Some(SphericalJoint {
                name: body.joint.name.clone(),
                first: first + angle,
                declared: sequence,
                // Only loads on the angles tie a joint to its chart: a free joint's
                // translations are the same coordinates in both.
                switchable: body
                    .joint
                    .loads
                    .iter()
                    .skip(angle)
                    .all(|l| l.spring.is_none() && l.damper.is_none() && l.effort.is_none()),
            })
        })
        .collect()
}

/// The chart sets a mechanism with these spherical joints provides, declared first: every
/// subset of the switchable joints when there are at most [`MAX_ALL_CHARTS`] of them,
/// otherwise the declared set and each switchable joint switched alone. Joints past
/// [`MAX_SPHERICAL_JOINTS`] are never switched.
///
/// # Examples
///
/// ```
/// use precess_core::mechanism::charts::{ChartSet, chart_variants};
/// assert_eq!(chart_variants(&[true, true]), [0, 1, 2, 3].map(ChartSet));
/// assert_eq!(chart_variants(&[true, false, true]), [0, 1, 4, 5].map(ChartSet));
/// assert_eq!(chart_variants(&[true; 3]), [0, 1, 2, 4].map(ChartSet));
/// ```
pub fn chart_variants(switchable: &[bool]) -> Vec<ChartSet> {
    let bits: Vec<u32> = switchable
        .iter()
        .take(MAX_SPHERICAL_JOINTS)
        .enumerate()
        .filter(|&(_, &s)| s)
        .map(|(j, _)| 1u32 << j)
        .collect();
    if bits.len() <= MAX_ALL_CHARTS {
        // Every subset, by counting through the masks of the chosen bits.
        (0u32..(1 << bits.len()))
            .map(|subset| {
                let set = bits
                    .iter()
                    .enumerate()
                    .filter(|&(k, _)| subset & (1 << k) != 0)
                    .fold(0, |acc, (_, &b)| acc | b);
                ChartSet(set)
            })
            .collect()
    } else {
        std::iter::once(ChartSet::DECLARED)
            .chain(bits.into_iter().map(ChartSet))
            .collect()
    }
}

/// `scene` with every spherical (or free) joint switched in `charts` turned to its partner
/// sequence (the scene is data: nothing else changes, so deriving the copy gives that
/// chart's equations).
pub fn scene_in_charts(scene: &MechanismScene, charts: ChartSet) -> MechanismScene {
    let mut out = scene.clone();
    let mut j = 0;
    for body in &mut out.bodies {
        if let JointKind::Spherical { sequence } | JointKind::Free { sequence } =
            &mut body.joint.kind
        {
            *sequence = charts.sequence(j, *sequence);
            j += 1;
        }
    }
    out
}

/// The ODE of a mechanism in each of its chart sets, over the state `[q, q̇]` of `S = 2n`
/// numbers: what [`ChartedMechanism`] integrates. Implemented by the run-time
/// [`MechanismCharts`] and by `#[derive(Mechanism)]` for mechanisms with spherical joints.
pub trait ChartedDynamics<const S: usize> {
    /// The number of coordinates n (the state has 2n entries).
    fn dof(&self) -> usize;

    /// The spherical joints, in body order.
    fn spherical_joints(&self) -> Vec<SphericalJoint>;

    /// Whether the equations of `charts` are available ([`chart_variants`]).
    fn has_charts(&self, charts: ChartSet) -> bool;

    /// d[q, q̇]/dt in the chart set `charts`, unchecked (NaN at a singular mass matrix or
    /// for a chart set that is not available).
    fn rhs_in(&self, charts: ChartSet, t: f64, y: &[f64; S], dydt: &mut [f64; S]);

    /// The energy T + V at the state `y` of the chart set `charts` (NaN for a chart set that
    /// is not available).
    fn energy_in(&self, charts: ChartSet, t: f64, y: &[f64; S]) -> f64;

    /// Checks the parameters read from fields (as
    /// [`MechanismDynamics::check_parameters`](super::MechanismDynamics::check_parameters)
    /// does), once, when [`ChartedMechanism::new`] starts or the driver restarts. The derive
    /// overrides it; a run-time [`MechanismCharts`] checks its values when built.
    ///
    /// # Errors
    /// [`MechanismError::NonFiniteParameter`], [`MechanismError::NegativeParameter`],
    /// [`MechanismError::Part`].
    fn check_parameters(&self) -> Result<(), MechanismError> {
        Ok(())
    }
}

impl<const S: usize, D: ChartedDynamics<S> + ?Sized> ChartedDynamics<S> for &D {
    fn dof(&self) -> usize {
        (**self).dof()
    }
    fn spherical_joints(&self) -> Vec<SphericalJoint> {
        (**self).spherical_joints()
    }
    fn has_charts(&self, charts: ChartSet) -> bool {
        (**self).has_charts(charts)
    }
    fn rhs_in(&self, charts: ChartSet, t: f64, y: &[f64; S], dydt: &mut [f64; S]) {
        (**self).rhs_in(charts, t, y, dydt)
    }
    fn energy_in(&self, charts: ChartSet, t: f64, y: &[f64; S]) -> f64 {
        (**self).energy_in(charts, t, y)
    }
    fn check_parameters(&self) -> Result<(), MechanismError> {
        (**self).check_parameters()
    }
}
