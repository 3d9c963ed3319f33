//! Lyapunov exponents by Benettin's method: carry m tangent vectors, re-orthonormalise them
//! every interval by Gram–Schmidt (the QR factorisation of the tangent matrix), and average
//! the logs of R's diagonal over time (Benettin, Galgani, Giorgilli & Strelcyn 1980).

use super::error::VariationalError;
use super::layout::{Layout, check_finite};
use super::system::VariationalSystem;
use crate::ode::{AdaptiveConfig, Dop853, Stats, Stepper};

/// The most renormalisation intervals one [`benettin`] run takes (transient and average
/// together): 10⁹, some days of the cheapest system's right-hand sides.
pub const MAX_INTERVALS: u64 = 1_000_000_000;

/// The smallest a tangent vector's new length Rⱼⱼ may get between re-orthonormalisations
/// before it is re-orthonormalised at once, at the end of the step that shrank it: 2⁻¹⁰.
///
/// The integrator controls each entry's error against atol + rtol·|y|, so a tangent vector
/// that shrinks towards atol is no longer followed to any relative accuracy, and its
/// logarithm — the exponent — is lost: x′ = −1000 x renormalised every unit of time gave
/// −27.8 for −1000. Renormalising in time keeps every vector near length 1 (its relative
/// error the integrator's rtol) whatever the interval; where no vector shrinks that far
/// within an interval, nothing changes.
pub const SHRINK_FLOOR: f64 = 1.0 / 1024.0;

/// How long to average and how often to re-orthonormalise.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BenettinConfig {
    /// Time between re-orthonormalisations: short enough that the tangent vectors neither
    /// overflow nor collapse onto one direction in floating point (a few e-folding times of
    /// the largest exponent at most). A vector that shrinks below [`SHRINK_FLOOR`] within
    /// an interval is re-orthonormalised earlier, at the end of that step.
    pub interval: f64,
    /// Time over which the logs are averaged, after the transient.
    pub duration: f64,
    /// Time integrated (and re-orthonormalised) first without averaging, so the tangent
    /// vectors align with the Lyapunov directions and x settles on its attractor.
    pub transient: f64,
}

impl BenettinConfig {
    /// Checks the three times.
    ///
    /// # Errors
    /// [`VariationalError::NonPositiveInterval`], [`VariationalError::NonPositiveDuration`],
    /// [`VariationalError::InvalidTransient`], [`VariationalError::TooManyIntervals`].
    pub fn validate(&self) -> Result<(), VariationalError> {
        let positive = |v: f64| v.is_finite() && v > 0.0;
        if !positive(self.interval) {
            return Err(VariationalError::NonPositiveInterval {
                interval: self.interval,
            });
        }
        if !positive(self.duration) {
            return Err(VariationalError::NonPositiveDuration {
                duration: self.duration,
            });
        }
        if !(self.transient.is_finite() && self.transient >= 0.0) {
            return Err(VariationalError::InvalidTransient {
                transient: self.transient,
            });
        }
        let intervals =
            (self.transient / self.interval).ceil() + (self.duration / self.interval).ceil();
        // Finite or +∞ (a tiny interval), never NaN: the three times are checked above.
        if intervals > MAX_INTERVALS as f64 {
            return Err(VariationalError::TooManyIntervals {
                intervals,
                max: MAX_INTERVALS,
            });
        }
        Ok(())
    }
}

/// The m largest Lyapunov exponents, largest first, over a finite time.
#[derive(Debug, Clone, PartialEq)]
pub struct LyapunovSpectrum {
    /// λ₁ ≥ λ₂ ≥ … (in the order Gram–Schmidt gives them, which is descending once the
    /// vectors have aligned).
    pub exponents: Vec<f64>,
    /// The time averaged over.
    pub time: f64,
    /// Renormalisation intervals averaged over (the early re-orthonormalisations within
    /// them, [`SHRINK_FLOOR`], are not counted).
    pub renormalisations: u64,
    /// The stepper's work, transient included.
    pub stats: Stats,
}

/// A generic starting basis for the m tangent vectors: orthonormalised columns of a fixed
/// matrix with no special alignment (the identity's columns can be exactly orthogonal to an
/// unstable direction of a symmetric system, and would then never see it).
fn starting_basis(layout: Layout, y: &mut [f64]) -> Result<(), VariationalError> {
    for j in 0..layout.tangents {
        for (i, v) in y[layout.tangent(j)].iter_mut().enumerate() {
            // Entries of a fixed irrational pattern in (−1, 1).
            *v = ((i as f64 + 1.0) * 0.754_877_666 + (j as f64 + 1.0) * 0.569_840_291).fract()
                * 2.0
                - 1.0;
        }
    }
    let mut logs = vec![0.0; layout.tangents];
    orthonormalise(layout, y, &mut logs, f64::NAN)
}

/// Modified Gram–Schmidt, run twice over each vector ("twice is enough"), on the tangent
/// columns of `y`; adds ln Rⱼⱼ to `logs[j]`.
fn orthonormalise(
    layout: Layout,
    y: &mut [f64],
    logs: &mut [f64],
    t: f64,
) -> Result<(), VariationalError> {
    for (j, log) in logs.iter_mut().enumerate().take(layout.tangents) {
        for _ in 0..2 {
            for k in 0..j {
                let (a, b) = (layout.tangent(k), layout.tangent(j));
                let dot: f64 = (0..layout.n).map(|i| y[a.start + i] * y[b.start + i]).sum();
                for i in 0..layout.n {
                    y[b.start + i] -= dot * y[a.start + i];
                }
            }
        }
        let col = layout.tangent(j);
        let norm = y[col.clone()].iter().map(|v| v * v).sum::<f64>().sqrt();
        if !(norm.is_finite() && norm > 0.0) {
            return Err(VariationalError::DegenerateTangents { index: j, norm, t });
        }
        y[col].iter_mut().for_each(|v| *v /= norm);
        *log += norm.ln();
    }
    Ok(())
}

