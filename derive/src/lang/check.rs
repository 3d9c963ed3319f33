//! The checker every attribute's values go through: one arena, one list of the struct's
//! fields read, one error context, so `#[rigid]`, `#[top]`, `#[free]` and `#[body]` values
//! meet the same rules and errors. The value language is in `values.rs`, the part language
//! in `parts.rs`; each attribute's own rules are in its `check.rs`.

use precess_core::sym::Arena;
use syn::Expr;

use super::ast::Input;
use super::ctxt::Ctxt;
use super::scalar::Expect;
use super::symbols::FieldParameters;

/// Converts attribute values into expressions of the macro's arena, recording every error.
/// It borrows the arena and the list of fields read, so the values of every attribute of one
/// struct share them with the same rules and errors.
pub struct Checker<'a> {
    /// Where errors go.
    pub cx: &'a Ctxt,
    /// The struct whose fields values may name.
    pub input: &'a Input<'a>,
    /// The arena the values are built in.
    pub arena: &'a mut Arena,
    /// The fields read so far, each with its parameter symbol.
    pub(crate) parameters: &'a mut FieldParameters,
    /// The dimension the key being read wants, if it has one (see `scalar.rs`).
    pub(crate) expect: Option<Expect>,
}

impl<'a> Checker<'a> {
    /// A checker building values of `input` in `arena`, recording the fields it reads.
    pub fn new(
        cx: &'a Ctxt,
        input: &'a Input<'a>,
        arena: &'a mut Arena,
        parameters: &'a mut FieldParameters,
    ) -> Self {
        Checker {
            cx,
            input,
            arena,
            parameters,
            expect: None,
        }
    }
}

impl Checker<'_> {
    /// The path of a user function (a plain path, not `<T as Trait>::f`), as the scenes'
    /// `torque = f`, `force = f`, `wrench = f` and a rotor's motor take it; else an error on
    /// `value`: `who` (the key, in backticks) expects a path to a function `function` (its
    /// type in backticks, then what it maps to what). None after an error.
    pub(crate) fn function_path(
        &self,
        value: &Expr,
        who: &str,
        function: &str,
    ) -> Option<syn::Path> {
        match value {
            Expr::Path(p) if p.qself.is_none() => Some(p.path.clone()),
            _ => {
                let message = format!("{who} expects a path to a function {function}");
                self.cx.error_spanned_by(value, message);
                None
            }
        }
    }

    /// Refuses every field read by a value whose name is one of the scene's `coordinates`
    /// (`whose` names them in the message, `the top's angles (zxz)`); false after an error.
    ///
    /// The generated code cannot confuse them (a field is read as `self.theta`, a coordinate
    /// from the state, and the engine keeps the two symbols apart), but the printed
    /// equations would: both would print as θ, one letter for two quantities.
    pub(crate) fn refuse_coordinate_names(&self, coordinates: &[String], whose: &str) -> bool {
        let mut ok = true;
        for field in self.parameters.fields() {
            let name = field.to_string();
            if coordinates.contains(&name) {
                self.cx.error_spanned_by(
                    field,
                    format!(
                        "field `{name}` has the name of one of the coordinates of {whose} ({}): the printed equations would show both as `{name}`; rename the field, e.g. `{name}_0`",
                        coordinates.join(", ")
                    ),
                );
                ok = false;
            }
        }
        ok
    }
}
