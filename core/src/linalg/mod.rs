//! Dense linear algebra beyond nalgebra's: eigenvalues of a general real matrix by a method
//! that always returns, Jacobians by central differences, and the linear system about a state
//! with its stability verdict, where that verdict changes along a parameter, and the
//! state-space form ẋ = A x + B u with inputs.
//!
//! nalgebra's `complex_eigenvalues` did not return on a 6×6 top Jacobian (a defective zero
//! eigenvalue from the cyclic coordinates); [`eigenvalues`] balances (isolating such zeros
//! exactly), reduces to Hessenberg form and runs the Francis double-shift QR iteration with
//! an iteration cap, so it terminates on every input.

mod balance;
mod crossing;
mod eigen;
mod error;
mod jacobian;
mod stability;
mod state_space;

pub use crossing::{
    CROSSING_TOLERANCE, Crossing, CrossingError, find_crossing, spectral_abscissa,
    stability_crossing,
};
pub use eigen::eigenvalues;
pub use error::LinalgError;
pub use jacobian::{JACOBIAN_STEP, jacobian, jacobian_of};
pub use stability::{LinearSystem, NEUTRAL_TOLERANCE, Stability};
pub use state_space::{OPERATING_POINT_TOLERANCE, SecondOrder, StateSpace, StateSpaceError};
