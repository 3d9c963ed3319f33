//! A derived top evaluated at run time through the code generator's interpreter, usable with
//! any stepper of [`crate::ode`]. The derive macro emits the same programs as compiled Rust;
//! this is the path for scenes built at run time and the reference the tests use.

use nalgebra::{Matrix3, Vector3};

use super::angle_chart::AngleChart;
use super::checks::checked_accelerations;
use super::derivation::TopDerivation;
use super::error::TopError;
#[cfg(doc)]
use crate::codegen::BindingError;
use crate::codegen::{Bindings, Program};
use crate::ode::System;
use crate::rigid::AngleSequence;
use crate::sym::{Arena, SymbolId};

/// A top's angle-form equations, lowered once and interpreted.
///
/// The state is `[q₀, q₁, q₂, q̇₀, q̇₁, q̇₂]`; time enters only through declared torques.
/// As an [`crate::ode::System`] it is unchecked, for the steppers' inner loop (NaN at the
/// chart's gimbal lock); [`TopModel::accelerations`] and [`AngleChart::rates_at`] check the chart
/// under the one rule of [`crate::rigid::check_chart`].
///
/// # Examples
///
/// The symmetric heavy top with its moments and weight as parameters; at θ = 60° and
/// ω3 = 10 with I1 = 1, I3 = ½, M g l = 1 it precesses steadily at the slow root
/// Ω = 0.204168476687 rad/s of I1 cos θ Ω² − I3 ω3 Ω + M g l = 0, so θ̈ vanishes:
///
/// ```
/// use precess_core::codegen::BindingError;
/// use precess_core::rigid::ChartError;
/// use precess_core::top::{TopError, TopModel, TopScene};
/// use precess_core::sym::Arena;
///
/// let mut a = Arena::new();
/// let (i1, i3) = (a.parameter("I_1"), a.parameter("I_3"));
/// let z = a.zero();
/// let mut scene = TopScene::free(&mut a, [[i1, z, z], [z, i1, z], [z, z, i3]]);
/// scene.mass = a.parameter("M");
/// scene.center = [z, z, a.parameter("l")];
/// scene.gravity = Some(a.parameter("g"));
/// let derivation = scene.derive(&mut a)?;
///
/// // Every parameter needs a value; a missing one is named.
/// let partial = TopModel::new(&mut a, &derivation, &[("I_1", 1.0), ("I_3", 0.5)]);
/// assert!(matches!(partial, Err(TopError::Binding(BindingError::UnsetParameter { name, .. })) if name == "M"));
///
/// let values = [("I_1", 1.0), ("I_3", 0.5), ("M", 1.0), ("g", 1.0), ("l", 1.0)];
/// let model = TopModel::new(&mut a, &derivation, &values)?;
/// let (theta, omega_p, w3) = (std::f64::consts::FRAC_PI_3, 0.204168476687, 10.0);
/// let q_ddot = model.accelerations(&[0.0, theta, 0.0, omega_p, 0.0, w3 - omega_p * theta.cos()])?;
/// assert!(q_ddot[1].abs() < 1e-10);
///
/// // Straight up, the ZXZ angles are singular.
/// let vertical = model.accelerations(&[0.0, 0.0, 0.0, 0.0, 0.0, 5.0]);
/// assert!(matches!(vertical, Err(TopError::Chart(ChartError::SingularChart { .. }))));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct TopModel {
    accel: Program,
    energy: Program,
    omega: Program,
    momenta: Program,
    rotation: Program,
    rate_matrix: Program,
    sequence: AngleSequence,
    q: [SymbolId; 3],
    rates: [SymbolId; 3],
    time: Option<SymbolId>,
    /// The parameters by name and the environment the programs run in.
    bindings: Bindings,
}

impl TopModel {
    /// Lowers the derivation's accelerations, energy, body rates and momenta, with a value for
    /// each parameter they read (`(name, value)` pairs; [`TopModel::set`] changes one later).
    ///
    /// # Errors
    /// In [`TopError::Binding`]: [`BindingError::UnsetParameter`] naming a parameter the
    /// derivation reads that `parameters` leaves out; [`BindingError::UnknownParameter`] for
    /// a name it does not read; [`BindingError::DuplicateParameter`] for a name given twice;
    /// [`BindingError::NonFinite`] for a NaN or infinite value;
    /// [`BindingError::RunTimeInput`] if the derivation reads a user torque's inputs, which
    /// the interpreter cannot supply.
    pub fn new(
        arena: &mut Arena,
        top: &TopDerivation,
        parameters: &[(&str, f64)],
    ) -> Result<TopModel, TopError> {
        let sym = |e| {
            arena
                .as_symbol(e)
                .unwrap_or_else(|| unreachable!("coordinates are symbols"))
        };
        let c = top.coords();
        let q = [sym(c.q[0]), sym(c.q[1]), sym(c.q[2])];
        let rates = [sym(c.rates[0]), sym(c.rates[1]), sym(c.rates[2])];
        let energy = top.energy(arena);
        let programs = [
            Program::lower(arena, &top.accelerations.accel),
            Program::lower(arena, &[energy]),
            Program::lower(arena, &top.omega),
            Program::lower(arena, &top.equations.momenta),
            Program::lower(arena, top.rotation.as_flattened()),
            Program::lower(arena, top.rate_matrix.as_flattened()),
        ];
        let supplied = [q[0], q[1], q[2], rates[0], rates[1], rates[2]];
        let bindings = Bindings::new(arena, &programs, &supplied, parameters)?;
        let [accel, energy, omega, momenta, rotation, rate_matrix] = programs;
        Ok(TopModel {
            accel,
            energy,
            omega,
            momenta,
            rotation,
            rate_matrix,
            sequence: top.sequence,
            q,
            rates,
            time: arena.time_symbol(),
            bindings,
        })
    }

