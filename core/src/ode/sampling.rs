//! The sample times of a run: every step, a list, or a regular grid, checked against the
//! run's span and handed out step by step.

use super::error::OdeError;

/// Which samples a run records.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Sampling {
    /// The start and every accepted step (the default).
    Steps,
    /// The given times, by the stepper's solution inside each step.
    Times(Vec<f64>),
    /// t0, t0 + dt, … up to the end.
    Every(f64),
}

/// The sample times of a run, handed out step by step.
pub(crate) struct SampleClock {
    sampling: Sampling,
    t0: f64,
    /// Index of the next sample.
    next: usize,
    /// Number of samples (for `Every`; the list's length for `Times`).
    count: usize,
    t_end: f64,
}

impl SampleClock {
    /// Checks the sampling against the span `[t0, t_end]`.
    ///
    /// # Errors
    /// [`OdeError::NonFiniteTime`], [`OdeError::StopBeforeCurrent`] (unsorted or before t0),
    /// [`OdeError::SampleAfterEnd`], [`OdeError::InvalidStep`] for a bad interval.
    pub(crate) fn new(sampling: Sampling, t0: f64, t_end: f64) -> Result<Self, OdeError> {
        let count = match &sampling {
            Sampling::Steps => 0,
            Sampling::Times(times) => {
                let mut last = t0;
                for &t in times {
                    if !t.is_finite() {
                        return Err(OdeError::NonFiniteTime { t });
                    }
                    if t < last {
                        return Err(OdeError::StopBeforeCurrent { stop: t, t: last });
                    }
                    if t > t_end {
                        return Err(OdeError::SampleAfterEnd { t, t_end });
                    }
                    last = t;
                }
                times.len()
            }
            &Sampling::Every(dt) => {
                if !(dt.is_finite() && dt > 0.0) {
                    return Err(OdeError::InvalidStep { h: dt });
                }
                // The slack keeps t_end = t0 + n dt from losing its last sample to round-off.
                ((t_end - t0) / dt * (1.0 + 1e-12)).floor() as usize + 1
            }
        };
        Ok(Self {
            sampling,
            t0,
            next: 0,
            count,
            t_end,
        })
    }

    /// Whether every step is recorded.
    pub(crate) fn steps(&self) -> bool {
        self.sampling == Sampling::Steps
    }

    /// The time of sample `i`.
    fn time(&self, i: usize) -> f64 {
        match &self.sampling {
            Sampling::Steps => self.t0,
            Sampling::Times(times) => times.get(i).copied().unwrap_or(f64::INFINITY),
            Sampling::Every(dt) => (self.t0 + i as f64 * dt).min(self.t_end),
        }
    }

    /// Whether a sample falls on the start (and takes it).
    pub(crate) fn take_start(&mut self, t0: f64) -> bool {
        if self.steps() {
            return true;
        }
        let at_start = self.next < self.count && self.time(self.next) <= t0;
        if at_start {
            self.next += 1;
        }
        at_start
    }

    /// The next sample time if it is at most `t_stop` (and takes it).
    pub(crate) fn next_until(&mut self, t_stop: f64) -> Option<f64> {
        if self.next >= self.count {
            return None;
        }
        let t = self.time(self.next);
        (t <= t_stop).then(|| {
            self.next += 1;
            t
        })
    }
}
