//! The values a scene's interpreted programs read: parameters set by name once, state and
//! time written per call. The run-time models of every scene (`TopModel`, `FreeModel`)
//! evaluate through it.
//!
//! The parameters are the model's and are only read while it runs; everything a call writes
//! (the state, time and the program's intermediate values) lives in an [`EvalWorkspace`], so
//! one model is `Send + Sync` and can be shared by every thread of an ensemble.

use super::program::Program;
use super::workspace::{EvalWorkspace, next_generation, with_workspace};
use crate::sym::{Arena, SymbolId, SymbolKind};

/// Why a parameter could not be bound; every scene's error nests it as its `Binding`
/// variant.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum BindingError {
    /// A name the programs do not read; `known` lists those they do.
    #[error("no parameter named `{name}` in this derivation (parameters: {known})")]
    UnknownParameter {
        /// The name given.
        name: String,
        /// The parameters read, comma-separated (`none` if there are none).
        known: String,
    },
    /// A parameter the programs read that was given no value.
    #[error("parameter `{name}` is not set: give a value for each of {known}")]
    UnsetParameter {
        /// The parameter left out.
        name: String,
        /// The parameters read, comma-separated.
        known: String,
    },
    /// NaN or ±∞ for a parameter.
    #[error("parameter `{name}` = {value} is not finite")]
    NonFinite {
        /// The parameter.
        name: String,
        /// The value given.
        value: f64,
    },
    /// The programs read a run-time input (a user function's) the interpreter cannot
    /// supply.
    #[error(
        "the derivation reads `{name}`, a run-time input (a user function's): the interpreted \
         model cannot supply it; derive the scene with its attribute instead"
    )]
    RunTimeInput {
        /// The input's name.
        name: String,
    },
    /// The same parameter given twice: which value was meant is unknown, so neither is
    /// taken (the last one used to win silently).
    #[error("parameter `{name}` is given twice ({first}, then {second}): give each parameter once")]
    DuplicateParameter {
        /// The parameter.
        name: String,
        /// The first value given.
        first: f64,
        /// The second value given.
        second: f64,
    },
}

/// Refuses a parameter named twice in `values`.
///
/// # Errors
/// [`BindingError::DuplicateParameter`] for the first name given twice.
pub(crate) fn check_distinct(values: &[(&str, f64)]) -> Result<(), BindingError> {
    for (i, &(name, first)) in values.iter().enumerate() {
        if let Some(&(_, second)) = values[i + 1..].iter().find(|(n, _)| *n == name) {
            return Err(BindingError::DuplicateParameter {
                name: name.to_owned(),
                first,
                second,
            });
        }
    }
    Ok(())
}

/// Parameters by name and the environment the programs run in.
///
/// `Send + Sync`: evaluation reads the parameters and writes only into an
/// [`EvalWorkspace`] — the caller's ([`Bindings::eval_in`]) or the calling thread's own
/// ([`Bindings::eval`]).
#[derive(Debug)]
pub struct Bindings {
    /// The parameters the programs read, by name, in alphabetical order.
    parameters: Vec<(String, SymbolId)>,
    /// Every symbol's value by index: the parameters set, NaN elsewhere (a workspace copies
    /// it, then writes the per-call inputs over it).
    env: Vec<f64>,
    /// The run-time inputs the programs may read; cleared to NaN before each call so a call
    /// never sees the inputs of an earlier one.
    supplied: Vec<SymbolId>,
    /// Which parameter values `env` holds: unique to this value of `env` over the process, so
    /// a workspace that last copied it can skip the copy.
    generation: u64,
}

impl Bindings {
    /// Binds `values` (`(name, value)` pairs) to the parameters `programs` read; the
    /// run-time inputs in `supplied` (state entries, time) are written per call by
    /// [`Bindings::eval`], any other input is refused.
    ///
    /// # Errors
    /// [`BindingError::DuplicateParameter`] for a name given twice,
    /// [`BindingError::RunTimeInput`] for an input not supplied, then as
    /// [`Bindings::set`] for each value, then [`BindingError::UnsetParameter`] for the
    /// first parameter left out.
    pub fn new(
        arena: &Arena,
        programs: &[Program],
        supplied: &[SymbolId],
        values: &[(&str, f64)],
    ) -> Result<Bindings, BindingError> {
        check_distinct(values)?;
        let mut read: Vec<(String, SymbolId)> = Vec::new();
        for s in programs.iter().flat_map(Program::inputs) {
            let symbol = arena.symbol(s);
            match symbol.kind {
                SymbolKind::Parameter if !read.iter().any(|&(_, r)| r == s) => {
                    read.push((symbol.name.clone(), s));
                }
                SymbolKind::Input if !supplied.contains(&s) => {
                    return Err(BindingError::RunTimeInput {
                        name: symbol.name.clone(),
                    });
                }
                _ => {}
            }
        }
        read.sort();
        let mut bindings = Bindings {
            parameters: read,
            env: vec![f64::NAN; arena.symbol_count()],
            supplied: supplied
                .iter()
                .copied()
                .filter(|s| s.index() < arena.symbol_count())
                .collect(),
            generation: next_generation(),
        };
        for &(name, value) in values {
            bindings.set(name, value)?;
        }
        let env = &bindings.env;
        if let Some((name, _)) = bindings
            .parameters
            .iter()
            .find(|(_, s)| env[s.index()].is_nan())
        {
            return Err(BindingError::UnsetParameter {
                name: name.clone(),
                known: bindings.known(),
            });
        }
        Ok(bindings)
    }

