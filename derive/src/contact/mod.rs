//! `#[contact(...)]`: the body on a table, touching it with one convex surface under a
//! contact law, in the phases every attribute has over `lang/`: `attr` (syntax), `check`
//! (meaning, its values read by the shared checker into the arena `#[rigid]` built),
//! `expand` (the `ContactDynamics` impl) and `fallback` (its stub); `forms` reads the
//! surface's and the law's call forms for `check`.

pub mod attr;
pub mod check;
pub mod expand;
pub mod fallback;
mod forms;

#[cfg(test)]
mod tests;
