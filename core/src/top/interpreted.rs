//! A derived top evaluated at run time through the code generator's interpreter, usable with
//! any stepper of [`crate::ode`]. The derive macro emits the same programs as compiled Rust;
//! this is the path for scenes built at run time and the reference the tests use.

use std::cell::RefCell;

use nalgebra::Matrix3;

use super::angle_chart::AngleChart;
use super::error::ModelError;
use super::scene::TopDerivation;
use crate::codegen::Program;
use crate::ode::System;
use crate::rigid::AngleSequence;
use crate::sym::{Arena, SymbolId, SymbolKind};

/// A top's angle-form equations, lowered once and interpreted.
///
/// The state is `[q₀, q₁, q₂, q̇₀, q̇₁, q̇₂]`; time enters only through declared torques.
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
    parameters: Vec<(String, SymbolId)>,
    env: RefCell<Vec<f64>>,
    scratch: RefCell<Vec<f64>>,
}

impl TopModel {
    /// Lowers the derivation's accelerations, energy, body rates and momenta. Parameters
    /// start as NaN: set each with [`TopModel::set`].
    pub fn new(arena: &mut Arena, top: &TopDerivation) -> TopModel {
        let sym = |e| {
            arena
                .as_symbol(e)
                .unwrap_or_else(|| unreachable!("coordinates are symbols"))
        };
        let c = top.coords();
        let q = [sym(c.q[0]), sym(c.q[1]), sym(c.q[2])];
        let rates = [sym(c.rates[0]), sym(c.rates[1]), sym(c.rates[2])];
        let energy = top.energy(arena);
        let parameters = arena
            .symbols()
            .filter(|(_, s)| s.kind == SymbolKind::Parameter)
            .map(|(id, s)| (s.name.clone(), id))
            .collect();
        TopModel {
            accel: Program::lower(arena, &top.accelerations.accel),
            energy: Program::lower(arena, &[energy]),
            omega: Program::lower(arena, &top.omega),
            momenta: Program::lower(arena, &top.equations.momenta),
            rotation: Program::lower(arena, top.rotation.as_flattened()),
            rate_matrix: Program::lower(arena, top.rate_matrix.as_flattened()),
            sequence: top.sequence,
            q,
            rates,
            time: arena.time_symbol(),
            parameters,
            env: RefCell::new(vec![f64::NAN; arena.symbol_count()]),
            scratch: RefCell::new(Vec::new()),
        }
    }

    /// Sets the parameter `name`.
    ///
    /// # Errors
    /// [`ModelError::UnknownParameter`] for a name the derivation does not use,
    /// [`ModelError::NonFinite`] for NaN or ±∞.
    pub fn set(&mut self, name: &str, value: f64) -> Result<&mut Self, ModelError> {
        let Some(&(_, s)) = self.parameters.iter().find(|(n, _)| n == name) else {
            let known: Vec<&str> = self.parameters.iter().map(|(n, _)| n.as_str()).collect();
            return Err(ModelError::UnknownParameter {
                name: name.to_owned(),
                known: known.join(", "),
            });
        };
        if !value.is_finite() {
            return Err(ModelError::NonFinite {
                name: name.to_owned(),
                value,
            });
        }
        self.env.get_mut()[s.index()] = value;
        Ok(self)
    }

    fn run<const K: usize>(&self, p: &Program, t: f64, state: &[f64; 6]) -> [f64; K] {
        let mut env = self.env.borrow_mut();
        for k in 0..3 {
            env[self.q[k].index()] = state[k];
            env[self.rates[k].index()] = state[3 + k];
        }
        if let Some(ts) = self.time {
            env[ts.index()] = t;
        }
        let mut out = [0.0; K];
        p.eval_into(&env, &mut self.scratch.borrow_mut(), &mut out);
        out
    }

    /// q̈ at the state `[q, q̇]`.
    pub fn accel(&self, state: &[f64; 6]) -> [f64; 3] {
        self.run(&self.accel, 0.0, state)
    }

    /// The energy T + V.
    pub fn energy(&self, state: &[f64; 6]) -> f64 {
        self.run::<1>(&self.energy, 0.0, state)[0]
    }

    /// The body angular velocity ω.
    pub fn omega(&self, state: &[f64; 6]) -> [f64; 3] {
        self.run(&self.omega, 0.0, state)
    }

    /// The momenta `p_i = ∂L/∂q̇_i`.
    pub fn momenta(&self, state: &[f64; 6]) -> [f64; 3] {
        self.run(&self.momenta, 0.0, state)
    }

    /// The attitude R(q), body to space, row-major.
    pub fn rotation(&self, state: &[f64; 6]) -> [[f64; 3]; 3] {
        let r: [f64; 9] = self.run(&self.rotation, 0.0, state);
        [[r[0], r[1], r[2]], [r[3], r[4], r[5]], [r[6], r[7], r[8]]]
    }

    /// B(q) with ω = B q̇, row-major.
    pub fn rate_matrix(&self, state: &[f64; 6]) -> [[f64; 3]; 3] {
        let b: [f64; 9] = self.run(&self.rate_matrix, 0.0, state);
        [[b[0], b[1], b[2]], [b[3], b[4], b[5]], [b[6], b[7], b[8]]]
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
        let r = self.rotation(state);
        Matrix3::from_fn(|i, j| r[i][j])
    }
    fn rate_matrix_at(&self, state: &[f64; 6]) -> Matrix3<f64> {
        let b = self.rate_matrix(state);
        Matrix3::from_fn(|i, j| b[i][j])
    }
    fn energy_at(&self, state: &[f64; 6]) -> f64 {
        self.energy(state)
    }
}
