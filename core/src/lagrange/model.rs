//! A constrained derivation evaluated at run time through the code generator's interpreter.
//!
//! The state is `[q₀ … q_{n−1}, u₀ … u_{k−1}]`: every coordinate, then the free speeds
//! u = q̇_I. The dependent rates are not in the state: they are computed from the
//! constraints at every evaluation, so the velocity constraints hold to rounding by
//! construction and only the positions of a closed loop can drift
//! ([`ConstrainedModel::close_loop`] pulls them back).

use super::eliminate::ConstrainedEquations;
use super::error::LagrangeError;
#[cfg(doc)]
use crate::codegen::BindingError;
use crate::codegen::{Bindings, Program, with_workspace};
use crate::ode::System;
use crate::sym::{Arena, ExprId, SymbolId};

/// The reduced equations lowered once: the right-hand side, the multipliers, the position
/// constraints with their dependent Jacobian block, and any extra outputs (an energy, a
/// point's position) the caller asked for.
#[derive(Debug)]
pub struct ConstrainedModel {
    pub(super) n: usize,
    pub(super) independent: Vec<usize>,
    pub(super) dependent: Vec<usize>,
    q: Vec<SymbolId>,
    u: Vec<SymbolId>,
    time: Option<SymbolId>,
    /// Outputs: q̇_D (m), then u̇ (k), then Δ.
    rhs: Program,
    multipliers: Program,
    /// Outputs: q̈, all n.
    second: Program,
    /// Outputs: φ (m), then A_D row-major (m²); `None` unless every row is holonomic.
    pub(super) positions: Option<Program>,
    extra: Program,
    bindings: Bindings,
}

impl ConstrainedModel {
    /// Lowers the reduced equations and `outputs` (expressions in q, the rates, the
    /// accelerations and the parameters; the dependent rates in them are replaced by their
    /// constraint values and every acceleration by its derived value),
    /// with a value for each parameter the programs read.
    ///
    /// # Errors
    /// [`LagrangeError::Binding`] ([`BindingError::UnsetParameter`],
    /// [`BindingError::UnknownParameter`], [`BindingError::NonFinite`],
    /// [`BindingError::DuplicateParameter`], [`BindingError::RunTimeInput`]);
    /// [`LagrangeError::Sym`] if putting the dependent rates into an output fails.
    pub fn new(
        arena: &mut Arena,
        eqs: &ConstrainedEquations,
        outputs: &[ExprId],
        parameters: &[(&str, f64)],
    ) -> Result<ConstrainedModel, LagrangeError> {
        let coords = &eqs.equations.coords;
        let sym = |a: &Arena, e: ExprId| {
            a.as_symbol(e)
                .unwrap_or_else(|| unreachable!("coordinates are symbols"))
        };
        let q: Vec<SymbolId> = coords.q.iter().map(|&e| sym(arena, e)).collect();
        let u: Vec<SymbolId> = eqs
            .independent
            .iter()
            .map(|&i| sym(arena, coords.rates[i]))
            .collect();
        let rate_map: Vec<(SymbolId, ExprId)> = eqs
            .dependent
            .iter()
            .zip(&eqs.dependent_rates)
            .map(|(&d, &e)| (sym(arena, coords.rates[d]), e))
            .collect();
        let mut rhs_out = eqs.dependent_rates.clone();
        rhs_out.extend(&eqs.accelerations.accel);
        rhs_out.push(eqs.determinant);
        let mut q_ddot = vec![arena.zero(); coords.len()];
        for (j, &i) in eqs.independent.iter().enumerate() {
            q_ddot[i] = eqs.accelerations.accel[j];
        }
        for (j, &d) in eqs.dependent.iter().enumerate() {
            q_ddot[d] = eqs.dependent_accelerations[j];
        }
        // Outputs may read accelerations (a normal force m (z̈_G + g)): every q̈ is replaced
        // by its derived value along with the dependent rates.
        let mut map = rate_map;
        for (&acc, &value) in coords.accels.iter().zip(&q_ddot) {
            map.push((sym(arena, acc), value));
        }
        let extra: Vec<ExprId> = outputs
            .iter()
            .map(|&e| arena.subs(e, &map))
            .collect::<Result<_, _>>()?;
        let mut programs = vec![
            Program::lower(arena, &rhs_out),
            Program::lower(arena, &eqs.multipliers),
            Program::lower(arena, &extra),
            Program::lower(arena, &q_ddot),
        ];
        let positions = match eqs
            .constraints
            .positions
            .iter()
            .copied()
            .collect::<Option<Vec<ExprId>>>()
        {
            Some(mut out) if !out.is_empty() => {
                for row in &eqs.constraints.coefficients {
                    out.extend(eqs.dependent.iter().map(|&d| row[d]));
                }
                programs.push(Program::lower(arena, &out));
                true
            }
            _ => false,
        };
        let time = arena.time_symbol();
        let mut supplied: Vec<SymbolId> = q.iter().chain(&u).copied().collect();
        supplied.extend(time);
        let bindings = Bindings::new(arena, &programs, &supplied, parameters)?;
        let positions = if positions { programs.pop() } else { None };
        let mut programs = programs.into_iter();
        let mut next = || {
            programs
                .next()
                .unwrap_or_else(|| unreachable!("four programs lowered above"))
        };
        let (rhs, multipliers, extra, second) = (next(), next(), next(), next());
        Ok(ConstrainedModel {
            n: coords.len(),
            independent: eqs.independent.clone(),
            dependent: eqs.dependent.clone(),
            q,
            u,
            time,
            rhs,
            multipliers,
            second,
            positions,
            extra,
            bindings,
        })
    }

    /// The state length n + k (coordinates, then free speeds).
    pub fn state_len(&self) -> usize {
        self.n + self.independent.len()
    }

