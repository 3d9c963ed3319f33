//! `#[free(...)]`: the body as a free body under its declared forces, in the same phases as
//! `#[top]`: `attr` (syntax), `check` (meaning, with the `#[rigid]` value rules in the same
//! arena), `expand` (the `FreeDynamics` impl) and `fallback` (its stub).

pub mod attr;
pub mod check;
pub mod expand;
pub mod fallback;

#[cfg(test)]
mod tests;
