//! A derived mechanism evaluated at run time through the code generator's interpreter: the
//! path for mechanisms built without the macro, and the reference the tests use.

use super::derivation::{MechanismDerivation, Route};
use super::error::MechanismError;
use super::scene::MechanismScene;
use crate::codegen::{BindingError, Bindings, Program, check_distinct, with_workspace};
use crate::sym::{Arena, ExprId, SymbolId};

use super::checks::ParameterChecks;

/// A mechanism's q̈, pivots, energy and momenta, lowered once and interpreted.
///
/// Parameters are bound by name ([`MechanismModel::set`] changes one). The state is q and q̇
/// in [`MechanismScene::coordinate_names`] order; [`MechanismModel::system`] adapts the
/// model to the steppers of [`crate::ode`] over `[q, q̇]`.
///
/// # Examples
///
/// Two unit point masses on massless unit rods hinged about x, hanging straight down at
/// rest: an equilibrium (q̈ = 0) with energy E = V = −Σ m g·r = −(1 + 2) g for gravity
/// g ẑ, g = −9.81.
///
/// ```
/// use approx::assert_relative_eq;
/// use precess_core::mechanism::{JointKind, MechanismModel, MechanismScene, Parent, Route};
/// use precess_core::sym::Arena;
/// let mut a = Arena::new();
/// let (o, z) = (a.one(), a.zero());
/// let down = a.integer(-1);
/// let hinge = JointKind::Revolute { axis: [o, z, z] };
/// let mut scene = MechanismScene::new();
/// for (i, parent) in [Parent::Ground, Parent::Body(0)].into_iter().enumerate() {
///     let mut b = MechanismScene::body(&mut a, &format!("rod{i}"), parent, hinge.clone(),
///         &[&format!("theta{i}")]);
///     b.mass = o;
///     b.center = [z, z, down];
///     if i == 1 { b.joint.at = [z, z, down]; }
///     scene.bodies.push(b);
/// }
/// scene.gravity = Some([z, z, a.parameter("g")]);
/// let model = MechanismModel::new(&mut a, &scene, Route::Auto, &[("g", -9.81)])?;
/// // Hanging straight down and at rest: V = −m g z summed = 9.81·(−1) + 9.81·(−2).
/// assert_relative_eq!(model.energy(0.0, &[0.0, 0.0], &[0.0, 0.0])?, -3.0 * 9.81, epsilon = 1e-12);
/// assert_eq!(model.accelerations(0.0, &[0.0, 0.0], &[0.0, 0.0])?, vec![0.0, 0.0]);
/// # Ok::<(), precess_core::mechanism::MechanismError>(())
/// ```
#[derive(Debug)]
pub struct MechanismModel {
    /// Outputs: the pivots, then q̈.
    accel: Program,
    pivot_count: usize,
    /// Outputs: T, V, E, power.
    energy: Program,
    /// Outputs: the conserved momenta.
    momenta: Program,
    cyclic: Vec<usize>,
    /// The checks of the values made of parameters (axes, masses, inertias).
    checks: ParameterChecks,
    q: Vec<SymbolId>,
    rates: Vec<SymbolId>,
    time: SymbolId,
    route: Route,
    bindings: Bindings,
    /// The value of each parameter bound, so a refused [`MechanismModel::set`] can put the
    /// previous one back.
    values: Vec<(String, f64)>,
}

/// Each name once: a name given twice would bind its last value silently. The rule is the
/// bindings' own; the mechanism reports it in its own variant, as it always has.
fn distinct(parameters: &[(&str, f64)]) -> Result<(), MechanismError> {
    check_distinct(parameters).map_err(|e| match e {
        BindingError::DuplicateParameter {
            name,
            first,
            second,
        } => MechanismError::DuplicateParameter {
            name,
            first,
            second,
        },
        other => other.into(),
    })
}

fn symbol(arena: &Arena, e: ExprId) -> Result<SymbolId, MechanismError> {
    arena.as_symbol(e).ok_or(MechanismError::RouteUnavailable {
        route: "interpreted",
        reason: "a coordinate or the time is not a symbol",
    })
}

