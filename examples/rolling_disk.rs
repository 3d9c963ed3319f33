//! The rolling disk: a thin uniform disk (radius 10 cm, 0.5 kg) rolling without slip on its
//! sharp rim.
//!
//! Rolling upright and straight, it is stable only fast enough: a small lean oscillates when
//! the spin ω₀ about its axis exceeds ω_c, ω_c² = m g r A / (C (C + m r²)), which for the
//! thin disk is g / (3r) (`contact::theory::RollingDisk`). The threshold is found twice from
//! the derived model: by linearisation (the lean's acceleration at a slightly leaning state,
//! in the turning frame, whose sign changes at ω_c) and by simulation (bisecting the spin at
//! which a small lean stays small for 10 s). Then a steady circle: leaning 0.3 rad with its
//! contact point on a circle of radius 0.5 m, the disk keeps its lean, precesses at the
//! closed form's Ω and its centre runs on the circle of radius ρ.
//!
//! The disk is declared on a struct (`#[rigid(disk(..))]` and `#[contact(surface =
//! disk_rim(..), law = rolling, ..)]`); the linearisation needs nothing beyond the generated
//! `ContactDynamics`: it evaluates the derived accelerations at a slightly leaning state. The
//! runs are `ContactRun`s in the one run loop, driven by `ode::Run` (samples every 10 ms, the
//! lean as a quantity); a disk that falls towards its face stops there with the run's outcome
//! (`ContactOutcome::Unsupported`, or a lift-off) instead of passing through the table.
//!
//! Run with `cargo run --release --example rolling_disk`.

mod common;

use std::error::Error;

use common::{Axes, Series, Table, plot};
use precess::contact::theory::{DiskState, RollingDisk};
use precess::contact::{
    ContactDynamics, ContactError, ContactMode, ContactQuantities, ContactRun, Phase, STATE_LEN,
    attitude_of,
};
use precess::nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};
use precess::ode::{AdaptiveConfig, HybridState, Outcome, Run};
use precess::prelude::RigidBody;

/// A thin uniform disk, radius 10 cm and mass 0.5 kg, rolling on its sharp rim.
#[derive(RigidBody)]
#[rigid(disk(mass = 0.5, radius = 0.1))]
#[contact(surface = disk_rim(radius = 0.1), law = rolling, gravity = 9.81)]
struct Disk;

/// The state array of the disk at a theory state, yaw 0, centre at the origin: body axes
/// (u, t, n), so the disk's axis is body z.
fn state(model: &Disk, s: &DiskState) -> Result<[f64; STATE_LEN], ContactError> {
    let [t, u, n] = s.axes(0.0);
    let rot = Rotation3::from_matrix_unchecked(Matrix3::from_columns(&[u, t, n]));
    let q = UnitQuaternion::from_rotation_matrix(&rot);
    let w_body = q.inverse() * s.angular_velocity(0.0);
    model.rolling_state([0.0, 0.0], &q, &w_body)
}

/// The lean θ of a state: the disk's axis n has n_z = −sin θ.
fn lean(y: &[f64; STATE_LEN]) -> f64 {
    -(attitude_of(y) * Vector3::z()).z.clamp(-1.0, 1.0).asin()
}

/// θ̈ / θ of the model at θ = 1e-7 with ψ̇ = C ω₀ θ / A: ω̇·t = −θ̈ + p (s − ω₃) in the frame
/// turning at ψ̇ ẑ − θ̇ t (p = ψ̇ cos θ, s = −ψ̇ sin θ).
fn lean_rate_ratio(model: &Disk, d: &RollingDisk, w0: f64) -> Result<f64, Box<dyn Error>> {
    let eps = 1e-7;
    let s = DiskState {
        lean: eps,
        lean_rate: 0.0,
        yaw_rate: d.axial * w0 * eps / d.transverse,
        spin: w0,
    };
    let y = state(model, &s)?;
    let dy = model.accelerations(Phase::Rolling, 0.0, &y)?;
    let wdot = attitude_of(&y) * Vector3::new(dy[8], dy[9], dy[10]);
    let [t, _, _] = s.axes(0.0);
    let (p, sf) = (s.yaw_rate * eps.cos(), -s.yaw_rate * eps.sin());
    Ok((-wdot.dot(&t) + p * (sf - w0)) / eps)
}

