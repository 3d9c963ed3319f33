//! Closed forms for bodies on a table, to measure the contact scenes against: the tippe top's
//! inverted state from Jellett's integral, the rolling disk's steady circles, accelerations and
//! upright stability, the integrals of a rolling sphere (Routh's, Chaplygin's), and the
//! finite-time collapse of Euler's disk under an air-layer dissipation.
//!
//! Frames: space z is up, the table is z = 0, gravity g points along −z. A body's attitude q
//! turns its description axes into space axes; ω is given in body (description) axes and
//! turned with q where a formula needs it in space. Every function is plain arithmetic on f64:
//! outside a formula's stated domain it returns `None` or a NaN, never panics.
//!
//! They sit beside the scene they describe and check it: the contact tests hold them
//! against runs of derived bodies.

mod disk;
mod sphere;

pub use disk::{
    DiskAccelerations, DiskState, EulerDisk, RollingDisk, SteadyCircle, power_law_exponents,
};
pub use sphere::{SphereBody, TippeTop};