    /// The names of the parameters the programs read, in alphabetical order.
    pub fn parameters(&self) -> impl ExactSizeIterator<Item = &str> + '_ {
        self.parameters.iter().map(|(n, _)| n.as_str())
    }

    fn known(&self) -> String {
        let known: Vec<&str> = self.parameters().collect();
        if known.is_empty() {
            "none".to_owned()
        } else {
            known.join(", ")
        }
    }

    /// Sets the parameter `name`.
    ///
    /// # Errors
    /// [`BindingError::UnknownParameter`] for a name the programs do not read,
    /// [`BindingError::NonFinite`] for NaN or ±∞.
    pub fn set(&mut self, name: &str, value: f64) -> Result<(), BindingError> {
        let Some(&(_, s)) = self.parameters.iter().find(|(n, _)| n == name) else {
            return Err(BindingError::UnknownParameter {
                name: name.to_owned(),
                known: self.known(),
            });
        };
        if !value.is_finite() {
            return Err(BindingError::NonFinite {
                name: name.to_owned(),
                value,
            });
        }
        self.env[s.index()] = value;
        // Workspaces holding the old values must copy them again.
        self.generation = next_generation();
        Ok(())
    }

    /// The value bound to the parameter `name`, if the programs read it.
    pub fn value(&self, name: &str) -> Option<f64> {
        self.parameters
            .iter()
            .find(|(n, _)| n == name)
            .map(|&(_, s)| self.env[s.index()])
    }

    /// Runs `program` with the per-call `inputs` written over the parameters, in the
    /// calling thread's own workspace (allocation-free once it has grown to the largest
    /// program run on the thread).
    pub fn eval(
        &self,
        program: &Program,
        inputs: impl IntoIterator<Item = (SymbolId, f64)>,
        out: &mut [f64],
    ) {
        with_workspace(|ws| self.eval_in(ws, program, inputs, out));
    }

    /// As [`Bindings::eval`], in the caller's workspace `ws`.
    ///
    /// The result depends only on the parameters and `inputs`: an input the call does not
    /// give reads NaN, whatever `ws` ran before.
    pub fn eval_in(
        &self,
        ws: &mut EvalWorkspace,
        program: &Program,
        inputs: impl IntoIterator<Item = (SymbolId, f64)>,
        out: &mut [f64],
    ) {
        self.prepare(ws, inputs);
        program.eval_into(&ws.env, &mut ws.scratch, out);
    }

    /// As [`Bindings::eval_in`], the outputs left in `ws` and returned (all of them, in
    /// order): for models whose outputs are a run-time number long.
    pub fn eval_to<'w>(
        &self,
        ws: &'w mut EvalWorkspace,
        program: &Program,
        inputs: impl IntoIterator<Item = (SymbolId, f64)>,
    ) -> &'w [f64] {
        self.prepare(ws, inputs);
        ws.out.clear();
        ws.out.resize(program.outputs().len(), 0.0);
        program.eval_into(&ws.env, &mut ws.scratch, &mut ws.out);
        &ws.out
    }

    /// Loads the parameters into `ws` (only if it holds another set), clears the run-time
    /// inputs and writes `inputs`.
    fn prepare(&self, ws: &mut EvalWorkspace, inputs: impl IntoIterator<Item = (SymbolId, f64)>) {
        if ws.generation == self.generation && ws.env.len() == self.env.len() {
            for s in &self.supplied {
                ws.env[s.index()] = f64::NAN;
            }
        } else {
            ws.env.clone_from(&self.env);
            ws.generation = self.generation;
        }
        for (s, v) in inputs {
            if let Some(slot) = ws.env.get_mut(s.index()) {
                *slot = v;
            }
        }
    }
}
