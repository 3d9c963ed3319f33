//! A free-body derivation evaluated at run time through the code generator's interpreter:
//! the path for scenes built at run time, and a reference for the generated code.

use nalgebra::Vector3;

use super::derivation::FreeDerivation;
use super::dynamics::Wrench;
use super::error::FreeError;
#[cfg(doc)]
use crate::codegen::BindingError;
use crate::codegen::{Bindings, Program};
use crate::ode::{OdeError, System};
use crate::sym::{Arena, SymbolId};

/// A free body's equations, lowered once and interpreted.
///
/// # Examples
///
/// A body of the Geometric Numerical Integration book (I = (2, 1, 2/3), m(0) =
/// (cos 1.1, 0, sin 1.1)), torque-free: its angular momentum at t = 10 is quoted to 30 digits.
///
/// ```
/// use approx::assert_relative_eq;
/// use nalgebra::Vector3;
/// use precess_core::free::{FreeModel, FreeScene, FreeState};
/// use precess_core::ode::{AdaptiveConfig, Dop853};
/// use precess_core::sym::Arena;
///
/// let mut a = Arena::new();
/// let (m, i1, i2, i3) = (a.integer(1), a.integer(2), a.integer(1), a.parameter("I3"));
/// let scene = FreeScene::new(&mut a, m, [i1, i2, i3]);
/// let derivation = scene.derive(&mut a)?;
/// let model = FreeModel::new(&mut a, &derivation, &[("I3", 2.0 / 3.0)])?;
/// let w0 = Vector3::new(1.1f64.cos() / 2.0, 0.0, 1.1f64.sin() * 1.5);
/// let s0 = FreeState { omega_principal: w0, ..FreeState::at_rest() };
/// let mut ode = Dop853::new(&model, 0.0, s0.to_array(), AdaptiveConfig::with_tol(1e-13, 1e-15))?;
/// ode.advance_to(10.0)?;
/// assert_relative_eq!(2.0 * ode.y()[10], 0.407_066_136_588_040_8, epsilon = 1e-11);
/// assert_relative_eq!(ode.y()[11], 0.283_007_426_812_843_7, epsilon = 1e-11);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct FreeModel {
    rhs: Program,
    wrench: Program,
    energy: Program,
    power: Program,
    momenta: Program,
    /// The principal moments, then the entries of each I − Σⱼ≤ₖ Jⱼ âⱼ âⱼᵀ, nine per driven
    /// rotor, row by row.
    driven: Program,
    /// The state symbols: the 13 of the layout, then the driven rotors' rates.
    state: Vec<SymbolId>,
    /// The parameters by name and the environment the programs run in.
    bindings: Bindings,
}

