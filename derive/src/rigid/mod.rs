//! `#[rigid(...)]`: the body's parts and pivot, in the phases every attribute of the derive
//! has: `ast` (borrowed view of the input), `attr` (syntax), `check` (meaning, with the value
//! language in `values`), `expand` (the `RigidBody` impl) and `fallback` (its stub).

pub mod ast;
pub mod attr;
pub mod check;
pub mod expand;
pub mod fallback;
pub(crate) mod values;

#[cfg(test)]
mod tests;
