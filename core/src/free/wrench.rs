//! A wrench a user function applies to a free body: force and torque together, each in the
//! frame its constructor names, so a contact model is evaluated once per state and its
//! torque is never converted between frames by hand.
//!
//! The derivation sees four parts, each three numbers: a force through the centre of mass
//! and a torque about it in space axes, and the same in description axes. Forces at points
//! are resolved into the space parts when the centre of mass is known ([`AppliedWrench::space_part`]).

use std::iter::Sum;
use std::ops::{Add, AddAssign};

use nalgebra::Vector3;

use super::error::FreeError;
use crate::sym::ExprId;

/// A force and a torque acting on a free body, in the frames their constructor names.
///
/// Frames (see `docs/conventions.md`): *space* axes are the fixed frame the centre of mass
/// `x` and the state's velocity live in; *description* axes are the body's own, where its
/// parts are placed (the attitude turns them into space axes). Every torque is about the
/// centre of mass. Wrenches add: a function may return the sum of several contacts.
///
/// | constructor | force | torque about the centre of mass |
/// | --- | --- | --- |
/// | [`AppliedWrench::space`] | F, space axes, through the centre of mass | τ, space axes |
/// | [`AppliedWrench::body`] | F, description axes, through the centre of mass | τ, description axes |
/// | [`AppliedWrench::at_point_space`] | F, space axes, at the point p (space coordinates) | (p − x) × F, formed by precess |
///
/// ```
/// use approx::assert_relative_eq;
/// use nalgebra::Vector3;
/// use precess_core::free::AppliedWrench;
///
/// // A force of 2 N along +x at 1 m above the centre of mass turns the body about +y.
/// let x = Vector3::new(0.0, 0.0, 5.0);
/// let w = AppliedWrench::at_point_space(Vector3::new(2.0, 0.0, 0.0), Vector3::new(0.0, 0.0, 6.0));
/// let (force, torque) = w.space_part(&x);
/// assert_eq!(force, Vector3::new(2.0, 0.0, 0.0));
/// assert_relative_eq!(torque, Vector3::new(0.0, 2.0, 0.0));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct AppliedWrench {
    /// Force through the centre of mass, space axes.
    force_space: Vector3<f64>,
    /// Torque about the centre of mass, space axes.
    torque_space: Vector3<f64>,
    /// Force through the centre of mass, description axes.
    force_description: Vector3<f64>,
    /// Torque about the centre of mass, description axes.
    torque_description: Vector3<f64>,
    /// Σ F of the forces at points, space axes.
    point_force: Vector3<f64>,
    /// Σ p × F of the forces at points, about the space origin: linear in the forces, so
    /// point forces add before the centre of mass is known.
    point_moment: Vector3<f64>,
}

impl AppliedWrench {
    /// No force and no torque.
    pub fn zero() -> AppliedWrench {
        AppliedWrench::default()
    }

    /// A force through the centre of mass and a torque about it, both in space axes.
    pub fn space(force: impl Into<Vector3<f64>>, torque: impl Into<Vector3<f64>>) -> AppliedWrench {
        AppliedWrench {
            force_space: force.into(),
            torque_space: torque.into(),
            ..AppliedWrench::default()
        }
    }

    /// A force through the centre of mass and a torque about it, both in description axes
    /// (the body's own axes, where its parts are placed): they turn with the body.
    pub fn body(force: impl Into<Vector3<f64>>, torque: impl Into<Vector3<f64>>) -> AppliedWrench {
        AppliedWrench {
            force_description: force.into(),
            torque_description: torque.into(),
            ..AppliedWrench::default()
        }
    }

    /// A force in space axes acting at the point `point`, given in space coordinates (a
    /// contact point on the ground, say): precess adds the torque (p − x) × F about the
    /// centre of mass x.
    pub fn at_point_space(
        force: impl Into<Vector3<f64>>,
        point: impl Into<Vector3<f64>>,
    ) -> AppliedWrench {
        let (force, point) = (force.into(), point.into());
        AppliedWrench {
            point_force: force,
            point_moment: point.cross(&force),
            ..AppliedWrench::default()
        }
    }

    /// The space-axes part with the centre of mass at `center` (space coordinates): the
    /// force through it (with the forces at points) and the torque about it, space axes.
    pub fn space_part(&self, center: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
        // Σ (pᵢ − x) × Fᵢ = Σ pᵢ × Fᵢ − x × Σ Fᵢ.
        let lever_torque = self.point_moment - center.cross(&self.point_force);
        (
            self.force_space + self.point_force,
            self.torque_space + lever_torque,
        )
    }

