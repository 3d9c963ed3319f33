//! `taylor_system!`: an ODE `y' = f(t, y)` the user writes as equations, turned into the
//! symbolic engine's expressions while the macro expands, and emitted as the struct with
//! `impl System<N>`, `impl TaylorSystem<N>` and `impl TaylorLanes<N, L>` (`lanes`), and a
//! type per `event Name = g;` whose Taylor coefficients are compiled (`events`). The phases of the derives over `lang/`:
//! `attr` (syntax), `check` (names and counts), `values` (the right-hand sides' expression
//! language into the arena) and `expand` (the impls). It has no fallback: after an error the
//! struct alone is emitted, so its uses raise no errors of their own.

mod attr;
mod check;
mod events;
mod expand;
pub(crate) mod lanes;
mod values;

pub use expand::expand;
