//! The augmented equations lowered to one program and run by the interpreter as an
//! [`ode::System`](crate::ode::System) over the flat state.

use nalgebra::DMatrix;

use super::equations::VariationalEquations;
use super::error::VariationalError;
use super::layout::Layout;
use crate::codegen::{Bindings, OpCount, Program};
use crate::ode::System;
use crate::sym::{Arena, SymbolId};

/// First-order variational equations as a system of size `N = n + n·m + n·k`, one program
/// for f, J Φ and J S + ∂f/∂p together.
///
/// `Send + Sync` like every interpreted model: the program's scratch is the calling
/// thread's workspace, so one system serves every thread of an ensemble.
///
/// The logistic-free decay `x' = −k x` has Φ(t) = e^{−kt} and ∂x/∂k = −t x₀ e^{−kt}:
///
/// ```
/// use precess_core::ode::{AdaptiveConfig, Dop853};
/// use precess_core::sym::Arena;
/// use precess_core::variational::{VariationalEquations, VariationalSystem};
/// let mut a = Arena::new();
/// let (x, k) = (a.input("x"), a.parameter("k"));
/// let kx = a.mul(k, x);
/// let f = a.neg(kx);
/// let eq = VariationalEquations::new(&mut a, &[x], &[f], 1, &[k])?;
/// let sys = VariationalSystem::<3>::new(&a, &eq, &[("k", 0.5)])?;
/// let y0 = sys.layout().initial_state::<3>(&[2.0])?;
/// let mut ode = Dop853::new(&sys, 0.0, y0, AdaptiveConfig::with_tol(1e-12, 1e-14))?;
/// ode.advance_to(3.0)?;
/// let decay = (-1.5f64).exp();
/// approx::assert_relative_eq!(ode.y()[1], decay, max_relative = 1e-10);
/// approx::assert_relative_eq!(ode.y()[2], -3.0 * 2.0 * decay, max_relative = 1e-10);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct VariationalSystem<const N: usize> {
    layout: Layout,
    program: Program,
    /// The augmented state's symbols, in layout order.
    symbols: Vec<SymbolId>,
    time: Option<SymbolId>,
    bindings: Bindings,
}

impl<const N: usize> VariationalSystem<N> {
    /// Lowers `equations` to one program and binds `parameters` (`(name, value)` pairs, one
    /// for every parameter the equations read).
    ///
    /// # Errors
    /// [`VariationalError::SizeMismatch`] if `N` is not the layout's length; in
    /// [`VariationalError::Binding`], as [`Bindings::new`].
    pub fn new(
        arena: &Arena,
        equations: &VariationalEquations,
        parameters: &[(&str, f64)],
    ) -> Result<VariationalSystem<N>, VariationalError> {
        let layout = equations.layout();
        layout.check_size(N)?;
        let program = Program::lower(arena, equations.outputs());
        let time = arena.time_symbol();
        let mut supplied = equations.symbols().to_vec();
        supplied.extend(time);
        let bindings = Bindings::new(arena, std::slice::from_ref(&program), &supplied, parameters)?;
        Ok(VariationalSystem {
            layout,
            program,
            symbols: equations.symbols().to_vec(),
            time,
            bindings,
        })
    }

    /// The sizes of the augmented state.
    pub fn layout(&self) -> Layout {
        self.layout
    }

    /// The operations of the augmented program per right-hand side.
    pub fn op_count(&self) -> OpCount {
        self.program.op_count()
    }

    /// Sets the parameter `name` (for a sweep over one system).
    ///
    /// # Errors
    /// In [`VariationalError::Binding`], as [`Bindings::set`].
    pub fn set(&mut self, name: &str, value: f64) -> Result<(), VariationalError> {
        Ok(self.bindings.set(name, value)?)
    }

    /// The augmented state at the start: x₀, Φ = I (its first m columns), S = 0.
    ///
    /// # Errors
    /// As [`Layout::initial_state`].
    pub fn initial_state(&self, x0: &[f64]) -> Result<[f64; N], VariationalError> {
        self.layout.initial_state(x0)
    }

    /// Φ (n × m) in the augmented state `y`.
    pub fn transition(&self, y: &[f64; N]) -> DMatrix<f64> {
        self.layout.transition(y)
    }

    /// ∂x/∂p (n × k) in the augmented state `y`.
    pub fn sensitivities(&self, y: &[f64; N]) -> DMatrix<f64> {
        self.layout.sensitivities(y)
    }
}

impl<const N: usize> System<N> for VariationalSystem<N> {
    fn rhs(&self, t: f64, y: &[f64; N], dydt: &mut [f64; N]) {
        let state = self.symbols.iter().copied().zip(y.iter().copied());
        let time = self.time.map(|s| (s, t));
        self.bindings
            .eval(&self.program, state.chain(time), dydt.as_mut_slice());
    }
}
