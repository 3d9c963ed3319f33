//! `#[top(...)]`: the body as a top about its pivot, its declared torques and angle
//! sequence, in the same phases as `#[rigid]`: `attr` (syntax), `check` (meaning, with the
//! `#[rigid]` value rules in the same arena), `expand` (the `TopDynamics` impl) and `fallback` (its
//! stub). It reads the struct through `rigid::ast`.

pub mod attr;
pub mod check;
pub mod equations;
pub mod expand;
pub mod fallback;

#[cfg(test)]
mod tests;
