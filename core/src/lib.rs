//! precess-core: the symbolic engine, rigid-body mechanics, integrators and exact solutions
//! behind `precess`.
//!
//! The `#[derive(RigidBody)]` macro in `precess-derive` calls into this crate while it expands,
//! so everything the macro computes at compile time can also be computed at run time here.
//!
//! The layers, lowest first: the engine ([`sym`], [`codegen`], [`lagrange`], [`linalg`],
//! [`ode`], [`taylor`], [`exact`], and [`ensemble`], which runs many integrations at once);
//! the bodies and what every scene shares ([`body`], [`rigid`]); the scenes ([`top`],
//! [`free`], [`mechanism`], [`contact`]), each built on the layers below and none importing
//! another; above them [`variational`], the state transition matrix and Lyapunov exponents
//! of any symbolic right-hand side, the scenes' included. The SVG figures of a run's
//! trajectory and of work–precision measurements are a crate of their own over this one,
//! `precess-plot` (the facade's `plot` feature, `precess::plot`). Every scene has
//! the same files for the same roles (`scene.rs`, `derivation.rs`, `interpreted.rs`,
//! `dynamics.rs`, `error.rs`, `quantities.rs`); `docs/conventions.md` states the shape.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod body;
pub mod codegen;
pub mod contact;
pub mod ensemble;
pub mod exact;
pub mod free;
pub mod lagrange;
#[cfg(test)]
mod layering;
pub mod linalg;
pub mod mechanism;
pub mod ode;
pub mod rigid;
pub mod sym;
pub mod taylor;
pub mod top;
pub mod variational;

/// The linear-algebra crate precess's types come from, re-exported so users and generated
/// code agree on one version.
pub use nalgebra;