    /// Sets the parameter `name`.
    ///
    /// # Errors
    /// [`LagrangeError::Binding`]: [`BindingError::UnknownParameter`],
    /// [`BindingError::NonFinite`].
    pub fn set(&mut self, name: &str, value: f64) -> Result<&mut Self, LagrangeError> {
        self.bindings.set(name, value)?;
        Ok(self)
    }

    pub(super) fn run(&self, p: &Program, t: f64, state: &[f64], out: &mut [f64]) {
        self.bindings.eval(p, self.inputs(t, state), out);
    }

    /// The per-call inputs: the state and time by symbol.
    fn inputs<'s>(
        &'s self,
        t: f64,
        state: &'s [f64],
    ) -> impl Iterator<Item = (SymbolId, f64)> + 's {
        let inputs = self
            .q
            .iter()
            .chain(&self.u)
            .copied()
            .zip(state.iter().copied());
        inputs.chain(self.time.map(|s| (s, t)))
    }

    pub(super) fn check(&self, state: &[f64]) -> Result<(), LagrangeError> {
        if state.len() != self.state_len() {
            return Err(LagrangeError::StateLength {
                got: state.len(),
                expected: self.state_len(),
            });
        }
        match state.iter().position(|v| !v.is_finite()) {
            Some(index) => Err(LagrangeError::NonFiniteState {
                index,
                value: state[index],
            }),
            None => Ok(()),
        }
    }

    /// The unchecked right-hand side: `dydt = [q̇, u̇]` at `(t, y)`.
    pub fn rhs_into(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        let (m, k) = (self.dependent.len(), self.independent.len());
        for (j, &i) in self.independent.iter().enumerate() {
            dydt[i] = y[self.n + j];
        }
        // The outputs are a run-time number long: they go through the thread's workspace,
        // so the model stays shareable and a step allocates nothing.
        with_workspace(|ws| {
            let out = self.bindings.eval_to(ws, &self.rhs, self.inputs(t, y));
            for (j, &d) in self.dependent.iter().enumerate() {
                dydt[d] = out[j];
            }
            dydt[self.n..self.n + k].copy_from_slice(&out[m..m + k]);
        });
    }

    /// Every rate q̇ (the free ones from the state, the dependent ones from the
    /// constraints) and the free accelerations u̇ at `(t, state)`.
    ///
    /// # Errors
    /// [`LagrangeError::StateLength`], [`LagrangeError::NonFiniteState`];
    /// [`LagrangeError::SingularAtState`] where det A_D vanishes.
    pub fn rates(&self, t: f64, state: &[f64]) -> Result<Vec<f64>, LagrangeError> {
        self.check(state)?;
        let (m, k) = (self.dependent.len(), self.independent.len());
        let mut out = vec![0.0; m + k + 1];
        self.run(&self.rhs, t, state, &mut out);
        let determinant = out[m + k];
        let mut d = vec![0.0; state.len()];
        self.rhs_into(t, state, &mut d);
        if determinant != 0.0 && d.iter().all(|v| v.is_finite()) {
            Ok(d)
        } else {
            Err(LagrangeError::SingularAtState {
                determinant,
                scale: 1.0,
            })
        }
    }

    /// The multipliers λ at `(t, state)` (the constraint force is `Aᵀ λ`).
    ///
    /// # Errors
    /// As [`ConstrainedModel::rates`].
    pub fn multipliers(&self, t: f64, state: &[f64]) -> Result<Vec<f64>, LagrangeError> {
        self.rates(t, state)?;
        let mut out = vec![0.0; self.dependent.len()];
        self.run(&self.multipliers, t, state, &mut out);
        Ok(out)
    }

    /// Every acceleration q̈ (the free ones u̇ and the dependent ones) at `(t, state)`.
    ///
    /// # Errors
    /// As [`ConstrainedModel::rates`].
    pub fn accelerations(&self, t: f64, state: &[f64]) -> Result<Vec<f64>, LagrangeError> {
        self.rates(t, state)?;
        let mut out = vec![0.0; self.n];
        self.run(&self.second, t, state, &mut out);
        Ok(out)
    }

    /// The extra outputs given to [`ConstrainedModel::new`], at `(t, state)`.
    ///
    /// # Errors
    /// [`LagrangeError::StateLength`], [`LagrangeError::NonFiniteState`].
    pub fn outputs(&self, t: f64, state: &[f64]) -> Result<Vec<f64>, LagrangeError> {
        self.check(state)?;
        let mut out = vec![0.0; self.extra.outputs().len()];
        self.run(&self.extra, t, state, &mut out);
        Ok(out)
    }

    /// The model as an [`System`] of the fixed state length N = n + k.
    ///
    /// # Errors
    /// [`LagrangeError::StateLength`] if N is not n + k.
    pub fn system<const N: usize>(&self) -> Result<ConstrainedSystem<'_, N>, LagrangeError> {
        if N != self.state_len() {
            return Err(LagrangeError::StateLength {
                got: N,
                expected: self.state_len(),
            });
        }
        Ok(ConstrainedSystem { model: self })
    }
}

/// A [`ConstrainedModel`] seen as a [`System`] of its state length N (made by
/// [`ConstrainedModel::system`], which checks N).
#[derive(Debug, Clone, Copy)]
pub struct ConstrainedSystem<'a, const N: usize> {
    model: &'a ConstrainedModel,
}

impl<const N: usize> ConstrainedSystem<'_, N> {
    /// The model.
    pub fn model(&self) -> &ConstrainedModel {
        self.model
    }
}

impl<const N: usize> System<N> for ConstrainedSystem<'_, N> {
    fn rhs(&self, t: f64, y: &[f64; N], dydt: &mut [f64; N]) {
        self.model.rhs_into(t, y, dydt);
    }
}