/// What a run of the disk gives: its samples, each with its phase, and why it stopped.
type Rolled = Outcome<HybridState<ContactMode, [f64; STATE_LEN]>>;

/// Rolls the disk from `y0` for `t_end` s in the run loop at tolerance `tol`, sampled every
/// 10 ms with the lean θ and the standard quantities. A run the scene halts (the disk lying
/// flat, a lift-off) ends there: its outcome is `Halted`.
fn roll(
    model: &Disk,
    y0: [f64; STATE_LEN],
    t_end: f64,
    tol: f64,
) -> Result<Rolled, Box<dyn Error>> {
    let mut cfg = AdaptiveConfig::with_tol(tol, tol);
    cfg.max_steps = 10_000_000;
    // Steps no longer than the sampling interval: with the controller's own, longer steps
    // the steady circle holds its lean to 2e-12 rad over 20 s rather than 5e-15, and between
    // steps the samples would carry the dense output's error besides.
    cfg.h_max = 0.01;
    let mut run = ContactRun::new(model, Phase::Rolling, 0.0, y0, cfg)?;
    Ok(Run::new(&mut run, t_end)
        .sample_every(0.01)
        .quantities(ContactQuantities::new(model, Phase::Rolling))
        .quantity("lean", |_t, s| lean(s))
        .integrate()?)
}

/// A curve of (t, θ) points.
type Curve = Vec<(f64, f64)>;

/// The largest |lean| over `time` from upright with a lean rate of 1e-4 rad/s.
fn max_lean(model: &Disk, w0: f64, time: f64) -> Result<(f64, Curve), Box<dyn Error>> {
    let s = DiskState {
        lean: 0.0,
        lean_rate: 1e-4,
        yaw_rate: 0.0,
        spin: w0,
    };
    let out = roll(model, state(model, &s)?, time, 1e-10)?;
    let lean = out.trajectory.column("lean").ok_or("no lean")?;
    let curve: Vec<(f64, f64)> = out.trajectory.times().iter().copied().zip(lean).collect();
    Ok((curve.iter().map(|p| p.1.abs()).fold(0.0, f64::max), curve))
}

