//! What the integration tests, the benches and the work-precision example of precess share,
//! compiled once and optimised (the test crates themselves are not): the seeded generator,
//! reference systems with published values, the independent oracles that run long (bodies
//! as particle lattices summed directly, a Newton–Euler body on a table, a recursive
//! Newton–Euler mechanism), and the
//! work-precision report (the example writes it in full, a test runs its cheap rungs).
#![forbid(unsafe_code)]

pub mod bicycle;
pub mod linkages;
pub mod mechanism;
pub mod newton_euler;
pub mod particles;
pub mod rng;
pub mod scenes;
pub mod systems;
pub mod work_precision;
