//! Export of a scene's equations as C99 and as a NumPy module: what SymPy's codegen and PyDy
//! give, from the straight-line [`Program`]s precess already lowers.
//!
//! An [`Exported`] scene is a name, the names of its state y, of its inputs u (values a
//! user function gives in Rust, such as a motor's torque, which the caller of the C or the
//! Python supplies; most scenes have none) and of its parameters p, and functions
//! `f(t, y, u, p)` (the state derivative, the quantities and the Jacobians the scene has),
//! each one program. Its emitters write
//! - [`Exported::c_header`] and [`Exported::c_source`]: C99, no allocation, the parameters
//!   as a struct, one `void name_f(double t, const double *y, const name_params *p,
//!   double *out)` per function (with `const double *u` after `y` when the scene has inputs);
//! - [`Exported::python`]: a module over NumPy, vectorised over many states (y of shape
//!   `(n,)` or `(n, k)`), the parameters as keyword arguments (`u` positional after `y`).
//!
//! Both execute the program's instructions in its order, one IEEE operation each, so a C
//! compiler that does not contract `a·b + c` into a fused multiply–add (`-ffp-contract=off`)
//! and the same libm give the bits the Rust code gives (see `docs/export.md` for where NumPy
//! may differ by one ulp).
//!
//! A scene built at run time is exported with [`Exported::new`] and
//! [`Exported::function`] over its arena; a derived struct implements [`Export`], whose text
//! (the same [`Exported`], written by [`Exported::to_text`] while the macro expands) is read
//! back by [`Exported::from_text`].

mod build;
mod c;
mod eval;
mod names;
mod python;
mod syntax;
mod text;

use thiserror::Error;

pub use build::ExportBuilder;

use super::program::Program;

/// A scene's functions ready to be written as C or Python; see the module's docs.
#[derive(Clone, Debug, PartialEq)]
pub struct Exported {
    name: String,
    state: Vec<String>,
    inputs: Vec<String>,
    parameters: Vec<String>,
    functions: Vec<ExportedFunction>,
}

/// One exported function `out = f(t, y, u, p)`.
///
/// Its program reads the environment `[t, y₀ … yₙ₋₁, u₀ … uₖ₋₁, p₀ … pₘ₋₁]`: the time, the
/// state, the inputs and the parameters, in the order of [`Exported::state`],
/// [`Exported::inputs`] and [`Exported::parameters`].
#[derive(Clone, Debug, PartialEq)]
pub struct ExportedFunction {
    name: String,
    doc: String,
    rows: usize,
    cols: usize,
    program: Program,
}

impl ExportedFunction {
    /// The name (`rhs`, `energy`, `jacobian`), the suffix of the C function and the Python
    /// function's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// One line saying what the function computes.
    pub fn doc(&self) -> &str {
        &self.doc
    }

    /// The shape of the output, `(rows, cols)`, stored row by row; `cols` is 1 for a vector.
    pub fn shape(&self) -> (usize, usize) {
        (self.rows, self.cols)
    }

    /// The number of outputs, `rows · cols`.
    pub fn len(&self) -> usize {
        self.rows * self.cols
    }

    /// True for a function of no outputs.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The program, reading the environment `[t, y, u, p]`.
    pub fn program(&self) -> &Program {
        &self.program
    }
}

impl Exported {
    /// The scene's name: the prefix of every C name, the Python module's docstring.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The names of the state's entries, in order.
    pub fn state(&self) -> &[String] {
        &self.state
    }

    /// The names of the inputs u, in order: values the scene's Rust code takes from a user
    /// function (a motor's torque, a user torque's components) and the exported functions
    /// take from their caller. Empty for most scenes, whose C and Python then take no `u`.
    pub fn inputs(&self) -> &[String] {
        &self.inputs
    }

    /// The names of the parameters the functions read (the struct's fields for a derived
    /// struct), in order: the C struct's members and the Python keyword arguments.
    pub fn parameters(&self) -> &[String] {
        &self.parameters
    }

    /// The functions, in the order they were added.
    pub fn functions(&self) -> &[ExportedFunction] {
        &self.functions
    }

    /// The function called `name`, if there is one.
    pub fn get(&self, name: &str) -> Option<&ExportedFunction> {
        self.functions.iter().find(|f| f.name == name)
    }
}

