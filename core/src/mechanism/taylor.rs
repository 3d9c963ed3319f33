//! The Taylor recurrences of a mechanism at run time: its first-order system
//! `(q, q̇)' = (q̇, q̈)` decomposed into a [`TaylorTape`], the path for mechanisms built
//! without the macro and the reference the derive's `taylor = K` key is tested against.
//!
//! Every route lowers q̈ to straight-line arithmetic, sines and cosines of the coordinates
//! and divisions (the pivots of the recursive and factored routes, the determinant of the
//! symbolic one), all of which the tape has recurrences for.

use thiserror::Error;

use super::derivation::{MechanismDerivation, Route};
use super::error::MechanismError;
use super::scene::MechanismScene;
use crate::sym::{Arena, ExprId};
use crate::taylor::{TaylorError, TaylorTape};

/// Why a mechanism's Taylor recurrences could not be built.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MechanismTaylorError {
    /// The tape's dimension `S` is not twice the number of coordinates.
    #[error(
        "the Taylor state has {found} components, but the mechanism's [q, q̇] has {expected} ({coordinates} coordinates)"
    )]
    Dimension {
        /// `2n`, the length of [q, q̇].
        expected: usize,
        /// The `S` asked for.
        found: usize,
        /// The number of coordinates n.
        coordinates: usize,
    },
    /// The mechanism could not be derived.
    #[error(transparent)]
    Mechanism(#[from] MechanismError),
    /// The tape could not be built (an order out of range, a parameter unknown, unset or
    /// not finite, or a user function's input, whose derivatives the tape cannot know).
    #[error(transparent)]
    Taylor(#[from] TaylorError),
}

impl MechanismDerivation {
    /// The Taylor recurrences of `(q, q̇)' = (q̇, q̈)` over the state `[q, q̇]`
    /// (`S = 2n`), with a value for each parameter q̈ reads, up to `max_order`.
    ///
    /// # Errors
    /// [`MechanismTaylorError::Dimension`] if `S ≠ 2n`; [`MechanismTaylorError::Taylor`] for
    /// an order outside `1 ..= MAX_TAYLOR_ORDER`, a parameter unknown, unset or not finite,
    /// or a user function's input (an effort computed by a function has no recurrences).
    ///
    /// # Examples
    /// A pendulum of length l = 1 under g = 9.81 from q = 0, q̇ = 1: q̈ = −(g/l) sin q, so
    /// the coefficients are c₁ = q̇ = 1, c₂ = q̈/2 = 0 and c₃ = q⃛/6 = −g q̇/6.
    /// ```
    /// use approx::assert_relative_eq;
    /// use precess_core::mechanism::{JointKind, MechanismScene, Parent, Route};
    /// use precess_core::sym::Arena;
    /// use precess_core::taylor::TaylorSystem;
    /// let mut a = Arena::new();
    /// let (o, z) = (a.one(), a.zero());
    /// let down = a.integer(-1);
    /// let hinge = JointKind::Revolute { axis: [o, z, z] };
    /// let mut bob = MechanismScene::body(&mut a, "bob", Parent::Ground, hinge, &["theta"]);
    /// bob.mass = o;
    /// bob.center = [z, z, down];
    /// let mut scene = MechanismScene::new();
    /// scene.bodies.push(bob);
    /// scene.gravity = Some([z, z, a.parameter("g")]);
    /// let d = scene.derive(&mut a, Route::Auto)?;
    /// let tape = d.taylor_tape::<2>(&a, &[("g", -9.81)], 20)?;
    /// let mut c = [[0.0; 2]; 4];
    /// tape.coefficients(0.0, &[0.0, 1.0], 3, &mut c);
    /// assert_relative_eq!(c[1][0], 1.0);
    /// assert_relative_eq!(c[2][0], 0.0);
    /// assert_relative_eq!(c[3][0], -9.81 / 6.0, epsilon = 1e-12);
    /// # Ok::<(), precess_core::mechanism::MechanismTaylorError>(())
    /// ```
    pub fn taylor_tape<const S: usize>(
        &self,
        arena: &Arena,
        parameters: &[(&str, f64)],
        max_order: usize,
    ) -> Result<TaylorTape<S>, MechanismTaylorError> {
        let (state, rhs) = self.first_order::<S>()?;
        Ok(TaylorTape::new(
            arena,
            state,
            rhs,
            Some(self.time),
            parameters,
            max_order,
        )?)
    }

    /// The state `[q, q̇]` and right-hand side `(q̇, q̈)`, 2n expressions each.
    pub fn first_order_system(&self) -> (Vec<ExprId>, Vec<ExprId>) {
        let c = &self.coordinates;
        let state = c.q.iter().chain(&c.rates).copied().collect();
        let rhs = c.rates.iter().chain(&self.accelerations).copied().collect();
        (state, rhs)
    }

    /// The state `[q, q̇]` and right-hand side `(q̇, q̈)` as arrays of `S = 2n` expressions.
    ///
    /// # Errors
    /// [`MechanismTaylorError::Dimension`] if `S ≠ 2n`.
    pub fn first_order<const S: usize>(
        &self,
    ) -> Result<([ExprId; S], [ExprId; S]), MechanismTaylorError> {
        let c = &self.coordinates;
        let dimension = MechanismTaylorError::Dimension {
            expected: 2 * c.q.len(),
            found: S,
            coordinates: c.q.len(),
        };
        let (state, rhs) = self.first_order_system();
        let state: [ExprId; S] = state.try_into().map_err(|_| dimension.clone())?;
        let rhs: [ExprId; S] = rhs.try_into().map_err(|_| dimension)?;
        Ok((state, rhs))
    }
}

impl MechanismScene {
    /// Derives the mechanism by `route` and builds the Taylor recurrences of its
    /// first-order system over `[q, q̇]` ([`MechanismDerivation::taylor_tape`]).
    ///
    /// # Errors
    /// As [`MechanismScene::derive`] and [`MechanismDerivation::taylor_tape`].
    pub fn taylor_tape<const S: usize>(
        &self,
        arena: &mut Arena,
        route: Route,
        parameters: &[(&str, f64)],
        max_order: usize,
    ) -> Result<TaylorTape<S>, MechanismTaylorError> {
        self.derive(arena, route)?
            .taylor_tape(arena, parameters, max_order)
    }
}
