//! What the animation tests share: the tippe top's run (of `precess::models`' top), a heavy top's precession, and a
//! reader of a `.glb`'s accessors.

#![allow(dead_code)] // each test file uses the part it needs

pub mod browser;

use gltf_json::Root;
use precess::contact::{ContactDynamics, ContactMode, ContactRun, STATE_LEN};
use precess::ode::HybridState;
use precess::ode::{AdaptiveConfig, Run, Trajectory};
use precess::prelude::*;

pub use precess::models::TippeTop as Tippe;
pub use precess::models::tippe_top::RADIUS;

/// The offset αR of the sphere's centre above the centre of mass [m].
pub const OFFSET: f64 = precess::models::tippe_top::ALPHA * RADIUS;

/// The tippe top started 0.1 rad off upright at 140 rad/s, run to `t_end`, sampled every
/// `every` s (the example's run: it has turned over by 8 s).
pub fn tippe_run(
    t_end: f64,
    every: f64,
) -> (
    Tippe,
    Trajectory<HybridState<ContactMode, [f64; STATE_LEN]>>,
) {
    let model = Tippe { viscous: 0.1 };
    let y0 = Tippe::start(0.1, 140.0);
    let mut cfg = AdaptiveConfig::with_tol(1e-10, 1e-10);
    cfg.max_steps = 10_000_000;
    let phase = model.law().first_phase();
    let mut run = ContactRun::new(&model, phase, 0.0, y0, cfg).expect("a valid start");
    let out = Run::new(&mut run, t_end)
        .sample_every(every)
        .integrate()
        .expect("the run");
    (model, out.trajectory)
}

/// A disk on a stem about a pivot, as the heavy top example.
#[derive(RigidBody)]
#[rigid(
    disk(mass = 0.2, radius = 0.04, at = [0.0, 0.0, 0.05]),
    cylinder(mass = 0.01, radius = 0.003, length = 0.08, at = [0.0, 0.0, 0.04]),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81)]
pub struct Spinner;

/// Euler angles (φ, θ, ψ) of a steady precession sampled every 10 ms over 2 s: φ = 3 t,
/// θ = 0.4 + 0.1 sin 5t, ψ = 60 t (written down, not integrated: the test is of the
/// animation, whose attitudes the angles fix).
pub fn precession() -> Trajectory<[f64; 3]> {
    let mut run = Trajectory::new(vec![]);
    for k in 0..=200 {
        let t = 0.01 * k as f64;
        run.push(t, [3.0 * t, 0.4 + 0.1 * (5.0 * t).sin(), 60.0 * t], &[])
            .expect("increasing times");
    }
    run
}

/// The f32 values of accessor `i`, checked against its buffer view and the buffer.
pub fn floats(root: &Root, bin: &[u8], i: usize) -> Vec<f32> {
    let a = &root.accessors[i];
    let width = a.type_.unwrap().multiplicity();
    let view = &root.buffer_views[a.buffer_view.unwrap().value()];
    let start =
        view.byte_offset.map_or(0, |o| o.0 as usize) + a.byte_offset.map_or(0, |o| o.0 as usize);
    let len = a.count.0 as usize * width * 4;
    assert!(
        a.byte_offset.map_or(0, |o| o.0 as usize) + len <= view.byte_length.0 as usize,
        "accessor {i} runs past its view"
    );
    assert_eq!(start % 4, 0, "accessor {i} is not aligned");
    bin[start..start + len]
        .chunks_exact(4)
        .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect()
}
