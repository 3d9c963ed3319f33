//! `#[rigid(...)]`: the body's parts and pivot, in the phases every attribute of the derive
//! has: `ast` (borrowed view of the input), `attr` (syntax), `check` (meaning, with the value
//! language in `values`), `expand` (the `RigidBody` impl), `taylor` (the torque-free Euler
//! equations' `System<3>` and `TaylorSystem<3>`, with `taylor = K`) and `fallback` (the
//! stub).

pub mod ast;
pub mod attr;
pub mod check;
pub mod expand;
pub mod fallback;
mod taylor;
pub(crate) mod values;

#[cfg(test)]
mod tests;
