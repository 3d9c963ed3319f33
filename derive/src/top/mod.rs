//! `#[top(...)]`: the body as a top about its pivot, its declared torques and angle
//! sequence, in the phases every attribute has over `lang/`: `attr` (syntax), `check`
//! (meaning, its values read by the shared checker into the arena `#[rigid]` built), `expand`
//! (the `TopDynamics` impl, with its chart-dispatched methods in `charts`, its typeset
//! equations in `equations` and a driven top's methods in `driven`) and `fallback` (its stub); `variational` is the top's side of the
//! `variational(...)` group, whose checks and emission are `lang::variational`'s.

pub mod attr;
pub mod charts;
pub mod check;
pub mod driven;
pub mod equations;
pub mod expand;
pub mod fallback;
pub mod variational;

#[cfg(test)]
mod tests;
