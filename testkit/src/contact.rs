//! Runs of an interpreted contact model, optimised: `ContactRun` is generic over the body,
//! so a test crate that drives it compiles DOP853 and the hybrid loop unoptimised, and the
//! rattleback's 3·10⁴ dense samples spent most of their time there.
#![warn(missing_docs)]

use precess::contact::{ContactError, ContactModel, ContactRun, Phase, STATE_LEN};
use precess::ode::AdaptiveConfig;

/// The states at `times` (increasing, after 0) of `model` started in `phase` at `y0` at
/// t = 0, by [`ContactRun`] (DOP853, switching phases as the run does).
///
/// # Errors
/// The run's, at its start or at any time.
pub fn states(
    model: &ContactModel,
    phase: Phase,
    y0: [f64; STATE_LEN],
    config: AdaptiveConfig,
    times: &[f64],
) -> Result<Vec<[f64; STATE_LEN]>, ContactError> {
    let mut run = ContactRun::new(model, phase, 0.0, y0, config)?;
    times
        .iter()
        .map(|&t| {
            run.advance_to(t)?;
            Ok(*run.y())
        })
        .collect()
}
