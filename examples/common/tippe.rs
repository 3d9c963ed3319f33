//! The tippe top of `tippe_top` and `tippe_sweep`: the library's ready model
//! ([`precess::models::TippeTop`]), so that the sweep runs the same body the single run does.
//! Included by path (`#[path = "common/tippe.rs"] mod tippe;`).

#![allow(dead_code)] // each example uses the part it needs

pub use precess::models::TippeTop as Top;

/// The closed forms of the same top ([`precess::models::TippeTop::theory`]).
pub fn theory() -> precess::contact::theory::TippeTop {
    Top::theory()
}

/// The start: see [`precess::models::TippeTop::start`].
pub fn start(tilt: f64, spin: f64) -> [f64; precess::contact::STATE_LEN] {
    Top::start(tilt, spin)
}

/// cos θ of the symmetry axis with the vertical: see [`precess::models::TippeTop::axis_up`].
pub fn axis_up(y: &[f64; precess::contact::STATE_LEN]) -> f64 {
    Top::axis_up(y)
}
