//! Ensembles: many runs at once, spread over every core.
//!
//! An [`Ensemble`] is a range of run indices and a user closure that turns an index into one
//! finished run — it builds the initial state, parameters and tolerances from the index,
//! integrates with any integrator, and returns what is kept (the output function). The runs
//! go to the threads of the current rayon pool; [`Ensemble::run`] keeps every result at its
//! index ([`EnsembleResults`]), [`Ensemble::reduce`] folds them into one value instead, and
//! [`Ensemble::integrate`] is the common case of a [`crate::ode::Stepper`] taken to an end
//! time. [`Ensemble::lanes`] steps Taylor runs `L` at a time in batch lanes
//! ([`EnsembleLanes::integrate`]), with the same outputs bit for bit.
//!
//! # Guarantees
//! - **Determinism.** A run's result depends only on its index (given a closure that does):
//!   the same bits serially, on one thread or on many, in any order the runs happen to
//!   finish. The interpreted models evaluate in a workspace of the calling thread that each
//!   call clears of its inputs, so sharing one model between threads changes nothing.
//!   [`Ensemble::reduce`] folds in blocks fixed by the number of runs, not the threads.
//! - **Errors stay with their run.** An error the closure returns is
//!   [`EnsembleError::Run`] and a panic is caught and becomes [`EnsembleError::Panicked`],
//!   both with the run's index; the other runs finish and keep their outputs. (A panic is
//!   still printed by the panic hook; under `panic = "abort"` it cannot be caught.)
//! - **No runs** (an empty range) is no error: the results are empty and a reduction is its
//!   identity, so a shard that happens to get no runs needs no special case.
//! - **Threads.** The current rayon pool: all cores by default, a chosen number inside
//!   `rayon::ThreadPoolBuilder::new().num_threads(k).build()?.install(|| …)` ([`rayon`] is
//!   re-exported here).
//!
//! A model shared by the runs must be `Send + Sync`: every model of precess is (the
//! interpreted ones keep their scratch space outside themselves), as are the steppers over
//! them.
//!
//! # Examples
//! The decay y′ = −k y from y(0) = 1 for k = 1, 1.5, 2, …, to t = 2, against e^(−2k):
//!
//! ```
//! use precess_core::ensemble::Ensemble;
//! use precess_core::ode::{AdaptiveConfig, Dop853, FnSystem, OdeError};
//!
//! let rate = |i: usize| 1.0 + 0.5 * i as f64;
//! let results = Ensemble::new(0..8).integrate(
//!     2.0,
//!     |i| {
//!         let k = rate(i);
//!         let decay = FnSystem(move |_t: f64, y: &[f64; 1], d: &mut [f64; 1]| d[0] = -k * y[0]);
//!         Dop853::new(decay, 0.0, [1.0], AdaptiveConfig::with_tol(1e-12, 1e-14))
//!     },
//!     |_, ode| ode.y()[0],
//! );
//! for (i, y) in results.outputs() {
//!     approx::assert_relative_eq!(*y, (-2.0 * rate(i)).exp(), max_relative = 1e-10);
//! }
//! assert_eq!(results.failures(), 0);
//!
//! // The same runs summed instead of kept: a range of indices, a closure, a fold.
//! let total = Ensemble::new(0..8).reduce(
//!     |i| Ok::<f64, OdeError>((-2.0 * rate(i)).exp()),
//!     || 0.0,
//!     |acc, _, r| acc + r.unwrap_or(0.0),
//!     |a, b| a + b,
//! );
//! approx::assert_relative_eq!(total, (0..8).map(|i| (-2.0 * rate(i)).exp()).sum::<f64>());
//! ```

mod error;
mod integrate;
mod lanes;
mod results;
mod runner;

pub use error::EnsembleError;
pub use lanes::EnsembleLanes;
pub use results::EnsembleResults;
pub use runner::{Ensemble, EnsembleProgress, MAX_REDUCE_BLOCKS};

/// The thread-pool crate the ensembles run on, re-exported so a caller picks a number of
/// threads (`rayon::ThreadPoolBuilder`) with the same version.
pub use rayon;