/// Why a scene could not be exported, or an exported text not read.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum ExportError {
    /// A function reads a symbol that is neither the time, a state entry, an input nor a
    /// parameter (a user function's value not declared an input, a rate not in the state).
    #[error(
        "the exported function `{function}` reads `{symbol}`, which is neither the time, the state, an input nor a parameter"
    )]
    Unbound {
        /// The function.
        function: String,
        /// The symbol's name.
        symbol: String,
    },
    /// A state entry is not a bare symbol of the arena.
    #[error("state entry {index} is not a symbol")]
    StateNotSymbol {
        /// Its index in the state.
        index: usize,
    },
    /// The outputs do not fill the shape asked for.
    #[error("the function `{function}` has {outputs} outputs, not {rows} × {cols}")]
    Shape {
        /// The function.
        function: String,
        /// The outputs given.
        outputs: usize,
        /// The rows asked for.
        rows: usize,
        /// The columns asked for.
        cols: usize,
    },
    /// Two names (of the state, the parameters or the functions) are one identifier in C or
    /// Python.
    #[error("the name `{name}` is used twice in the exported C and Python")]
    DuplicateName {
        /// The name, as C and Python write it.
        name: String,
    },
    /// No function of that name was exported.
    #[error("no exported function is called `{name}`")]
    NoFunction {
        /// The name asked for.
        name: String,
    },
    /// The inputs given to [`Exported::eval`] have the wrong length.
    #[error("`{what}` has {found} values, the scene {expected}")]
    InputLength {
        /// `"y"`, `"u"`, `"p"`, `"state names"` or `"input names"`.
        what: &'static str,
        /// The length given.
        found: usize,
        /// The length expected.
        expected: usize,
    },
    /// The derive could not export the scene: forming its equations or building their
    /// programs failed (the reason is that error's message).
    #[error("the scene cannot be exported: {reason}")]
    NotExportable {
        /// Why.
        reason: String,
    },
    /// A line of an exported text is not what [`Exported::to_text`] writes.
    #[error("line {line} of the exported text is malformed: {reason}")]
    Text {
        /// The line, from 1.
        line: usize,
        /// What is wrong with it.
        reason: String,
    },
}

/// The exported equations of a derived struct: every `#[derive(RigidBody)]` (a top, with or
/// without motors, a free body, a body on a table, or the body's own torque-free Euler
/// equations: in principal axes when its principal frame is known at compile time, in its
/// description axes, ω̇ = I⁻¹(−ω × I ω), when a product of inertia depends on fields), every `#[derive(Mechanism)]` (a tree's state derivative, the pieces of a
/// rolling or a closed mechanism's equations, which their runs project numerically) and every
/// `taylor_system!` implements it. The values of user functions (motors, user torques,
/// forces, wrenches, couples, efforts) are the export's inputs ([`Exported::inputs`]).
///
/// The macro writes the scene's [`Exported`] as text ([`Export::EXPORTED`]) while it
/// expands, from the same programs its Rust methods are emitted from; the methods read it
/// back.
///
/// # Errors
/// Every method returns [`ExportError::NotExportable`] when the derive could not form the
/// scene's equations or build their programs, and [`ExportError::Text`] never for the text the macro wrote.
pub trait Export {
    /// The [`Exported::to_text`] of the scene, or why it could not be exported.
    const EXPORTED: Result<&'static str, &'static str>;

    /// The scene, read back from [`Export::EXPORTED`].
    fn exported() -> Result<Exported, ExportError> {
        match Self::EXPORTED {
            Ok(text) => Exported::from_text(text),
            Err(reason) => Err(ExportError::NotExportable {
                reason: reason.to_owned(),
            }),
        }
    }

    /// The C99 header ([`Exported::c_header`]).
    fn c_header() -> Result<String, ExportError> {
        Ok(Self::exported()?.c_header())
    }

    /// The C99 source ([`Exported::c_source`]).
    fn c_source() -> Result<String, ExportError> {
        Ok(Self::exported()?.c_source())
    }

    /// The Python module ([`Exported::python`]).
    fn python_module() -> Result<String, ExportError> {
        Ok(Self::exported()?.python())
    }

    /// The names of the state's entries.
    fn state_names() -> Result<Vec<String>, ExportError> {
        Ok(Self::exported()?.state)
    }

    /// The names of the inputs the caller supplies (user functions' values: a motor's
    /// torque, a user torque's components), empty for most scenes.
    fn input_names() -> Result<Vec<String>, ExportError> {
        Ok(Self::exported()?.inputs)
    }

    /// The names of the parameters (the fields the equations read).
    fn parameter_names() -> Result<Vec<String>, ExportError> {
        Ok(Self::exported()?.parameters)
    }
}
