//! A body on a table as the system the steppers take: one phase of its contact as an ODE on
//! the state array.

use super::dynamics::{ContactDynamics, Phase};
use super::state::STATE_LEN;
use crate::ode::System;

/// One phase of a body on a table as an ODE system on the state array of
/// [`super::layout`], for the adaptive pairs and RK4.
#[derive(Debug)]
pub struct ContactSystem<'a, D: ?Sized> {
    /// The body.
    pub body: &'a D,
    /// The phase whose equations are integrated.
    pub phase: Phase,
}

impl<D: ?Sized> Clone for ContactSystem<'_, D> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<D: ?Sized> Copy for ContactSystem<'_, D> {}

impl<D: ContactDynamics + ?Sized> System<STATE_LEN> for ContactSystem<'_, D> {
    #[inline]
    fn rhs(&self, t: f64, y: &[f64; STATE_LEN], dydt: &mut [f64; STATE_LEN]) {
        self.body.phase_rhs(self.phase, t, y, dydt);
    }
}
