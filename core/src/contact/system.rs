//! A body on a table as the system the steppers take: one phase of its contact as an ODE on
//! the state array, with what the run loop's hooks read of the body ([`super::phases`]).

use nalgebra::Matrix3;

use super::dynamics::ContactDynamics;
use super::error::ContactError;
use super::scene::{LawKind, Phase};
use super::state::STATE_LEN;
use super::surface::SurfaceKind;
use crate::ode::{OdeError, System};

/// One phase of a body on a table as an ODE system on the state array of
/// [`super::layout`], for any stepper, and as the hooks of the run loop
/// ([`crate::ode::Hybrid`]): the phase is its mode; lift-off, the friction cone, the slip
/// stopping, Painlevé's paradox, the support map's limit, a spin that pivoting friction
/// stops and a held spin breaking loose are its witnesses.
#[derive(Debug)]
pub struct ContactSystem<'a, D: ?Sized> {
    /// The body.
    pub body: &'a D,
    /// The phase whose equations are integrated.
    pub phase: Phase,
    /// Whether the spin about the vertical is held at zero by pivoting friction (the
    /// phase's equations with ω̇·γ = 0 and a pivot couple, see [`super::held_spin`]).
    pub spin_held: bool,
    /// What the hooks need of the body, read once.
    pub(crate) watch: Watch,
}

/// What the run loop's hooks read of a body: its law, its mass properties and the
/// coefficient of its friction, read once when the run starts (the body is immutable while
/// it runs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Watch {
    pub(crate) law: LawKind,
    pub(crate) surface: SurfaceKind,
    /// μ of a Coulomb or stick–slip law.
    pub(crate) mu: Option<f64>,
    /// μ of the normal-force-scaled viscous law F = −μ N u.
    pub(crate) normal_viscous: Option<f64>,
    /// ℓ_p of the pivoting friction −ℓ_p N sign(ω·γ) γ.
    pub(crate) pivoting: Option<f64>,
    pub(crate) mass: f64,
    /// The inverse of the inertia about the centre of mass, description axes.
    pub(crate) inertia_inv: Matrix3<f64>,
    pub(crate) gravity: f64,
    /// The stepper's tolerances (atol, rtol), zero unless the run sets them
    /// ([`ContactSystem::resolving`]): a slip or a spin the stepper cannot resolve is taken
    /// as zero, see [`super::phases::stick_speed`].
    pub(crate) resolution: (f64, f64),
}

impl Watch {
    /// The smallest speed the stepper resolves at the scale `scale`: atol + rtol·scale.
    pub(crate) fn resolved(&self, scale: f64) -> f64 {
        self.resolution.0 + self.resolution.1 * scale
    }
}

impl<'a, D: ContactDynamics + ?Sized> ContactSystem<'a, D> {
    /// `body` in `phase`.
    ///
    /// # Errors
    /// As [`ContactDynamics::check_parameters`] (a body whose inertia cannot be inverted
    /// fails there).
    pub fn new(body: &'a D, phase: Phase) -> Result<Self, ContactError> {
        body.check_parameters()?;
        let v = body.values();
        let inertia = Matrix3::from_fn(|i, j| v.inertia[i][j]);
        let inertia_inv = inertia.try_inverse().ok_or(ContactError::BadParameter {
            name: "inertia",
            value: inertia.determinant(),
            rule: "invertible (its determinant is this)",
        })?;
        let coefficient = |name: &str| {
            v.coefficients
                .iter()
                .find(|(n, _)| *n == name)
                .map(|&(_, c)| c)
        };
        let watch = Watch {
            law: body.law(),
            surface: body.surface_kind(),
            mu: body.friction_coefficient(),
            normal_viscous: coefficient("normal_viscous"),
            pivoting: coefficient("pivoting"),
            mass: v.mass,
            inertia_inv,
            gravity: v.gravity,
            resolution: (0.0, 0.0),
        };
        Ok(ContactSystem {
            body,
            phase,
            spin_held: false,
            watch,
        })
    }

    /// The system integrated by a stepper with these tolerances: a slip or a spin below what
    /// the stepper resolves (atol + rtol × the velocity scale) is taken as zero. Without
    /// this, a Coulomb slip that should stop chatters about zero at the tolerance's size, the
    /// friction reversing from step to step, and the steps shrink to that size: an eccentric
    /// sphere at tol 10⁻⁷ took 10⁵ steps for 0.02 s. [`super::ContactRun`] sets its stepper's
    /// tolerances; a run built by hand over this system (`ode::Hybrid` over a stepper of
    /// it) should set the same.
    pub fn resolving(mut self, atol: f64, rtol: f64) -> Self {
        self.watch.resolution = (atol, rtol);
        self
    }
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
        if self.spin_held {
            let pivoting = self.watch.pivoting.unwrap_or(0.0);
            *dydt = super::pivot::held(self.body, pivoting, self.phase, t, y).rates;
        } else {
            self.body.phase_rhs(self.phase, t, y, dydt);
        }
    }

    /// The body's [`ContactDynamics::check_parameters`], so that any run over a body on a
    /// table refuses an unphysical one before its first step.
    fn check_parameters(&self) -> Result<(), OdeError> {
        self.body
            .check_parameters()
            .map_err(ContactError::into_ode_error)
    }
}
