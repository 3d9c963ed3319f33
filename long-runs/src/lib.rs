//! The tests of precess that are long runs by design, in `tests/`: a closed-loop linkage over
//! 10⁴ crank turns. They are a crate of their own because the integration test crates compile
//! without optimisation (cheap to build, and quick where their work is in precess-core), while
//! a long run's stepper and loop solver are generic code instantiated in the crate that runs
//! them: here they compile at opt-level 3 (the workspace's Cargo.toml), and the run takes seconds
//! instead of minutes.
#![forbid(unsafe_code)]
