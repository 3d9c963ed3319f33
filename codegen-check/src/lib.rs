//! Test-only crate: the build script emits a few hundred random expressions through
//! precess-core's code generator, and this crate compiles them, so the tests can run the
//! emitted Rust beside the interpreter of the same program.
#![forbid(unsafe_code)]

pub mod generator;

/// A generated function: symbol values in (by index), the program's outputs out.
pub type Generated = fn(&[f64]) -> Vec<f64>;

/// The functions the build script emitted: `FUNCTIONS[k]` computes program `k`.
pub mod generated {
    use super::Generated;

    include!(concat!(env!("OUT_DIR"), "/generated.rs"));
}
