//! The sample times of a run: every step, a list, or a regular grid, checked against the
//! run's span and handed out step by step.

use super::error::OdeError;
use super::trajectory::MAX_SAMPLES;

/// The least sample interval of [`Run::sample_every`](super::Run::sample_every), in spacings
/// of the doubles at the larger of |t0|, |t_end| (one ulp there).
///
/// Each time is computed as t0 + k·dt: the product k·dt and the sum each round, by at most
/// two spacings and one, so two neighbouring times could come out equal when dt is within
/// six spacings; at eight they never do, and the times increase strictly.
pub const MIN_SAMPLE_SPACINGS: f64 = 8.0;

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
    /// [`OdeError::SampleAfterEnd`],
    /// [`OdeError::InvalidStep`] for an interval that is not finite and > 0,
    /// [`OdeError::SampleIntervalBelowResolution`] for one too fine for the doubles near the
    /// run's times, [`OdeError::TooManySamples`] beyond [`MAX_SAMPLES`].
    pub(crate) fn new(sampling: Sampling, t0: f64, t_end: f64) -> Result<Self, OdeError> {
        let count = match &sampling {
            Sampling::Steps => 0,
            Sampling::Times(times) => {
                check_count(times.len() as f64)?;
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
            &Sampling::Every(dt) => every_count(dt, t0, t_end)?,
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

/// The number of samples t0, t0 + dt, … ≤ t_end, after checking that they fit under
/// [`MAX_SAMPLES`] and that dt resolves the times of the run.
///
/// # Errors
/// [`OdeError::InvalidStep`], [`OdeError::SampleIntervalBelowResolution`],
/// [`OdeError::TooManySamples`].
fn every_count(dt: f64, t0: f64, t_end: f64) -> Result<usize, OdeError> {
    if !(dt.is_finite() && dt > 0.0) {
        return Err(OdeError::InvalidStep { h: dt });
    }
    let t = if t_end.abs() > t0.abs() { t_end } else { t0 };
    let spacing = ulp(t);
    if dt < MIN_SAMPLE_SPACINGS * spacing {
        return Err(OdeError::SampleIntervalBelowResolution { dt, t, spacing });
    }
    // The slack keeps t_end = t0 + n dt from losing its last sample to round-off. The count
    // stays in f64 until it is known to fit: a cast would saturate (or wrap, in older code).
    let samples = ((t_end - t0) / dt * (1.0 + 1e-12)).floor() + 1.0;
    check_count(samples)?;
    Ok(samples as usize)
}

/// Checks a number of samples against [`MAX_SAMPLES`] (∞ and NaN included).
///
/// # Errors
/// [`OdeError::TooManySamples`].
fn check_count(samples: f64) -> Result<(), OdeError> {
    if samples <= MAX_SAMPLES as f64 {
        Ok(())
    } else {
        Err(OdeError::TooManySamples {
            samples,
            max: MAX_SAMPLES,
        })
    }
}

/// The spacing of the doubles at `t`: the distance from |t| to the next double up.
fn ulp(t: f64) -> f64 {
    let a = t.abs();
    a.next_up() - a
}
