//! Runs of a constrained model by DOP853, optimised: the integrator is generic, so a test
//! crate that drives it compiles it unoptimised, and the four-bar's 10³ s runs spent half
//! their time there.
#![warn(missing_docs)]

use std::error::Error;

use precess::lagrange::ConstrainedModel;
use precess::ode::{AdaptiveConfig, Dop853};

/// The states at `times` (increasing, after 0) of a model of state length 4 (a loop of
/// three coordinates, one free) started at `y0` at t = 0, by DOP853 at rtol = atol = `tol`:
/// partitioned (projected back onto the loop to `projection` at each time) or, with None,
/// plainly integrated.
///
/// # Errors
/// The model's state length is not 4, the integrator fails, or the loop does not close.
pub fn dop853_states(
    model: &ConstrainedModel,
    y0: [f64; 4],
    times: &[f64],
    tol: f64,
    projection: Option<f64>,
) -> Result<Vec<[f64; 4]>, Box<dyn Error>> {
    let config = AdaptiveConfig::with_tol(tol, tol);
    let mut ode = Dop853::new(model.system::<4>()?, 0.0, y0, config)?;
    let mut states = Vec::with_capacity(times.len());
    for &t in times {
        match projection {
            Some(tolerance) => {
                model.advance_partitioned(&mut ode, t, tolerance)?;
            }
            None => ode.advance_to(t)?,
        }
        states.push(*ode.y());
    }
    Ok(states)
}