impl MechanismModel {
    /// Derives `scene` by `route` and lowers it with a value for each parameter
    /// (`(name, value)` pairs), checking every value made of parameters by the rules
    /// constants meet (see [`MechanismModel::set`]).
    ///
    /// # Errors
    /// [`MechanismError::DuplicateParameter`] for a name given twice (before deriving); as
    /// [`MechanismScene::derive`] and [`MechanismModel::from_derivation`];
    /// [`MechanismError::ZeroAxis`] for an axis with no direction and
    /// [`MechanismError::ParallelAxes`] for a universal joint's parallel axes at the values
    /// given ([`crate::mechanism::check_universal_axes`]);
    /// [`MechanismError::NonFiniteParameter`] or [`MechanismError::NegativeParameter`] for a
    /// mass, [`MechanismError::Part`] for an inertia, made of parameters, that no body can
    /// have (see [`MechanismModel::set`]).
    pub fn new(
        arena: &mut Arena,
        scene: &MechanismScene,
        route: Route,
        parameters: &[(&str, f64)],
    ) -> Result<MechanismModel, MechanismError> {
        distinct(parameters)?;
        let derivation = scene.derive(arena, route)?;
        let mut model = Self::from_derivation(arena, &derivation, parameters)?;
        // Mass properties from parameters get the checks literal parts get at compile time.
        model.checks = ParameterChecks::new(arena, scene, &[], &derivation.parameters(arena));
        model.check_parameters()?;
        Ok(model)
    }

    /// Lowers a derivation with a value for each parameter it reads.
    ///
    /// # Errors
    /// [`MechanismError::DuplicateParameter`] for a name given twice;
    /// [`MechanismError::Binding`] for a parameter left out, an unknown name, a non-finite
    /// value, or a user function's input (which the interpreter cannot supply).
    pub fn from_derivation(
        arena: &Arena,
        d: &MechanismDerivation,
        parameters: &[(&str, f64)],
    ) -> Result<MechanismModel, MechanismError> {
        distinct(parameters)?;
        let c = &d.coordinates;
        let q =
            c.q.iter()
                .map(|&e| symbol(arena, e))
                .collect::<Result<Vec<_>, _>>()?;
        let rates = c
            .rates
            .iter()
            .map(|&e| symbol(arena, e))
            .collect::<Result<Vec<_>, _>>()?;
        let time = symbol(arena, d.time)?;
        let outputs: Vec<ExprId> = d.pivots.iter().chain(&d.accelerations).copied().collect();
        let accel = Program::lower(arena, &outputs);
        let energy = Program::lower(arena, &[d.kinetic, d.potential, d.energy, d.power]);
        let momenta: Vec<ExprId> = d.conserved_momenta.iter().map(|&(_, p)| p).collect();
        let momenta = Program::lower(arena, &momenta);
        let mut supplied: Vec<SymbolId> = q.iter().chain(&rates).copied().collect();
        supplied.push(time);
        let programs = [accel, energy, momenta];
        let bindings = Bindings::new(arena, &programs, &supplied, parameters)?;
        let [accel, energy, momenta] = programs;
        Ok(MechanismModel {
            accel,
            pivot_count: d.pivots.len(),
            energy,
            momenta,
            cyclic: d.conserved_momenta.iter().map(|&(i, _)| i).collect(),
            checks: ParameterChecks::none(arena),
            q,
            rates,
            time,
            route: d.route,
            values: parameters
                .iter()
                .map(|&(name, value)| (name.to_owned(), value))
                .collect(),
            bindings,
        })
    }

    /// The checks of [`MechanismModel::new`] and [`MechanismModel::set`]
    /// (`checks.rs`).
    pub(super) fn check_parameters(&self) -> Result<(), MechanismError> {
        self.checks.check(&self.bindings)
    }

    /// The number of coordinates n.
    pub fn dof(&self) -> usize {
        self.q.len()
    }

    /// The route the derivation took.
    pub fn route(&self) -> Route {
        self.route
    }

    /// The operation count of the program computing the pivots and q̈.
    pub fn op_count(&self) -> crate::codegen::OpCount {
        self.accel.op_count()
    }