fn main() -> Result<(), Box<dyn Error>> {
    let disk = RollingDisk::thin(0.1, 0.5, 9.81);
    let model = Disk;
    let wc = disk.critical_spin();

    // The threshold by linearisation: bisect the sign of θ̈/θ.
    let (mut lo, mut hi) = (0.5 * wc, 2.0 * wc);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if lean_rate_ratio(&model, &disk, mid)? > 0.0 {
            lo = mid
        } else {
            hi = mid
        }
    }
    let linear = 0.5 * (lo + hi);
    // The threshold by simulation: the least spin at which the lean stays below 0.05 rad.
    let (mut lo, mut hi) = (0.8 * wc, 1.2 * wc);
    for _ in 0..30 {
        let mid = 0.5 * (lo + hi);
        if max_lean(&model, mid, 10.0)?.0 > 0.05 {
            lo = mid
        } else {
            hi = mid
        }
    }
    let simulated = 0.5 * (lo + hi);

    println!(
        "Rolling disk: thin, r = {} m, m = {} kg; theory ω_c = √(g/(3r)) = {wc:.12} rad/s",
        disk.radius, disk.mass
    );
    let mut t1 = Table::default();
    t1.row("ω_c by the model's linearisation (rad/s)", linear, wc);
    t1.row("ω_c by simulation, 10 s, |θ| < 0.05 (rad/s)", simulated, wc);
    for f in [0.5, 1.5, 3.0] {
        t1.row(
            format!("ν² = −θ̈/θ at ω₀ = {f} ω_c (1/s²)"),
            -lean_rate_ratio(&model, &disk, f * wc)?,
            disk.upright_frequency_squared(f * wc),
        );
    }
    t1.print("The upright disk's threshold");
    println!("\n  spin/ω_c   max |lean| over 10 s from θ̇₀ = 1e-4 rad/s");
    let mut curves = Vec::new();
    for f in [0.9, 0.97, 1.03, 1.1] {
        let (worst, curve) = max_lean(&model, f * wc, 10.0)?;
        println!("  {f:8.2}   {worst:.3e} rad");
        if f == 0.9 || f == 1.1 {
            curves.push(Series::line(format!("ω₀ = {f} ω_c"), curve));
        }
    }

    // A steady circle.
    let (lean0, path) = (0.3, 0.5);
    let c = disk.steady_circle(lean0, path).ok_or("no steady circle")?;
    let s = DiskState {
        lean: lean0,
        lean_rate: 0.0,
        yaw_rate: c.precession,
        spin: c.spin,
    };
    let t_end = 20.0;
    let out = roll(&model, state(&model, &s)?, t_end, 1e-12)?;
    if out.stop == precess::ode::StopReason::Halted {
        println!("the steady circle stopped at t = {} s", out.t);
    }
    let states = out.trajectory.states();
    // The centre's circle is about (0, ρ) (h = ŷ at yaw 0).
    let centre = Vector3::new(0.0, c.centre_radius, 0.0);
    let azimuth = |y: &[f64; STATE_LEN]| {
        let n = attitude_of(y) * Vector3::z();
        n.y.atan2(n.x)
    };
    let (mut worst_r, mut worst_lean, mut heading) = (0.0_f64, 0.0_f64, 0.0);
    let mut last_phi = azimuth(&states[0]);
    let (mut path_c, mut path_p) = (Vec::new(), Vec::new());
    for y in states {
        let pos = Vector3::new(y[0], y[1], 0.0);
        worst_r = worst_r.max(((pos - centre).norm() - c.centre_radius).abs());
        worst_lean = worst_lean.max((lean(y) - lean0).abs());
        let phi = azimuth(y);
        let dphi = phi - last_phi;
        heading += dphi - (dphi / std::f64::consts::TAU).round() * std::f64::consts::TAU;
        last_phi = phi;
        path_c.push((y[0], y[1]));
        let cp = model.contact(y).space;
        path_p.push((cp.x, cp.y));
    }
    let e0 = model.energy(Phase::Rolling, &states[0]);
    let e1 = model.energy(Phase::Rolling, &out.state);
    let mut t2 = Table::default();
    t2.row(
        "precession rate, mean over 20 s (rad/s)",
        heading / out.t,
        c.precession,
    );
    t2.row("max |ρ(t) − ρ| of the centre's circle (m)", worst_r, 0.0);
    t2.row("max |θ(t) − θ₀| (rad)", worst_lean, 0.0);
    t2.row("energy after 20 s (J)", e1, e0);
    t2.print(&format!("Steady circle: θ = {lean0} rad, contact circle R = {path} m (Ω = {:.9} rad/s, ω₃ = {:.9} rad/s, ρ = {:.9} m)", c.precession, c.spin, c.centre_radius));

    let a1 = Axes {
        title: "Upright rolling disk: a small lean below and above ω_c",
        x: "t (s)",
        y: "lean θ (rad)",
        log_x: false,
        log_y: false,
    };
    let f1 = plot("rolling_disk_threshold.svg", &a1, &curves)?;
    let a2 = Axes {
        title: "Steady circular rolling: centre and contact point",
        x: "x (m)",
        y: "y (m)",
        log_x: false,
        log_y: false,
    };
    let f2 = plot(
        "rolling_disk_circle.svg",
        &a2,
        &[
            Series::line("centre of mass", path_c),
            Series::line("contact point", path_p),
        ],
    )?;
    println!("\nfigures: {}, {}", f1.display(), f2.display());
    Ok(())
}
