//! `#[contact(...)]`: the body on a table, touching it with one convex surface under a
//! contact law, in the phases every attribute has over `lang/`: `attr` (syntax), `check`
//! (meaning, its values read by the shared checker into the arena `#[rigid]` built),
//! `expand` (the `ContactDynamics` impl) and `fallback` (its stub).

pub mod attr;
pub mod check;
pub mod expand;
pub mod fallback;

#[cfg(test)]
mod tests;
