//! What the integration tests, the benches and the work-precision example of precess share,
//! compiled once: the seeded generator, reference systems with published values, and the
//! work-precision report (the example writes it in full, a test runs its cheap rungs).
#![forbid(unsafe_code)]

pub mod bicycle;
pub mod rng;
pub mod scenes;
pub mod systems;
pub mod work_precision;