    /// The names of the parameters the derivation reads, in alphabetical order.
    pub fn parameters(&self) -> impl ExactSizeIterator<Item = &str> + '_ {
        self.bindings.parameters()
    }

    /// Sets the parameter `name`.
    ///
    /// # Errors
    /// In [`TopError::Binding`]: [`BindingError::UnknownParameter`] for a name the derivation
    /// does not read, [`BindingError::NonFinite`] for NaN or ±∞.
    pub fn set(&mut self, name: &str, value: f64) -> Result<&mut Self, TopError> {
        self.bindings.set(name, value)?;
        Ok(self)
    }

    fn run<const K: usize>(&self, p: &Program, t: f64, state: &[f64; 6]) -> [f64; K] {
        let coordinates = self.q.iter().chain(&self.rates).copied().zip(*state);
        let time = self.time.map(|s| (s, t));
        let mut out = [0.0; K];
        self.bindings.eval(p, coordinates.chain(time), &mut out);
        out
    }

    /// q̈ at the state `[q, q̇]` (at t = 0 for time-dependent torques), refusing a state the
    /// chart cannot take.
    ///
    /// # Errors
    /// [`TopError::NonFinite`] for non-finite angles or rates; [`TopError::Chart`] ([`crate::rigid::ChartError::SingularChart`]) at
    /// the chart's gimbal lock (`|det B(q)|` below [`crate::rigid::SINGULAR_DET`]): integrate
    /// through it with [`super::ChartedTop`]; [`TopError::NonFiniteResult`] if q̈ overflows.
    pub fn accelerations(&self, state: &[f64; 6]) -> Result<[f64; 3], TopError> {
        checked_accelerations(
            self.sequence,
            state,
            |_| self.rate_matrix_at(state),
            || self.run(&self.accel, 0.0, state),
        )
    }

    /// The energy T + V.
    pub fn energy(&self, state: &[f64; 6]) -> f64 {
        self.run::<1>(&self.energy, 0.0, state)[0]
    }

    /// The body angular velocity ω.
    pub fn omega(&self, state: &[f64; 6]) -> Vector3<f64> {
        self.run::<3>(&self.omega, 0.0, state).into()
    }

    /// The momenta `p_i = ∂L/∂q̇_i`.
    pub fn momenta(&self, state: &[f64; 6]) -> [f64; 3] {
        self.run(&self.momenta, 0.0, state)
    }

    /// The attitude R(q), body to space.
    pub fn rotation(&self, state: &[f64; 6]) -> Matrix3<f64> {
        let r: [f64; 9] = self.run(&self.rotation, 0.0, state);
        Matrix3::from_row_slice(&r)
    }

    /// B(q) with ω = B q̇.
    pub fn rate_matrix(&self, state: &[f64; 6]) -> Matrix3<f64> {
        let b: [f64; 9] = self.run(&self.rate_matrix, 0.0, state);
        Matrix3::from_row_slice(&b)
    }

    /// The angle sequence of the state.
    pub fn sequence(&self) -> AngleSequence {
        self.sequence
    }
}

impl System<6> for TopModel {
    fn rhs(&self, t: f64, y: &[f64; 6], dydt: &mut [f64; 6]) {
        let a: [f64; 3] = self.run(&self.accel, t, y);
        dydt[..3].copy_from_slice(&y[3..]);
        dydt[3..].copy_from_slice(&a);
    }
}

impl AngleChart for TopModel {
    fn sequence(&self) -> AngleSequence {
        self.sequence
    }
    fn rotation_at(&self, state: &[f64; 6]) -> Matrix3<f64> {
        self.rotation(state)
    }
    fn rate_matrix_at(&self, state: &[f64; 6]) -> Matrix3<f64> {
        self.rate_matrix(state)
    }
    fn energy_at(&self, state: &[f64; 6]) -> f64 {
        self.energy(state)
    }
}
