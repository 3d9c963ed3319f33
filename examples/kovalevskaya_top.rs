//! The Kovalevskaya top: principal moments A = B = 2C about the pivot and the centre of mass
//! in the equatorial plane. Besides the energy, the vertical angular momentum and |γ| = 1 it
//! has a fourth integral, found by Sofia Kovalevskaya in 1888,
//!
//! K = (p² − q² − c γ1)² + (2 p q − c γ2)², c = M g x0 / C,
//!
//! for the body angular velocity ω = (p, q, r) and the upward vertical γ in body axes. It is
//! conserved by the motion and by nothing in the integrator: a check of the derived equations
//! that no other tool ships. A control top with A = B = 2.2 C shows K is not conserved there.
//!
//! ```sh
//! cargo run --release --example kovalevskaya_top [plot directory]
//! ```

mod common;

use std::error::Error;

use common::{Axes, Series, Table, plot};
use precess::ode::{AdaptiveConfig, Dop853};
use precess::prelude::*;

/// A = B = 2, C = 1 about the pivot; M g x0 = 1 with the centre of mass on the body x axis.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [1.0, 0.0, 0.0], inertia = diag(2.0, 2.0, 1.0), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 1.0)]
struct Kovalevskaya;

/// The control: A = B = 2.2 C, not a Kovalevskaya top.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [1.0, 0.0, 0.0], inertia = diag(2.2, 2.2, 1.0), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 1.0)]
struct Control;

/// The invariants along one run: (t, K, E, L·γ).
type Record = Vec<(f64, f64, f64, f64)>;

fn invariants<T: TopDynamics + RigidBody>(
    top: &T,
    y: &[f64; 7],
) -> Result<(f64, f64, f64), Box<dyn Error>> {
    let attitude = EulerianTop::<T>::attitude(y)?;
    let w = Vector3::new(y[4], y[5], y[6]);
    let gamma = attitude.inverse() * Vector3::z();
    let inertia = top.inertia();
    let c = top.mass() * 1.0 * top.center_of_mass().x / inertia[(2, 2)];
    let (p, q) = (w.x, w.y);
    let k = (p * p - q * q - c * gamma.x).powi(2) + (2.0 * p * q - c * gamma.y).powi(2);
    let g_weight = top.mass() * 1.0;
    let energy = 0.5 * w.dot(&(inertia * w)) + g_weight * top.center_of_mass().dot(&gamma);
    let vertical_momentum = (inertia * w).dot(&gamma);
    Ok((k, energy, vertical_momentum))
}

fn run<T: TopDynamics + RigidBody>(top: &T, t_end: f64) -> Result<Record, Box<dyn Error>> {
    // Released tilted 40° about the body y axis, spinning about the body z and x axes.
    let q0 = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), 40f64.to_radians());
    let w0 = Vector3::new(0.7, -0.2, 2.5);
    let y0 = EulerianTop::<T>::state(&q0, &w0);
    let mut ode = Dop853::new(
        EulerianTop(top),
        0.0,
        y0,
        AdaptiveConfig::with_tol(1e-13, 1e-13),
    )?;
    let mut record = Record::new();
    for k in 0..=2000 {
        let t = t_end * k as f64 / 2000.0;
        ode.advance_to(t)?;
        let (kv, e, lz) = invariants(top, ode.y())?;
        record.push((t, kv, e, lz));
    }
    Ok(record)
}

fn main() -> Result<(), Box<dyn Error>> {
    let t_end = 200.0;
    let kov = run(&Kovalevskaya, t_end)?;
    let control = run(&Control, t_end)?;

    let first = kov[0];
    let last = kov[kov.len() - 1];
    let mut table = Table::default();
    table.row("K(T), Kovalevskaya top", last.1, first.1);
    table.row("E(T)", last.2, first.2);
    table.row("L·γ(T), vertical angular momentum", last.3, first.3);
    let worst_k = kov
        .iter()
        .map(|r| (r.1 - first.1).abs())
        .fold(0.0, f64::max);
    table.row(
        "max |K(t) − K(0)| over the run, relative",
        first.1 + worst_k,
        first.1,
    );
    let (c0, c_last) = (control[0], control[control.len() - 1]);
    table.row(
        "K(T), control A = B = 2.2 C (not conserved)",
        c_last.1,
        c0.1,
    );
    table.row("E(T), control (conserved)", c_last.2, c0.2);
    table.print("Kovalevskaya top over T = 200 (DOP853, rtol 1e-13)");

    let drift = |r: &Record, pick: fn(&(f64, f64, f64, f64)) -> f64| -> Vec<(f64, f64)> {
        let v0 = pick(&r[0]);
        r.iter()
            .skip(1)
            .map(|row| (row.0, ((pick(row) - v0) / v0).abs().max(1e-17)))
            .collect()
    };
    let path = plot(
        "kovalevskaya_top.svg",
        &Axes {
            title: "Kovalevskaya's integral K along the motion",
            x: "t",
            y: "|K(t) − K(0)| / K(0)",
            log_x: false,
            log_y: true,
        },
        &[
            Series::line("Kovalevskaya top: K", drift(&kov, |r| r.1)),
            Series::line("Kovalevskaya top: E", drift(&kov, |r| r.2)),
            Series::line("control A = 2.2 C: K", drift(&control, |r| r.1)),
        ],
    )?;
    println!("  figure: {}", path.display());
    Ok(())
}
