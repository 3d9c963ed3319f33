//! What the contact examples share: a run sampled on a grid of times. Included by path
//! (`#[path = "common/contact.rs"] mod contact;`).

#![allow(dead_code)] // not every example reads every field (only the rattleback asks for a lift-off)

use std::error::Error;

use precess::contact::{ContactDynamics, ContactOutcome, ContactRun, STATE_LEN};
use precess::ode::AdaptiveConfig;

/// A run's samples: times and states.
pub struct Samples {
    /// The sample times reached.
    pub t: Vec<f64>,
    /// The states there.
    pub y: Vec<[f64; STATE_LEN]>,
    /// When the body left the table, if it did.
    pub lift_off: Option<f64>,
}

/// Runs `body` from `y0` in its law's first phase, sampling every `dt` up to `t_end`.
pub fn sample<D: ContactDynamics>(
    body: &D,
    y0: [f64; STATE_LEN],
    dt: f64,
    t_end: f64,
    tol: f64,
) -> Result<Samples, Box<dyn Error>> {
    let mut cfg = AdaptiveConfig::with_tol(tol, tol);
    cfg.max_steps = 10_000_000;
    let mut run = ContactRun::new(body, body.law().first_phase(), 0.0, y0, cfg)?;
    let mut out = Samples {
        t: vec![0.0],
        y: vec![y0],
        lift_off: None,
    };
    let n = (t_end / dt).round() as usize;
    for k in 1..=n {
        match run.advance_to(k as f64 * dt)? {
            ContactOutcome::Reached { t } => {
                out.t.push(t);
                out.y.push(*run.y());
            }
            ContactOutcome::LiftOff { t, .. } => {
                out.lift_off = Some(t);
                break;
            }
        }
    }
    Ok(out)
}
