//! The values a scene's interpreted programs read: parameters set by name once, state and
//! time written per call, in one environment indexed by symbol and allocated once. The
//! run-time models of every scene (`TopModel`, `FreeModel`) evaluate through it.

use std::cell::RefCell;

use super::program::Program;
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
#[derive(Debug)]
pub struct Bindings {
    /// The parameters the programs read, by name, in alphabetical order.
    parameters: Vec<(String, SymbolId)>,
    env: RefCell<Vec<f64>>,
    scratch: RefCell<Vec<f64>>,
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
            env: RefCell::new(vec![f64::NAN; arena.symbol_count()]),
            scratch: RefCell::new(Vec::new()),
        };
        for &(name, value) in values {
            bindings.set(name, value)?;
        }
        let env = bindings.env.get_mut();
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
        self.env.get_mut()[s.index()] = value;
        Ok(())
    }

    /// Runs `program` with the per-call `inputs` written into the environment first.
    pub fn eval(
        &self,
        program: &Program,
        inputs: impl IntoIterator<Item = (SymbolId, f64)>,
        out: &mut [f64],
    ) {
        let mut env = self.env.borrow_mut();
        for (s, v) in inputs {
            env[s.index()] = v;
        }
        program.eval_into(&env, &mut self.scratch.borrow_mut(), out);
    }
}
