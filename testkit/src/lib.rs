//! What the integration tests, the benches and the work-precision example of precess share,
//! compiled once and optimised (the test crates themselves are not): the seeded generator,
//! reference systems with published values, the independent oracles that run long (bodies
//! as particle lattices summed directly, a Newton–Euler body on a table, a recursive
//! Newton–Euler mechanism, the Monte Carlo example's ensemble), and the work-precision
//! report (the example writes it in full, a test runs its cheap rungs).
#![forbid(unsafe_code)]

// The example code included below names this crate as its users do.
extern crate self as precess_testkit;

pub mod bicycle;
pub mod constrained;
pub mod contact;
pub mod euler;
pub mod eulerian_top;
pub mod linkages;
pub mod mechanism;
/// The uncertain heavy top of the `monte_carlo_top` example, its very file included, so
/// that its physics test runs the example's code optimised: the test's thousands of DOP853
/// runs of the derived top, compiled in the test crate, took 13 s.
#[path = "../../examples/common/monte_carlo.rs"]
pub mod monte_carlo;
pub mod newton_euler;
pub mod particles;
pub mod rng;
pub mod rotations;
pub mod scenes;
pub mod systems;
pub mod work_precision;
