//! A [`MechanismModel`] as the system the steppers take: its ODE `(q, q̇)' = (q̇, q̈)` over
//! the state array `[q, q̇]`, with the model's parameter checks as the run's first hook.

use super::error::MechanismError;
use super::interpreted::MechanismModel;
use crate::ode::{OdeError, System};

impl MechanismModel {
    /// The model as an ODE system over `[q, q̇]` with `N = 2n` entries.
    ///
    /// # Errors
    /// [`MechanismError::StateLength`] if N ≠ 2n.
    pub fn system<const N: usize>(&self) -> Result<MechanismSystem<'_, N>, MechanismError> {
        if N != 2 * self.dof() {
            return Err(MechanismError::StateLength {
                quantity: "the ODE state",
                expected: 2 * self.dof(),
                got: N,
            });
        }
        Ok(MechanismSystem { model: self })
    }
}

/// A [`MechanismModel`] as an [`crate::ode::System`] over `[q, q̇]`: unchecked, for the
/// steppers' inner loop (a singular M gives NaN, which the adaptive drivers reject).
#[derive(Debug, Clone, Copy)]
pub struct MechanismSystem<'a, const N: usize> {
    model: &'a MechanismModel,
}

impl<const N: usize> System<N> for MechanismSystem<'_, N> {
    fn rhs(&self, t: f64, y: &[f64; N], dydt: &mut [f64; N]) {
        let n = self.model.dof();
        let (q, qdot) = y.split_at(n);
        let (rates, accelerations) = dydt.split_at_mut(n);
        rates.copy_from_slice(qdot);
        self.model.accelerations_into(t, q, qdot, accelerations);
    }

    /// The model's checks of its values ([`MechanismModel::set`] already refuses a bad one,
    /// so this holds for a model built through the API; it is the hook all the same).
    fn check_parameters(&self) -> Result<(), OdeError> {
        self.model
            .check_parameters()
            .map_err(MechanismError::into_ode_error)
    }
}
