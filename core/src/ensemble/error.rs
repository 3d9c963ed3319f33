//! What one run of an ensemble can end in besides its output.

/// Why one run of an ensemble gave no output; every variant names the run.
///
/// One run's error never stops the others: the ensemble's results hold it at the run's
/// place, beside the outputs of the runs that succeeded.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum EnsembleError<E> {
    /// The run's closure returned an error (for [`super::Ensemble::integrate`]: building
    /// the stepper, or a step, failed).
    #[error("run {index} failed: {source}")]
    Run {
        /// The run's index.
        index: usize,
        /// The closure's error.
        #[source]
        source: E,
    },
    /// The run's closure panicked; the panic was caught at the run and went no further.
    #[error("run {index} panicked: {message}")]
    Panicked {
        /// The run's index.
        index: usize,
        /// The panic's message (`<no message>` when its payload was not text).
        message: String,
    },
}

impl<E> EnsembleError<E> {
    /// The index of the run that failed.
    pub fn index(&self) -> usize {
        match self {
            EnsembleError::Run { index, .. } | EnsembleError::Panicked { index, .. } => *index,
        }
    }
}