/// Benettin's method over any stepper of the augmented system laid out as `layout`, from
/// the stepper's current state (its tangent vectors are replaced by a generic orthonormal
/// basis, its sensitivities are carried along untouched).
///
/// Every vector is re-orthonormalised at the end of each interval, and also at the end of
/// any step within one after which some Rⱼⱼ is below [`SHRINK_FLOOR`] (a vector shrinking
/// towards the integrator's atol would lose its exponent); the logs are summed the same way.
///
/// # Errors
/// [`VariationalError::TooManyTangents`] for a layout with more tangent vectors than state
/// entries ([`Layout::validate`]),
/// [`VariationalError::SizeMismatch`] if `N` is not the layout's length,
/// [`VariationalError::NoTangents`], the configuration's errors
/// ([`BenettinConfig::validate`]), [`VariationalError::NonPositiveDuration`] also when the
/// duration vanishes in rounding beside the start time, [`VariationalError::NonFinite`] for
/// the stepper's state,
/// [`VariationalError::DegenerateTangents`], and the stepper's own failures in
/// [`VariationalError::Ode`].
pub fn benettin<S, const N: usize>(
    stepper: &mut S,
    layout: Layout,
    config: &BenettinConfig,
) -> Result<LyapunovSpectrum, VariationalError>
where
    S: Stepper<State = [f64; N]>,
{
    layout.validate()?;
    layout.check_size(N)?;
    if layout.tangents == 0 {
        return Err(VariationalError::NoTangents);
    }
    config.validate()?;
    let mut y = *stepper.state();
    check_finite(&y[..layout.n])?;
    starting_basis(layout, &mut y)?;
    let t0 = stepper.t();
    stepper.restart(t0, y)?;
    let mut logs = vec![0.0; layout.tangents];
    // Interval ends counted from t0, so no rounding accumulates over many intervals.
    let transient_steps = (config.transient / config.interval).ceil() as u64;
    let averaged_steps = (config.duration / config.interval).ceil().max(1.0) as u64;
    let t_start = t0 + config.transient;
    let t_end = t_start + config.duration;
    if t_end <= t_start {
        // The duration is lost in rounding next to t₀ + transient: there is no time to
        // average over.
        return Err(VariationalError::NonPositiveDuration {
            duration: t_end - t_start,
        });
    }
    let at = |stepper: &mut S, t: f64, logs: &mut [f64]| -> Result<(), VariationalError> {
        while stepper.t() < t {
            stepper.step(t)?;
            if stepper.t() < t {
                renormalise_if_shrunk(stepper, layout, logs)?;
            }
        }
        let mut y = *stepper.state();
        orthonormalise(layout, &mut y, logs, t)?;
        stepper.restart(t, y)?;
        Ok(())
    };
    let mut discard = vec![0.0; layout.tangents];
    for k in 1..=transient_steps {
        let t = (t0 + k as f64 * config.interval).min(t_start);
        at(stepper, t, &mut discard)?;
    }
    for k in 1..=averaged_steps {
        let t = (t_start + k as f64 * config.interval).min(t_end);
        at(stepper, t, &mut logs)?;
    }
    let time = stepper.t() - t_start;
    Ok(LyapunovSpectrum {
        exponents: logs.iter().map(|l| l / time).collect(),
        time,
        renormalisations: averaged_steps,
        stats: stepper.stats(),
    })
}

/// Re-orthonormalises the stepper's tangent vectors now, adding their logs to `logs`, if
/// any Rⱼⱼ has fallen below [`SHRINK_FLOOR`] since the last time.
fn renormalise_if_shrunk<S, const N: usize>(
    stepper: &mut S,
    layout: Layout,
    logs: &mut [f64],
) -> Result<(), VariationalError>
where
    S: Stepper<State = [f64; N]>,
{
    let (now, mut y) = (stepper.t(), *stepper.state());
    let mut step_logs = vec![0.0; layout.tangents];
    orthonormalise(layout, &mut y, &mut step_logs, now)?;
    if step_logs.iter().all(|&l| l >= SHRINK_FLOOR.ln()) {
        return Ok(());
    }
    logs.iter_mut()
        .zip(&step_logs)
        .for_each(|(log, step)| *log += step);
    stepper.restart(now, y)?;
    Ok(())
}

impl<const N: usize> VariationalSystem<N> {
    /// The m largest Lyapunov exponents from `(t0, x0)` by [`benettin`] over DOP853 with
    /// the tolerances `ode` (the default stepper; pass any other to [`benettin`]).
    ///
    /// # Errors
    /// As [`Layout::initial_state`], [`Dop853`]'s constructor and [`benettin`].
    pub fn lyapunov(
        &self,
        t0: f64,
        x0: &[f64],
        config: &BenettinConfig,
        ode: AdaptiveConfig,
    ) -> Result<LyapunovSpectrum, VariationalError> {
        let y0 = self.initial_state(x0)?;
        let mut stepper = Dop853::new(self, t0, y0, ode)?;
        benettin(&mut stepper, self.layout(), config)
    }
}
