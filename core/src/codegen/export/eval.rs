//! Evaluating an exported function in Rust: the interpreter of its program, which the C and
//! the Python are compared against.

use super::{ExportError, Exported};

impl Exported {
    /// The outputs of the function `name` at time `t`, state `y` and parameters `p` (in the
    /// order of [`Exported::state`] and [`Exported::parameters`]), row by row, computed by
    /// [`crate::codegen::Program::eval`] over `[t, y, p]`.
    ///
    /// # Errors
    /// [`ExportError::NoFunction`] for an unknown name, [`ExportError::InputLength`] for a
    /// `y` or `p` of the wrong length.
    pub fn eval(&self, name: &str, t: f64, y: &[f64], p: &[f64]) -> Result<Vec<f64>, ExportError> {
        let f = self.get(name).ok_or_else(|| ExportError::NoFunction {
            name: name.to_owned(),
        })?;
        for (what, found, expected) in [
            ("y", y.len(), self.state.len()),
            ("p", p.len(), self.parameters.len()),
        ] {
            if found != expected {
                return Err(ExportError::InputLength {
                    what,
                    found,
                    expected,
                });
            }
        }
        let env: Vec<f64> = std::iter::once(t)
            .chain(y.iter().copied())
            .chain(p.iter().copied())
            .collect();
        Ok(f.program.eval(&env))
    }
}
