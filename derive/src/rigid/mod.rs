//! `#[rigid(...)]`: the body's parts and pivot, in the phases every attribute of the derive
//! has over `lang/`: `attr` (syntax), `check` (meaning and the body's rules), `expand` (the
//! `RigidBody` impl, and with `taylor = K` the torque-free Euler equations' `System<3>` and
//! `TaylorSystem<3>` in `expand/euler.rs`) and `fallback` (the stub).

pub mod attr;
pub mod check;
pub mod expand;
pub mod fallback;

#[cfg(test)]
mod tests;
