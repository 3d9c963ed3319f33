//! The outputs of an ensemble's runs, each at its run's index.

use std::ops::Range;

use super::error::EnsembleError;

/// One result per run, in the order of the runs' indices, whatever order they finished in.
///
/// Built by [`super::Ensemble::run`] and [`super::Ensemble::integrate`].
///
/// ```
/// use precess_core::ensemble::{Ensemble, EnsembleError};
/// let results = Ensemble::new(10..14).run(|i| if i == 12 { Err("odd one out") } else { Ok(i * i) });
/// assert_eq!(results.runs(), 10..14);
/// assert_eq!(results.get(11), Some(&Ok(121)));
/// assert_eq!(results.outputs().collect::<Vec<_>>(), [(10, &100), (11, &121), (13, &169)]);
/// assert!(matches!(results.errors().next(), Some(EnsembleError::Run { index: 12, .. })));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct EnsembleResults<T, E> {
    start: usize,
    results: Vec<Result<T, EnsembleError<E>>>,
}

impl<T, E> EnsembleResults<T, E> {
    pub(super) fn new(start: usize, results: Vec<Result<T, EnsembleError<E>>>) -> Self {
        EnsembleResults { start, results }
    }

    /// The indices of the runs.
    pub fn runs(&self) -> Range<usize> {
        self.start..self.start + self.results.len()
    }

    /// The number of runs.
    pub fn len(&self) -> usize {
        self.results.len()
    }

    /// Whether there were no runs.
    pub fn is_empty(&self) -> bool {
        self.results.is_empty()
    }

    /// The result of run `index` (`None` outside [`EnsembleResults::runs`]).
    pub fn get(&self, index: usize) -> Option<&Result<T, EnsembleError<E>>> {
        self.results.get(index.checked_sub(self.start)?)
    }

    /// Every run's index and result, in index order.
    pub fn iter(&self) -> impl ExactSizeIterator<Item = (usize, &Result<T, EnsembleError<E>>)> {
        self.runs().zip(&self.results)
    }

    /// The outputs of the runs that succeeded, with their indices, in index order.
    pub fn outputs(&self) -> impl Iterator<Item = (usize, &T)> {
        self.iter()
            .filter_map(|(i, r)| r.as_ref().ok().map(|t| (i, t)))
    }

    /// The errors of the runs that failed, in index order (each names its run).
    pub fn errors(&self) -> impl Iterator<Item = &EnsembleError<E>> {
        self.results.iter().filter_map(|r| r.as_ref().err())
    }

    /// The number of runs that failed.
    pub fn failures(&self) -> usize {
        self.errors().count()
    }

    /// The results, in index order; the first is run [`EnsembleResults::runs`]`.start`.
    pub fn into_vec(self) -> Vec<Result<T, EnsembleError<E>>> {
        self.results
    }
}

impl<T, E> IntoIterator for EnsembleResults<T, E> {
    type Item = Result<T, EnsembleError<E>>;
    type IntoIter = std::vec::IntoIter<Result<T, EnsembleError<E>>>;

    /// The results by value, in index order.
    fn into_iter(self) -> Self::IntoIter {
        self.results.into_iter()
    }
}
