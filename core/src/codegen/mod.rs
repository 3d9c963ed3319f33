//! Code generation: expressions to straight-line programs, Rust tokens and LaTeX.
//!
//! [`Program::lower`] turns the outputs of a derivation into one instruction list with every
//! common subexpression computed once. The same program is
//! - emitted as Rust ([`Program::to_tokens`]), which is what the derive macro splices in;
//! - interpreted in f64 ([`Program::eval`]), the oracle the emitted code is tested against;
//! - counted ([`Program::op_count`]), the cost model the reports print.
//!
//! [`latex`] renders an expression for a reader.

mod count;
mod interp;
mod latex;
mod program;
mod tokens;

pub use count::OpCount;
pub use latex::latex;
pub use program::{Op, Program, Slot};
pub use tokens::{Emitted, f64_literal};