impl FreeModel {
    /// Lowers the derivation, with a value for each parameter it reads (`(name, value)`
    /// pairs; [`FreeModel::set`] changes one later).
    ///
    /// # Errors
    /// In [`FreeError::Binding`]: [`BindingError::UnsetParameter`] naming a parameter left
    /// out, [`BindingError::UnknownParameter`] for a name the derivation does not read,
    /// [`BindingError::NonFinite`] for NaN or ±∞, [`BindingError::RunTimeInput`] if the
    /// derivation reads a user force or torque.
    pub fn new(
        arena: &mut Arena,
        derivation: &FreeDerivation,
        parameters: &[(&str, f64)],
    ) -> Result<FreeModel, FreeError> {
        let state: Vec<SymbolId> = derivation
            .full_state()
            .into_iter()
            .map(|e| {
                arena
                    .as_symbol(e)
                    .unwrap_or_else(|| unreachable!("the derivation's state entries are symbols"))
            })
            .collect();
        let d = derivation;
        let wrench: Vec<_> = d.force.iter().chain(&d.torque).copied().collect();
        let momenta: Vec<_> = d
            .linear_momentum
            .iter()
            .chain(&d.angular_momentum)
            .copied()
            .collect();
        let driven: Vec<_> = d
            .moments
            .iter()
            .chain(d.driven_inertia.iter().flatten().flatten())
            .copied()
            .collect();
        let programs = [
            Program::lower(arena, &d.full_rhs()),
            Program::lower(arena, &wrench),
            Program::lower(arena, &[d.energy]),
            Program::lower(arena, &[d.power]),
            Program::lower(arena, &momenta),
            Program::lower(arena, &driven),
        ];
        let bindings =
            Bindings::new(arena, &programs, &state, parameters).map_err(FreeError::from)?;
        let [rhs, wrench, energy, power, momenta, driven] = programs;
        Ok(FreeModel {
            rhs,
            wrench,
            energy,
            power,
            momenta,
            driven,
            state,
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
    /// In [`FreeError::Binding`]: [`BindingError::UnknownParameter`] for a name the
    /// derivation does not read, [`BindingError::NonFinite`] for NaN or ±∞.
    pub fn set(&mut self, name: &str, value: f64) -> Result<&mut Self, FreeError> {
        self.bindings.set(name, value)?;
        Ok(self)
    }

    fn run(&self, p: &Program, y: &[f64], out: &mut [f64]) {
        self.bindings
            .eval(p, self.state.iter().copied().zip(y.iter().copied()), out);
    }

    /// The length of the state: 13, and one per driven rotor.
    pub fn state_len(&self) -> usize {
        self.state.len()
    }

    /// Checks the driven rotors for the current parameters: the body's inertia stays
    /// positive definite beyond rounding as each wheel's axial moment is taken out, the rule
    /// of [`crate::rigid::first_singular_driven`] (one criterion,
    /// [`crate::rigid::singular_driven_step`], measured against the largest principal moment).
    ///
    /// # Errors
    /// [`FreeError::DrivenInertia`] naming the first rotor (its index in
    /// [`super::FreeScene::driven`]) for which it does not.
    pub fn check_driven(&self) -> Result<(), FreeError> {
        let mut out = vec![0.0; self.driven.outputs().len()];
        self.run(&self.driven, &[], &mut out);
        let (moments, steps) = out.split_at(3.min(out.len()));
        let scale = moments.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for (rotor, a) in steps.chunks_exact(9).enumerate() {
            let step = nalgebra::Matrix3::from_row_slice(a);
            if let Some(smallest) = crate::rigid::singular_driven_step(&step, scale) {
                return Err(FreeError::DrivenInertia { rotor, smallest });
            }
        }
        Ok(())
    }

    /// The total force (space axes) and torque about the centre of mass (principal axes).
    pub fn wrench<const N: usize>(&self, y: &[f64; N]) -> Wrench {
        let mut out = [0.0; 6];
        self.run(&self.wrench, y, &mut out);
        Wrench {
            force_space: Vector3::new(out[0], out[1], out[2]),
            torque_principal: Vector3::new(out[3], out[4], out[5]),
        }
    }

    /// The energy ½ M |v|² + ½ Σ Iᵢ ωᵢ² − M g·x.
    pub fn energy<const N: usize>(&self, y: &[f64; N]) -> f64 {
        let mut out = [0.0];
        self.run(&self.energy, y, &mut out);
        out[0]
    }

    /// The power of every force but gravity: dE/dt.
    pub fn power<const N: usize>(&self, y: &[f64; N]) -> f64 {
        let mut out = [0.0];
        self.run(&self.power, y, &mut out);
        out[0]
    }

    /// The linear momentum and the angular momentum about the origin, space axes.
    pub fn momenta<const N: usize>(&self, y: &[f64; N]) -> (Vector3<f64>, Vector3<f64>) {
        let mut out = [0.0; 6];
        self.run(&self.momenta, y, &mut out);
        (
            Vector3::new(out[0], out[1], out[2]),
            Vector3::new(out[3], out[4], out[5]),
        )
    }
}

/// On the state of [`FreeModel::state_len`] numbers (13 without driven rotors); any other `N`
/// is refused by [`System::check_parameters`] before a step.
impl<const N: usize> System<N> for FreeModel {
    fn rhs(&self, _t: f64, y: &[f64; N], dydt: &mut [f64; N]) {
        if N == self.state.len() {
            self.run(&self.rhs, y, dydt);
        } else {
            dydt.fill(f64::NAN);
        }
    }

    /// The state's length, and [`FreeModel::check_driven`].
    fn check_parameters(&self) -> Result<(), OdeError> {
        if N != self.state.len() {
            return Err(FreeError::StateLength {
                len: N,
                expected: self.state.len(),
            }
            .into_ode_error());
        }
        self.check_driven().map_err(FreeError::into_ode_error)
    }
}
