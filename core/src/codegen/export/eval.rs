//! Evaluating an exported function in Rust: the interpreter of its program, which the C and
//! the Python are compared against.

use super::{ExportError, Exported};

impl Exported {
    /// The outputs of the function `name` at time `t`, state `y` and parameters `p` (in the
    /// order of [`Exported::state`] and [`Exported::parameters`]) of a scene without inputs,
    /// row by row, computed by [`crate::codegen::Program::eval`] over `[t, y, p]`.
    ///
    /// # Errors
    /// [`ExportError::NoFunction`] for an unknown name, [`ExportError::InputLength`] for a
    /// `y` or `p` of the wrong length, or for a scene with inputs (see
    /// [`Exported::eval_with_inputs`]).
    pub fn eval(&self, name: &str, t: f64, y: &[f64], p: &[f64]) -> Result<Vec<f64>, ExportError> {
        self.eval_with_inputs(name, t, y, &[], p)
    }

    /// As [`Exported::eval`], with the inputs `u` (in the order of [`Exported::inputs`]):
    /// the program over `[t, y, u, p]`.
    ///
    /// # Errors
    /// As [`Exported::eval`], [`ExportError::InputLength`] for a `u` of the wrong length.
    pub fn eval_with_inputs(
        &self,
        name: &str,
        t: f64,
        y: &[f64],
        u: &[f64],
        p: &[f64],
    ) -> Result<Vec<f64>, ExportError> {
        let f = self.get(name).ok_or_else(|| ExportError::NoFunction {
            name: name.to_owned(),
        })?;
        for (what, found, expected) in [
            ("y", y.len(), self.state.len()),
            ("u", u.len(), self.inputs.len()),
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
            .chain(u.iter().copied())
            .chain(p.iter().copied())
            .collect();
        Ok(f.program.eval(&env))
    }
}
