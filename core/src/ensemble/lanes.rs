//! An ensemble of Taylor runs stepped `L` at a time in batch lanes
//! ([`crate::taylor::batch::BatchTaylor`]), the chunks spread over rayon's threads.

use std::panic::{AssertUnwindSafe, catch_unwind};

use rayon::prelude::*;

use super::error::EnsembleError;
use super::results::EnsembleResults;
use super::runner::{Ensemble, Tally, panic_message};
use crate::ode::{OdeError, check_span};
use crate::taylor::Taylor;
use crate::taylor::batch::{BatchTaylor, TaylorLanes};

/// An [`Ensemble`] whose Taylor runs are stepped `L` at a time in batch lanes; made by
/// [`Ensemble::lanes`].
///
/// The runs are cut into chunks of `L` consecutive indices fixed by the range alone (the
/// last chunk may be short: its empty lanes are masked), and the chunks go to the threads.
#[derive(Debug, Clone)]
pub struct EnsembleLanes<'e, 'p, const L: usize> {
    ensemble: &'e Ensemble<'p>,
}

impl<'p> Ensemble<'p> {
    /// The same runs stepped `L` at a time in batch lanes: 4 for AVX2, 8 for AVX-512 (see
    /// `docs/lanes.md`). `L = 0` is refused at compile time.
    ///
    /// ```
    /// use precess_core::ensemble::Ensemble;
    /// let ensemble = Ensemble::new(0..10);
    /// let lanes = ensemble.lanes::<4>();
    /// # let _ = lanes;
    /// ```
    pub fn lanes<const L: usize>(&self) -> EnsembleLanes<'_, 'p, L> {
        const { assert!(L > 0, "a batch needs at least one lane") };
        EnsembleLanes { ensemble: self }
    }
}

impl<const L: usize> EnsembleLanes<'_, '_, L> {
    /// [`Ensemble::integrate`] for Taylor runs, `L` at a time: `build(index)` makes each
    /// run's [`Taylor`] integrator (system, parameters, initial state, configuration), the
    /// chunk's integrators are stepped together to `t_end`, and `output(index, &taylor)` is
    /// kept of each.
    ///
    /// **Bit-identical to the scalar ensemble.** With the same `build` and `output`, the
    /// outputs are those of [`Ensemble::integrate`] bit for bit (a lane takes the steps of
    /// its scalar run, [`BatchTaylor`]), on any number of threads; the chunks depend on the
    /// range, never on the threads.
    ///
    /// # Errors
    /// Per run, as [`EnsembleError::Run`]: `build`'s error; [`OdeError::NonFiniteTime`] or
    /// [`OdeError::EndBeforeStart`] when `t_end` is not a finite time at or after the
    /// run's start; the lane's own failures ([`OdeError::NonFiniteState`],
    /// [`OdeError::MaxStepsExceeded`], …, and [`OdeError::InvalidParameter`] for the
    /// extended mode, which lanes do not have), converted into `E`. The other lanes of the
    /// chunk go on. [`EnsembleError::Panicked`] for a panic in `build` or `output` (that
    /// run's), or in the system while the chunk steps (every unfinished run of the chunk).
    pub fn integrate<S, const N: usize, T, E, B, O>(
        &self,
        t_end: f64,
        build: B,
        output: O,
    ) -> EnsembleResults<T, E>
    where
        S: TaylorLanes<N, L>,
        B: Fn(usize) -> Result<Taylor<S, N>, E> + Sync,
        O: Fn(usize, &Taylor<S, N>) -> T + Sync,
        E: From<OdeError> + Send,
        T: Send,
    {
        let runs = self.ensemble.runs();
        let done = Tally::default();
        let chunks: Vec<Vec<Result<T, EnsembleError<E>>>> = (0..runs.len().div_ceil(L))
            .into_par_iter()
            .map(|c| {
                let lo = runs.start + c * L;
                // Saturating: a range ending at usize::MAX would wrap `lo + L` to an empty chunk.
                let hi = lo.saturating_add(L).min(runs.end);
                let results = chunk(lo..hi, t_end, &build, &output);
                for _ in lo..hi {
                    self.ensemble.report(&done);
                }
                results
            })
            .collect();
        EnsembleResults::new(runs.start, chunks.into_iter().flatten().collect())
    }
}

/// One chunk of at most `L` runs, `indices`: built, stepped in one batch, kept.
fn chunk<S, const N: usize, const L: usize, T, E, B, O>(
    indices: std::ops::Range<usize>,
    t_end: f64,
    build: &B,
    output: &O,
) -> Vec<Result<T, EnsembleError<E>>>
where
    S: TaylorLanes<N, L>,
    B: Fn(usize) -> Result<Taylor<S, N>, E>,
    O: Fn(usize, &Taylor<S, N>) -> T,
    E: From<OdeError>,
{
    // Each run's error so far (`None`: its lane is live).
    let mut errors: Vec<Option<EnsembleError<E>>> = Vec::with_capacity(L);
    let mut odes: [Result<Taylor<S, N>, OdeError>; L] = core::array::from_fn(|_| Err(EMPTY));
    for (l, index) in indices.clone().enumerate() {
        let built = catch_unwind(AssertUnwindSafe(|| build(index)));
        let (ode, error) = match built {
            Ok(Ok(ode)) => match check_span(ode.t(), t_end) {
                Ok(()) => (Ok(ode), None),
                Err(e) => (Err(EMPTY), Some(run_error(index, e))),
            },
            Ok(Err(source)) => (Err(EMPTY), Some(EnsembleError::Run { index, source })),
            Err(payload) => (Err(EMPTY), Some(panicked(index, payload.as_ref()))),
        };
        if let Some(slot) = odes.get_mut(l) {
            *slot = ode;
        }
        errors.push(error);
    }
    let mut batch = BatchTaylor::from_integrators(odes);
    let ends = match catch_unwind(AssertUnwindSafe(|| batch.advance_to([t_end; L]))) {
        Ok(ends) => ends.map(Some),
        Err(payload) => {
            // The system panicked mid-batch: no lane's state can be trusted.
            let message = panic_message(payload.as_ref());
            return indices
                .zip(errors)
                .map(|(index, error)| {
                    Err(error.unwrap_or_else(|| EnsembleError::Panicked {
                        index,
                        message: message.clone(),
                    }))
                })
                .collect();
        }
    };
    indices
        .zip(errors)
        .zip(ends)
        .enumerate()
        .map(|(l, ((index, error), end))| {
            if let Some(error) = error {
                return Err(error);
            }
            match (end, batch.lane(l)) {
                (Some(Ok(_)), Some(Ok(ode))) => {
                    catch_unwind(AssertUnwindSafe(|| output(index, ode)))
                        .map_err(|payload| panicked(index, payload.as_ref()))
                }
                (Some(Err(e)), _) | (_, Some(Err(e))) => Err(run_error(index, e)),
                // A lane of the chunk always has its end and its integrator.
                _ => Err(run_error(index, EMPTY)),
            }
        })
        .collect()
}

/// The placeholder of a lane no run fills (the tail of the last chunk, or a run that
/// failed before stepping); its result is never read.
const EMPTY: OdeError = OdeError::InvalidParameter {
    name: "lane without a run",
    value: f64::NAN,
};

fn run_error<E: From<OdeError>>(index: usize, e: OdeError) -> EnsembleError<E> {
    EnsembleError::Run {
        index,
        source: e.into(),
    }
}

fn panicked<E>(index: usize, payload: &(dyn std::any::Any + Send)) -> EnsembleError<E> {
    EnsembleError::Panicked {
        index,
        message: panic_message(payload),
    }
}
