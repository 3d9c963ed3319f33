//! Spreading an ensemble's runs over the threads of rayon's pool, each run caught on its own.

use std::ops::Range;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use rayon::prelude::*;

use super::error::EnsembleError;
use super::results::EnsembleResults;

/// How far an ensemble has got, as given to the callback of [`Ensemble::progress`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct EnsembleProgress {
    /// Runs finished (succeeded or failed) so far.
    pub done: usize,
    /// Runs in the ensemble.
    pub total: usize,
}

impl EnsembleProgress {
    /// `done / total`, 1 for an ensemble of no runs.
    pub fn fraction(&self) -> f64 {
        if self.total == 0 {
            1.0
        } else {
            self.done as f64 / self.total as f64
        }
    }
}

/// The most blocks [`Ensemble::reduce`] folds a range into: enough to keep every core busy,
/// few enough that the blocks' partial results cost nothing to keep.
pub const MAX_REDUCE_BLOCKS: usize = 4096;

/// N runs, named by the indices of a range, spread over the threads of the current rayon
/// pool.
///
/// Each run is a user closure of its index, `Fn(usize) -> Result<T, E>`, which builds the
/// run (initial state, parameters, tolerances), integrates it with any integrator and
/// returns what should be kept of it. See the [module docs](super) for the guarantees.
#[derive(Clone)]
pub struct Ensemble<'p> {
    runs: Range<usize>,
    progress: Option<&'p (dyn Fn(EnsembleProgress) + Sync)>,
}

impl std::fmt::Debug for Ensemble<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Ensemble")
            .field("runs", &self.runs)
            .field("progress", &self.progress.is_some())
            .finish()
    }
}

impl<'p> Ensemble<'p> {
    /// The runs with the indices in `runs`; an empty range (also `start > end`) is an
    /// ensemble of no runs, whose results are empty and whose reduction is the identity.
    ///
    /// A range rather than a count so that a shard of a larger ensemble is the same call:
    /// machine k of n runs its own sub-range, and each run still sees its global index.
    pub fn new(runs: Range<usize>) -> Ensemble<'p> {
        let runs = if runs.start > runs.end {
            runs.start..runs.start
        } else {
            runs
        };
        Ensemble {
            runs,
            progress: None,
        }
    }

    /// Calls `report` after each run finishes, from the thread that ran it (so in no
    /// particular order; `done` counts up to `total` all the same). For a progress bar.
    ///
    /// A panic in `report` is caught where it is called: every run goes on and keeps its
    /// result, and `report` is not called again in that ensemble call (a progress bar that
    /// broke once would only panic again).
    pub fn progress(mut self, report: &'p (dyn Fn(EnsembleProgress) + Sync)) -> Ensemble<'p> {
        self.progress = Some(report);
        self
    }

    /// The indices of the runs.
    pub fn runs(&self) -> Range<usize> {
        self.runs.clone()
    }

    /// Runs `f` on every index and keeps each result at its index.
    ///
    /// # Errors
    /// None for the ensemble as a whole; each run's own failure is in the results:
    /// [`EnsembleError::Run`] for an error `f` returned, [`EnsembleError::Panicked`] for a
    /// panic, each with the run's index.
    pub fn run<T, E, F>(&self, f: F) -> EnsembleResults<T, E>
    where
        F: Fn(usize) -> Result<T, E> + Sync,
        T: Send,
        E: Send,
    {
        let done = Tally::default();
        let results = self
            .runs
            .clone()
            .into_par_iter()
            .map(|index| {
                let r = run_one(index, &f);
                self.report(&done);
                r
            })
            .collect();
        EnsembleResults::new(self.runs.start, results)
    }

    /// Runs `f` on every index and folds the results, failures included, into one value
    /// without keeping them: `fold(acc, index, result)` over consecutive blocks of runs in
    /// index order, each block starting from `identity()`, then `combine(left, right)` over
    /// the blocks in order.
    ///
    /// The blocks are fixed by the number of runs alone (at most [`MAX_REDUCE_BLOCKS`] of
    /// them), never by the threads, so a floating-point sum comes out to the same bits on
    /// any number of threads. No runs: `identity()`.
    ///
    /// A panic in `f` is caught and folded as the run's [`EnsembleError::Panicked`]; one in
    /// the [`progress`](Ensemble::progress) callback is caught and silences it, the runs
    /// going on and every result folded; one in `identity`, `fold` or `combine` is the
    /// caller's own and is not caught (it ends the call and loses the partial results).
    pub fn reduce<T, E, A, F, I, G, C>(&self, f: F, identity: I, fold: G, combine: C) -> A
    where
        F: Fn(usize) -> Result<T, E> + Sync,
        I: Fn() -> A + Sync,
        G: Fn(A, usize, Result<T, EnsembleError<E>>) -> A + Sync,
        C: Fn(A, A) -> A,
        A: Send,
    {
        let n = self.runs.len();
        let block = n.div_ceil(MAX_REDUCE_BLOCKS).max(1);
        let done = Tally::default();
        let start = self.runs.start;
        let partials: Vec<A> = (0..n.div_ceil(block))
            .into_par_iter()
            .map(|b| {
                let (lo, hi) = (start + b * block, start + ((b + 1) * block).min(n));
                (lo..hi).fold(identity(), |acc, index| {
                    let r = run_one(index, &f);
                    self.report(&done);
                    fold(acc, index, r)
                })
            })
            .collect();
        partials.into_iter().fold(identity(), combine)
    }

    /// Counts a finished run and calls the progress callback, if any, catching its panic.
    pub(super) fn report(&self, done: &Tally) {
        let finished = done.runs.fetch_add(1, Ordering::Relaxed) + 1;
        let Some(report) = self.progress else {
            return;
        };
        if done.silenced.load(Ordering::Relaxed) {
            return;
        }
        let progress = EnsembleProgress {
            done: finished,
            total: self.runs.len(),
        };
        // `AssertUnwindSafe`: the callback is the user's and only borrowed; after its panic
        // it is not called again, and the ensemble's own state is the two atomics.
        if catch_unwind(AssertUnwindSafe(|| report(progress))).is_err() {
            done.silenced.store(true, Ordering::Relaxed);
        }
    }
}

/// The runs finished so far in one ensemble call, and whether its progress callback has
/// panicked (and so is called no more).
#[derive(Debug, Default)]
pub(super) struct Tally {
    runs: AtomicUsize,
    silenced: AtomicBool,
}

/// Runs `f(index)`, a panic caught and turned into the run's error.
///
/// `AssertUnwindSafe`: the closure is the user's and only borrowed; a panic in it loses
/// that run's result, and anything it had half-changed through shared interior mutability
/// is the user's to judge — the ensemble itself holds no state a panic could break.
fn run_one<T, E>(
    index: usize,
    f: &(impl Fn(usize) -> Result<T, E> + Sync),
) -> Result<T, EnsembleError<E>> {
    match catch_unwind(AssertUnwindSafe(|| f(index))) {
        Ok(Ok(output)) => Ok(output),
        Ok(Err(source)) => Err(EnsembleError::Run { index, source }),
        Err(payload) => Err(EnsembleError::Panicked {
            index,
            message: panic_message(payload.as_ref()),
        }),
    }
}

/// The text of a panic's payload (`panic!` gives a `&str` or a `String`).
pub(super) fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_owned()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "<no message>".to_owned()
    }
}