    /// The description-axes part: the force through the centre of mass and the torque
    /// about it, description axes.
    pub fn description_part(&self) -> (Vector3<f64>, Vector3<f64>) {
        (self.force_description, self.torque_description)
    }

    /// Checks every part is finite.
    ///
    /// # Errors
    /// [`FreeError::NonFiniteWrench`] naming the first part holding NaN or ±∞ (the
    /// space-axes force or torque, the description-axes force or torque, the force at a
    /// point or its moment).
    ///
    /// ```
    /// use nalgebra::Vector3;
    /// use precess_core::free::{AppliedWrench, FreeError};
    /// let w = AppliedWrench::body(Vector3::zeros(), Vector3::new(0.0, f64::NAN, 0.0));
    /// assert!(matches!(w.check(), Err(FreeError::NonFiniteWrench { part, .. }) if part.contains("torque")));
    /// ```
    pub fn check(&self) -> Result<(), FreeError> {
        let parts = [
            ("force, space axes", self.force_space),
            (
                "torque about the centre of mass, space axes",
                self.torque_space,
            ),
            ("force, description axes", self.force_description),
            (
                "torque about the centre of mass, description axes",
                self.torque_description,
            ),
            ("force at a point, space axes", self.point_force),
            ("moment of the forces at points", self.point_moment),
        ];
        match parts
            .into_iter()
            .find(|(_, v)| v.iter().any(|c| !c.is_finite()))
        {
            Some((part, v)) => Err(FreeError::NonFiniteWrench {
                part,
                values: [v.x, v.y, v.z],
            }),
            None => Ok(()),
        }
    }
}

impl Add for AppliedWrench {
    type Output = AppliedWrench;

    fn add(mut self, rhs: AppliedWrench) -> AppliedWrench {
        self += rhs;
        self
    }
}

impl AddAssign for AppliedWrench {
    fn add_assign(&mut self, rhs: AppliedWrench) {
        self.force_space += rhs.force_space;
        self.torque_space += rhs.torque_space;
        self.force_description += rhs.force_description;
        self.torque_description += rhs.torque_description;
        self.point_force += rhs.point_force;
        self.point_moment += rhs.point_moment;
    }
}

impl Sum for AppliedWrench {
    fn sum<I: Iterator<Item = AppliedWrench>>(iter: I) -> AppliedWrench {
        iter.fold(AppliedWrench::zero(), Add::add)
    }
}

/// A user wrench in a [`super::FreeScene`]: the four parts an [`AppliedWrench`] resolves
/// into, as input symbols supplied at run time (space parts from
/// [`AppliedWrench::space_part`], description parts from [`AppliedWrench::description_part`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WrenchInputs {
    /// Force through the centre of mass, space axes.
    pub force_space: [ExprId; 3],
    /// Torque about the centre of mass, space axes.
    pub torque_space: [ExprId; 3],
    /// Force through the centre of mass, description axes.
    pub force_description: [ExprId; 3],
    /// Torque about the centre of mass, description axes.
    pub torque_description: [ExprId; 3],
}

impl WrenchInputs {
    /// Twelve fresh input symbols named `{prefix}fs0` … `{prefix}td2`.
    pub fn new(arena: &mut crate::sym::Arena, prefix: &str) -> WrenchInputs {
        let mut part =
            |name: &str| std::array::from_fn(|k| arena.input(&format!("{prefix}{name}{k}")));
        WrenchInputs {
            force_space: part("fs"),
            torque_space: part("ts"),
            force_description: part("fd"),
            torque_description: part("td"),
        }
    }

    /// The twelve symbols in the order force space, torque space, force description,
    /// torque description.
    pub fn symbols(&self) -> [ExprId; 12] {
        let parts = [
            self.force_space,
            self.torque_space,
            self.force_description,
            self.torque_description,
        ];
        std::array::from_fn(|k| parts[k / 3][k % 3])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two forces at points sum to the same torque as each formed by hand, (pᵢ − x) × Fᵢ.
    #[test]
    fn point_forces_add_before_the_centre_is_known() {
        let x = Vector3::new(0.3, -1.2, 2.0);
        let (f1, p1) = (Vector3::new(1.0, 2.0, -3.0), Vector3::new(0.5, 0.1, 1.9));
        let (f2, p2) = (Vector3::new(-0.4, 0.0, 7.0), Vector3::new(0.2, -1.3, 2.4));
        let w = AppliedWrench::at_point_space(f1, p1) + AppliedWrench::at_point_space(f2, p2);
        let (f, t) = w.space_part(&x);
        let by_hand = (p1 - x).cross(&f1) + (p2 - x).cross(&f2);
        assert!((f - (f1 + f2)).norm() < 1e-15);
        assert!((t - by_hand).norm() < 1e-14, "{t} vs {by_hand}");
    }
}
