//! Code generation: expressions to straight-line programs, Rust tokens and LaTeX.
//!
//! [`Program::lower`] turns the outputs of a derivation into one instruction list with every
//! common subexpression computed once. The same program is
//! - emitted as Rust ([`Program::to_tokens`]), which is what the derive macro splices in;
//! - interpreted in f64 ([`Program::eval`]), the oracle the emitted code is tested against;
//! - counted ([`Program::op_count`]), the cost model the reports print.
//!
//! [`Exported`] writes a scene's programs as C99 and as a NumPy module ([`Export`] for a
//! derived struct).
//!
//! [`latex()`] renders an expression for a reader in the engine's canonical form,
//! [`paper_latex`] as a paper prints it (grouped by parameter, sin² where shorter).

mod bindings;
mod count;
mod export;
mod interp;
mod latex;
mod paper;
mod program;
mod tokens;
mod typeset;
mod workspace;

pub(crate) use bindings::check_distinct;
pub use bindings::{BindingError, Bindings};
pub use count::OpCount;
pub use export::{Export, ExportBuilder, ExportError, Exported, ExportedFunction};
pub use latex::{decimal, latex};
pub(crate) use paper::Paper;
pub use paper::{paper_equation, paper_latex};
pub use program::{Op, Program, Slot};
pub use tokens::{Emitted, f64_literal};
pub use typeset::{ALIGN_WIDTH, Lines, MethodCost, Typeset};
pub use workspace::EvalWorkspace;
pub(crate) use workspace::with_workspace;
