//! The run-time checks of a mechanism's values made of parameters, by the rules literals
//! meet at compile time: shared by the interpreted [`super::MechanismModel`] and
//! [`super::rolling::RollingModel`].

use super::error::MechanismError;
use super::rules::{check_axis, check_universal_axes};
use super::scene::{JointKind, MechanismScene};
use crate::body::{BodyError, Definiteness, check_inertia};
use crate::codegen::{Bindings, Program};
use crate::sym::{Arena, ExprId, SymbolKind};

/// Lowered programs for every axis, mass, inertia (and extra lengths that must not be
/// negative, such as a wheel's radius) that reads a parameter.
#[derive(Debug)]
pub(crate) struct ParameterChecks {
    /// Outputs: the components of the axes of every joint whose axes read a parameter (three
    /// per axis), named by `axis_joints` with whether the joint is universal (two axes).
    axes: Program,
    axis_joints: Vec<(String, bool)>,
    /// Outputs: the mass and the nine inertia entries of every body whose mass properties
    /// read a parameter, named by `mass_bodies`.
    mass_properties: Program,
    mass_bodies: Vec<String>,
    /// Outputs: lengths that must be finite and not negative, named by `length_names`
    /// (owner, quantity).
    lengths: Program,
    length_names: Vec<(String, String)>,
}

impl ParameterChecks {
    /// No checks.
    pub(crate) fn none(arena: &Arena) -> ParameterChecks {
        ParameterChecks {
            axes: Program::lower(arena, &[]),
            axis_joints: Vec::new(),
            mass_properties: Program::lower(arena, &[]),
            mass_bodies: Vec::new(),
            lengths: Program::lower(arena, &[]),
            length_names: Vec::new(),
        }
    }

    /// The checks of `scene` and of `lengths` ((owner, quantity), expression), reading only
    /// the parameters in `known` (those a model binds: an inertia the motion never reads,
    /// such as a hinge's moments across its axis, has no values to check).
    pub(crate) fn new(
        arena: &Arena,
        scene: &MechanismScene,
        lengths: &[((String, String), ExprId)],
        known: &[String],
    ) -> ParameterChecks {
        let bound = |e: ExprId| {
            arena.free_symbols(e).iter().all(|&s| {
                let symbol = arena.symbol(s);
                symbol.kind != SymbolKind::Parameter || known.contains(&symbol.name)
            })
        };
        let constant = |e: &ExprId| arena.as_rational(*e).is_some();
        let mut components = Vec::new();
        let mut axis_joints = Vec::new();
        for body in &scene.bodies {
            let (axes, universal): (&[[ExprId; 3]], bool) = match &body.joint.kind {
                JointKind::Revolute { axis } | JointKind::Prismatic { axis } => {
                    (std::slice::from_ref(axis), false)
                }
                JointKind::Universal { axes } => (axes, true),
                JointKind::Spherical { .. } | JointKind::Free { .. } => (&[], false),
            };
            // Constant axes met the same rules in `MechanismScene::validate`.
            if axes.iter().flatten().all(constant) {
                continue;
            }
            components.extend(axes.iter().flatten());
            axis_joints.push((body.joint.name.clone(), universal));
        }
        let zero = arena.zero();
        let mut properties = Vec::new();
        let mut mass_bodies = Vec::new();
        for body in &scene.bodies {
            let mut entries: Vec<ExprId> = std::iter::once(body.mass)
                .chain(body.inertia.iter().flatten().copied())
                .collect();
            if entries.iter().all(constant) {
                continue;
            }
            if !bound(entries[0]) {
                entries[0] = zero;
            }
            if !entries[1..].iter().all(|&e| bound(e)) {
                entries[1..].fill(zero);
            }
            properties.extend(entries);
            mass_bodies.push(body.name.clone());
        }
        let (length_names, length_exprs): (Vec<_>, Vec<_>) = lengths
            .iter()
            .filter(|(_, e)| !constant(e) && bound(*e))
            .cloned()
            .unzip();
        ParameterChecks {
            axes: Program::lower(arena, &components),
            axis_joints,
            mass_properties: Program::lower(arena, &properties),
            mass_bodies,
            lengths: Program::lower(arena, &length_exprs),
            length_names,
        }
    }

    /// Every axis made of parameters has a length, every mass and listed length made of
    /// parameters is finite and not negative, and every inertia made of parameters is
    /// finite and symmetric, with principal moments that are not negative and meet the
    /// triangle inequality I1 + I2 ≥ I3 (zero moments stay allowed: point masses and thin
    /// rods have them, and a body with no inertia at all is the singular mass matrix's
    /// concern).
    ///
    /// # Errors
    /// [`MechanismError::ZeroAxis`], [`MechanismError::ParallelAxes`],
    /// [`MechanismError::NonFiniteParameter`], [`MechanismError::NegativeParameter`],
    /// [`MechanismError::Part`].
    pub(crate) fn check(&self, bindings: &Bindings) -> Result<(), MechanismError> {
        self.check_axes(bindings)?;
        let mut out = vec![0.0; 10 * self.mass_bodies.len()];
        bindings.eval(&self.mass_properties, [], &mut out);
        for (body, values) in self.mass_bodies.iter().zip(out.chunks_exact(10)) {
            not_negative(format!("body `{body}`"), "mass", values[0])?;
            body_inertia(&values[1..]).map_err(|error| MechanismError::Part {
                body: body.clone(),
                error,
            })?;
        }
        let mut out = vec![0.0; self.length_names.len()];
        bindings.eval(&self.lengths, [], &mut out);
        for ((owner, quantity), &value) in self.length_names.iter().zip(&out) {
            not_negative(owner.clone(), quantity, value)?;
        }
        Ok(())
    }

    fn check_axes(&self, bindings: &Bindings) -> Result<(), MechanismError> {
        let mut out = vec![0.0; self.axes.outputs().len()];
        bindings.eval(&self.axes, [], &mut out);
        let mut values = out.chunks_exact(3).map(|c| [c[0], c[1], c[2]]);
        for (joint, universal) in &self.axis_joints {
            let mut next = || values.next().unwrap_or([f64::NAN; 3]);
            if *universal {
                let (outer, inner) = (next(), next());
                check_universal_axes(joint, outer, inner)?;
            } else {
                check_axis(joint, "axis", next())?;
            }
        }
        Ok(())
    }
}

fn not_negative(owner: String, quantity: &str, value: f64) -> Result<(), MechanismError> {
    if !value.is_finite() {
        return Err(MechanismError::NonFiniteParameter {
            owner,
            quantity: quantity.into(),
            value,
        });
    }
    if value < 0.0 {
        return Err(MechanismError::NegativeParameter {
            owner,
            quantity: quantity.into(),
            value,
        });
    }
    Ok(())
}

/// A body's inertia about its centre (row-major `entries`), under the body language's one
/// rule ([`check_inertia`]) with zero moments allowed: the tensor is the body's sum of parts,
/// so errors number part 0.
fn body_inertia(entries: &[f64]) -> Result<(), BodyError> {
    let row =
        |i: usize| std::array::from_fn(|j| entries.get(3 * i + j).copied().unwrap_or(f64::NAN));
    check_inertia(0, &[row(0), row(1), row(2)], Definiteness::SemiPositive)
}
