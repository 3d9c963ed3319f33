//! What the contact examples share: a scene's numbers as named parameters, and a run sampled
//! on a grid of times. Included by path (`#[path = "common/contact.rs"] mod contact;`).

#![allow(dead_code)] // each example uses the part it needs

use std::error::Error;

use precess::contact::{ContactDynamics, ContactOutcome, ContactRun, STATE_LEN};
use precess::ode::AdaptiveConfig;
use precess::sym::{Arena, ExprId};

/// Parameters named as they are made, their values kept for [`precess::contact::ContactModel::new`].
#[derive(Default)]
pub struct Params {
    /// `(name, value)` pairs.
    pub values: Vec<(&'static str, f64)>,
}

impl Params {
    /// A parameter `name` with `value`.
    pub fn add(&mut self, arena: &mut Arena, name: &'static str, value: f64) -> ExprId {
        self.values.push((name, value));
        arena.parameter(name)
    }
}

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
