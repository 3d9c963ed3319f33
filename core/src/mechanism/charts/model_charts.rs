//! The run-time [`super::ChartedDynamics`]: one [`MechanismModel`] per chart set, each
//! derived from the scene with the switched joints' sequences swapped.

use super::{
    ChartSet, ChartedDynamics, MAX_SPHERICAL_JOINTS, SphericalJoint, chart_variants,
    scene_in_charts, spherical_joints,
};
use crate::mechanism::MechanismError;
use crate::mechanism::{MechanismModel, MechanismScene, Route};
use crate::sym::Arena;

/// A mechanism's run-time models in every chart set of [`chart_variants`], for
/// [`super::ChartedMechanism`].
///
/// # Examples
///
/// A pendulum on a spherical joint (a unit mass a unit length below the joint, I = 1 about
/// its centre, g = 1) has the equations of both of its charts; hanging straight down it is
/// at rest in either:
///
/// ```
/// use precess_core::mechanism::charts::{ChartSet, ChartedDynamics, MechanismCharts};
/// use precess_core::mechanism::{JointKind, MechanismScene, Parent, Route};
/// use precess_core::rigid::AngleSequence;
/// use precess_core::sym::Arena;
/// let mut a = Arena::new();
/// let (o, z) = (a.one(), a.zero());
/// let ball = JointKind::Spherical { sequence: AngleSequence::Zxz };
/// let mut bob = MechanismScene::body(&mut a, "bob", Parent::Ground, ball, &["phi", "theta", "psi"]);
/// bob.mass = o;
/// bob.center = [z, z, a.integer(-1)];
/// bob.inertia = [[o, z, z], [z, o, z], [z, z, o]];
/// let mut scene = MechanismScene::new();
/// scene.bodies.push(bob);
/// scene.gravity = Some([z, z, a.integer(-1)]);
/// let charts = MechanismCharts::new(&mut a, &scene, Route::Auto, &[])?;
/// assert!(charts.has_charts(ChartSet(1)));
/// let mut dydt = [1.0; 6];
/// // ZYX at zero angles: the bob straight down.
/// ChartedDynamics::<6>::rhs_in(&charts, ChartSet(1), 0.0, &[0.0; 6], &mut dydt);
/// assert_eq!(dydt, [0.0; 6]);
/// # Ok::<(), precess_core::mechanism::MechanismError>(())
/// ```
#[derive(Debug)]
pub struct MechanismCharts {
    joints: Vec<SphericalJoint>,
    models: Vec<(ChartSet, MechanismModel)>,
}

impl MechanismCharts {
    /// Derives `scene` by `route` in each of its chart sets and binds `parameters` in each.
    ///
    /// # Errors
    /// [`MechanismError::TooManyJoints`] past [`MAX_SPHERICAL_JOINTS`] spherical joints;
    /// as [`MechanismModel::new`].
    pub fn new(
        arena: &mut Arena,
        scene: &MechanismScene,
        route: Route,
        parameters: &[(&str, f64)],
    ) -> Result<MechanismCharts, MechanismError> {
        let joints = spherical_joints(scene);
        if joints.len() > MAX_SPHERICAL_JOINTS {
            return Err(MechanismError::TooManyJoints {
                count: joints.len(),
                max: MAX_SPHERICAL_JOINTS,
            });
        }
        let switchable: Vec<bool> = joints.iter().map(|j| j.switchable).collect();
        let models = chart_variants(&switchable)
            .into_iter()
            .map(|charts| {
                let variant = scene_in_charts(scene, charts);
                let model = MechanismModel::new(arena, &variant, route, parameters)?;
                Ok((charts, model))
            })
            .collect::<Result<Vec<_>, MechanismError>>()?;
        Ok(MechanismCharts { joints, models })
    }

    /// The model of the chart set `charts`, if it is one of [`chart_variants`].
    pub fn model(&self, charts: ChartSet) -> Option<&MechanismModel> {
        self.models
            .iter()
            .find(|(c, _)| *c == charts)
            .map(|(_, m)| m)
    }

    /// Whether the equations of `charts` are available ([`chart_variants`]).
    pub fn has_charts(&self, charts: ChartSet) -> bool {
        self.model(charts).is_some()
    }

    /// The spherical joints, in body order.
    pub fn spherical_joints(&self) -> &[SphericalJoint] {
        &self.joints
    }

    /// The number of coordinates n.
    pub fn dof(&self) -> usize {
        self.models.first().map_or(0, |(_, m)| m.dof())
    }

    /// Sets the parameter `name` in every chart's model.
    ///
    /// # Errors
    /// As [`MechanismModel::set`].
    pub fn set(&mut self, name: &str, value: f64) -> Result<&mut Self, MechanismError> {
        for (_, model) in &mut self.models {
            model.set(name, value)?;
        }
        Ok(self)
    }
}

impl<const S: usize> ChartedDynamics<S> for MechanismCharts {
    fn dof(&self) -> usize {
        MechanismCharts::dof(self)
    }

    fn spherical_joints(&self) -> Vec<SphericalJoint> {
        self.joints.clone()
    }

    fn has_charts(&self, charts: ChartSet) -> bool {
        MechanismCharts::has_charts(self, charts)
    }

    fn rhs_in(&self, charts: ChartSet, t: f64, y: &[f64; S], dydt: &mut [f64; S]) {
        match self.model(charts).map(|m| m.system::<S>()) {
            Some(Ok(system)) => crate::ode::System::rhs(&system, t, y, dydt),
            _ => dydt.fill(f64::NAN),
        }
    }

    fn energy_in(&self, charts: ChartSet, t: f64, y: &[f64; S]) -> f64 {
        let Some(model) = self.model(charts) else {
            return f64::NAN;
        };
        let (q, qdot) = y.split_at(S / 2);
        model.energy(t, q, qdot).unwrap_or(f64::NAN)
    }
}