    /// The names of the parameters the model reads, in alphabetical order.
    pub fn parameters(&self) -> impl ExactSizeIterator<Item = &str> + '_ {
        self.bindings.parameters()
    }

    /// Sets the parameter `name`.
    ///
    /// # Errors
    /// [`MechanismError::Binding`] for an unknown name or a non-finite value;
    /// [`MechanismError::ZeroAxis`] if an axis loses its direction,
    /// [`MechanismError::ParallelAxes`] if a universal joint's axes become parallel,
    /// [`MechanismError::NegativeParameter`] if a mass becomes negative (non-finite:
    /// [`MechanismError::NonFiniteParameter`]), [`MechanismError::Part`] if an inertia
    /// becomes non-finite, asymmetric, has a negative principal moment or breaks
    /// I1 + I2 ≥ I3. After an error the model is as it was: the previous value is kept, so
    /// later errors still name their own cause.
    pub fn set(&mut self, name: &str, value: f64) -> Result<&mut Self, MechanismError> {
        self.bindings.set(name, value)?;
        let slot = self.values.iter().position(|(n, _)| n == name);
        if let Err(e) = self.check_parameters() {
            if let Some(&(_, previous)) = slot.and_then(|i| self.values.get(i)) {
                // Known and finite: it was bound before.
                self.bindings.set(name, previous)?;
            }
            return Err(e);
        }
        if let Some((_, v)) = slot.and_then(|i| self.values.get_mut(i)) {
            *v = value;
        }
        Ok(self)
    }

    fn check_state(&self, t: f64, q: &[f64], qdot: &[f64]) -> Result<(), MechanismError> {
        let n = self.dof();
        for (quantity, v) in [("q", q), ("q̇", qdot)] {
            if v.len() != n {
                return Err(MechanismError::StateLength {
                    quantity,
                    expected: n,
                    got: v.len(),
                });
            }
            if !v.iter().all(|x| x.is_finite()) {
                return Err(MechanismError::NonFinite {
                    quantity,
                    values: v.to_vec(),
                });
            }
        }
        if !t.is_finite() {
            return Err(MechanismError::NonFinite {
                quantity: "t",
                values: vec![t],
            });
        }
        Ok(())
    }

    fn run(&self, program: &Program, t: f64, q: &[f64], qdot: &[f64], out: &mut [f64]) {
        self.bindings.eval(program, self.inputs(t, q, qdot), out);
    }

    /// The per-call inputs: the state and time by symbol.
    fn inputs<'s>(
        &'s self,
        t: f64,
        q: &'s [f64],
        qdot: &'s [f64],
    ) -> impl Iterator<Item = (SymbolId, f64)> + 's {
        let state = self
            .q
            .iter()
            .zip(q)
            .chain(self.rates.iter().zip(qdot))
            .map(|(&s, &v)| (s, v));
        state.chain(std::iter::once((self.time, t)))
    }

    /// q̈ at time t and state (q, q̇).
    ///
    /// # Errors
    /// [`MechanismError::StateLength`] or [`MechanismError::NonFinite`] for a bad state;
    /// [`MechanismError::SingularMassMatrix`] when a pivot is not positive (a massless chain,
    /// or a configuration where M degenerates); [`MechanismError::NonFinite`] if q̈ overflows.
    pub fn accelerations(
        &self,
        t: f64,
        q: &[f64],
        qdot: &[f64],
    ) -> Result<Vec<f64>, MechanismError> {
        self.check_state(t, q, qdot)?;
        let mut out = vec![0.0; self.pivot_count + self.dof()];
        self.run(&self.accel, t, q, qdot, &mut out);
        let (pivots, qdd) = out.split_at(self.pivot_count);
        if let Some((pivot, &value)) = pivots
            .iter()
            .enumerate()
            .find(|&(_, &p)| p.is_nan() || p <= 0.0)
        {
            return Err(MechanismError::SingularMassMatrix { pivot, value });
        }
        if !qdd.iter().all(|x| x.is_finite()) {
            return Err(MechanismError::NonFinite {
                quantity: "q̈",
                values: qdd.to_vec(),
            });
        }
        Ok(qdd.to_vec())
    }

    fn energies(&self, t: f64, q: &[f64], qdot: &[f64]) -> Result<[f64; 4], MechanismError> {
        self.check_state(t, q, qdot)?;
        let mut out = [0.0; 4];
        self.run(&self.energy, t, q, qdot, &mut out);
        Ok(out)
    }

    /// The energy E = T + V (gravity and springs in V).
    ///
    /// # Errors
    /// As the state checks of [`MechanismModel::accelerations`].
    pub fn energy(&self, t: f64, q: &[f64], qdot: &[f64]) -> Result<f64, MechanismError> {
        Ok(self.energies(t, q, qdot)?[2])
    }

    /// The kinetic energy T.
    ///
    /// # Errors
    /// As the state checks of [`MechanismModel::accelerations`].
    pub fn kinetic(&self, t: f64, q: &[f64], qdot: &[f64]) -> Result<f64, MechanismError> {
        Ok(self.energies(t, q, qdot)?[0])
    }

    /// dE/dt from the non-conservative loads, Σ Q_i q̇_i.
    ///
    /// # Errors
    /// As the state checks of [`MechanismModel::accelerations`].
    pub fn power(&self, t: f64, q: &[f64], qdot: &[f64]) -> Result<f64, MechanismError> {
        Ok(self.energies(t, q, qdot)?[3])
    }

    /// `(i, p_i)` for each conserved momentum of a cyclic coordinate.
    ///
    /// # Errors
    /// As the state checks of [`MechanismModel::accelerations`].
    pub fn conserved_momenta(
        &self,
        t: f64,
        q: &[f64],
        qdot: &[f64],
    ) -> Result<Vec<(usize, f64)>, MechanismError> {
        self.check_state(t, q, qdot)?;
        let mut out = vec![0.0; self.cyclic.len()];
        self.run(&self.momenta, t, q, qdot, &mut out);
        Ok(self.cyclic.iter().copied().zip(out).collect())
    }

    /// q̈ into `accelerations` (n entries), unchecked: the steppers' inner loop, where a
    /// singular M gives NaN, which the adaptive drivers reject. The outputs (pivots, then
    /// q̈) are a run-time number long: they go through the thread's workspace, so the model
    /// stays shareable and the call allocation-free.
    pub(super) fn accelerations_into(
        &self,
        t: f64,
        q: &[f64],
        qdot: &[f64],
        accelerations: &mut [f64],
    ) {
        with_workspace(|ws| {
            let out = self
                .bindings
                .eval_to(ws, &self.accel, self.inputs(t, q, qdot));
            for (a, &v) in accelerations
                .iter_mut()
                .zip(out.iter().skip(self.pivot_count))
            {
                *a = v;
            }
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::{About, BodyError, Part, Shape, check_part};
    use crate::mechanism::JointKind;
    use crate::mechanism::Parent;
    use crate::rigid::AngleSequence;

    /// The tensor with principal moments (1, 1, 2 + ε), the largest about (0, 1, 1)/√2, so
    /// its largest entry is 1.5 + ε/2 < I3: a relative tolerance taken of the largest entry
    /// and one taken of I3 draw the triangle inequality's border at different ε.
    fn tilted(eps: f64) -> [[f64; 3]; 3] {
        let (d, c) = (1.5 + eps / 2.0, 0.5 + eps / 2.0);
        [[1.0, 0.0, 0.0], [0.0, d, c], [0.0, c, d]]
    }

    /// Whether a mechanism body (on a ball joint, so every entry is read) with the tensor of
    /// parameters `d`, `c` is accepted by the interpreted model.
    fn mechanism_accepts(t: &[[f64; 3]; 3]) -> bool {
        let mut a = Arena::new();
        let (o, z) = (a.one(), a.zero());
        let ball = JointKind::Spherical {
            sequence: AngleSequence::Zxz,
        };
        let mut bob = MechanismScene::body(&mut a, "bob", Parent::Ground, ball, &["p", "t", "s"]);
        let (d, c) = (a.parameter("d"), a.parameter("c"));
        bob.mass = o;
        bob.center = [z, z, a.integer(-1)];
        bob.inertia = [[o, z, z], [z, d, c], [z, c, d]];
        let mut scene = MechanismScene::new();
        scene.bodies.push(bob);
        let values = [("d", t[1][1]), ("c", t[1][2])];
        match MechanismModel::new(&mut a, &scene, Route::Auto, &values) {
            Ok(_) => true,
            Err(MechanismError::Part { error, .. }) => {
                assert!(matches!(error, BodyError::TriangleInequality { .. }));
                false
            }
            Err(e) => panic!("unexpected error {e}"),
        }
    }

    /// An explicit part of a body's description (a top's, a free body's) with the tensor.
    fn part_accepts(t: &[[f64; 3]; 3]) -> bool {
        let shape = Shape::Explicit {
            mass: 1.0,
            inertia: *t,
            about: About::Center,
        };
        check_part(0, &Part::new(shape, [0.0; 3])).is_ok()
    }

    /// The one inertia rule: a mechanism's body and a body's explicit part accept and refuse
    /// the same tensors at the triangle inequality's border, 1e-12 of the largest entry
    /// (1.5): ε = 1.25e-12 passes, ε = 1.75e-12 fails in both (when the body rule took the
    /// tolerance of I3 = 2, it passed ε = 1.75e-12 that the mechanism refused).
    #[test]
    fn scenes_share_the_inertia_border() {
        for (eps, accepted) in [
            (1.25e-12, true),
            (1.75e-12, false),
            (0.0, true),
            (1e-9, false),
        ] {
            let t = tilted(eps);
            assert_eq!(part_accepts(&t), accepted, "explicit part, ε = {eps:e}");
            assert_eq!(
                mechanism_accepts(&t),
                accepted,
                "mechanism body, ε = {eps:e}"
            );
        }
    }
}
