//! The gyroscope: a fast symmetric top released at rest in its tilt precesses slowly at
//! Ω ≈ M g l / (I3 ω3) while nutating at ω_n ≈ I3 ω3 / I1, the fast-top approximations.
//! Both are measured from simulations (turning points of θ as events, the precession angle
//! gained between them) and compared with the exact heavy-top solution (the library's
//! elliptic-integral theory) and with the approximations, whose error shrinks as ω3 grows.
//! Then a motor spins a gyroscope's wheel up on its pivot (a driven rotor of `#[top]`): the
//! wheel and the body it turns back follow the closed forms of a spin-up from rest.
//!
//! ```sh
//! cargo run --release --example gyroscope [plot directory]
//! ```

mod common;

use std::error::Error;
use std::f64::consts::TAU;

use common::{Axes, Series, Table, plot, relative_error};
use precess::ode::{AdaptiveConfig, Dop853, Event, Run};
use precess::prelude::*;
use precess::top::HeavyTopTheory;

/// I1 = 1, I3 = ½ about the pivot, M g l = 1.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 1.0)]
struct Gyro;

/// The same top hanging below its pivot, its wheel (J = 0.1 about the figure axis) turned
/// by a motor of constant torque [`MOTOR`]; the figure axis stays vertical (ZYX is regular
/// there).
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, -1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 1.0, angles = zyx, rotor(axis = [0, 0, 1], inertia = 0.1, torque = motor))]
struct Motorised;

/// The motor's torque on the wheel, N m.
const MOTOR: f64 = 0.05;

fn motor(_: &Motorised, _t: f64, _state: &[f64]) -> f64 {
    MOTOR
}

/// From ten nutation periods: (nutation frequency 2π/T, mean precession rate).
fn measure(omega3: f64) -> Result<(f64, f64), Box<dyn Error>> {
    let theta0 = 60f64.to_radians();
    let y0 = [0.0, theta0, 0.0, 0.0, 0.0, omega3];
    let chart = TopChart::declared(&Gyro);
    let theory = HeavyTopTheory::new(1.0, 0.5, 1.0)?
        .motion_from_angles(&[0.0, theta0, 0.0], &[0.0, 0.0, omega3])?;
    let t_end = 10.5 * theory.nutation_period();
    let mut ode = Dop853::new(&chart, 0.0, y0, AdaptiveConfig::with_tol(1e-13, 1e-13))?;
    // θ̇ rising through zero: the top is at its highest (θ smallest), once a period.
    let out = Run::new(&mut ode, t_end)
        .sample_none()
        .event(
            Event::new("θ at its minimum").rising(),
            |_t, y: &[f64; 6]| y[4],
        )
        .integrate()?;
    let hits = &out.events;
    let (first, last) = match (hits.first(), hits.last()) {
        (Some(a), Some(b)) if hits.len() > 2 => (a, b),
        _ => return Err("fewer than three turning points".into()),
    };
    let periods = (hits.len() - 1) as f64;
    let period = (last.t - first.t) / periods;
    let precession = (last.state[0] - first.state[0]) / (last.t - first.t);
    Ok((TAU / period, precession))
}

fn main() -> Result<(), Box<dyn Error>> {
    let heavy = HeavyTopTheory::new(1.0, 0.5, 1.0)?;
    let (i1, i3, mgl) = (heavy.i1(), heavy.i3(), heavy.mgl());
    let mut table = Table::default();
    let mut nutation_gap = Vec::new();
    let mut precession_gap = Vec::new();
    for omega3 in [20.0, 50.0, 100.0, 200.0, 500.0] {
        let (nutation, precession) = measure(omega3)?;
        let exact =
            heavy.motion_from_angles(&[0.0, 60f64.to_radians(), 0.0], &[0.0, 0.0, omega3])?;
        table.row(
            format!("ω3 = {omega3}: nutation frequency, exact"),
            nutation,
            TAU / exact.nutation_period(),
        );
        table.row(
            format!("ω3 = {omega3}: mean precession, exact"),
            precession,
            exact.mean_precession_rate()?,
        );
        let (approx_nutation, approx_precession) = (i3 * omega3 / i1, mgl / (i3 * omega3));
        table.row(
            format!("ω3 = {omega3}: nutation frequency ≈ I3 ω3 / I1"),
            nutation,
            approx_nutation,
        );
        table.row(
            format!("ω3 = {omega3}: mean precession ≈ M g l / (I3 ω3)"),
            precession,
            approx_precession,
        );
        nutation_gap.push((omega3, relative_error(approx_nutation, nutation)));
        precession_gap.push((omega3, relative_error(approx_precession, precession)));
    }
    table.print("Gyroscope: I1 = 1, I3 = 0.5, M g l = 1, released at θ = 60° (DOP853, rtol 1e-13)");
    println!("  the '≈' rows' errors are the fast-top approximations', shrinking as ω3 grows");

    let path = plot(
        "gyroscope.svg",
        &Axes {
            title: "Fast-top approximations against the simulated top",
            x: "ω3 [rad/s]",
            y: "relative error of the approximation",
            log_x: true,
            log_y: true,
        },
        &[
            Series::markers("nutation frequency I3 ω3 / I1", nutation_gap),
            Series::markers("precession M g l / (I3 ω3)", precession_gap),
        ],
    )?;
    println!("  figure: {}", path.display());

    // The axial momentum (I3 − J) ω3 + J (ω3 + Ω) stays 0: ω3 = −u t/(I3 − J),
    // Ω = u t/J + u t/(I3 − J).
    let (i3, j) = (0.5, 0.1);
    let chart = TopChart::declared(&Motorised);
    let mut ode = Dop853::new(
        &chart,
        0.0,
        [0.0; 7],
        AdaptiveConfig::with_tol(1e-13, 1e-13),
    )?;
    let mut spin_up = Table::default();
    for t in [1.0, 10.0, 100.0] {
        ode.advance_to(t)?;
        let y = ode.y();
        spin_up.row(format!("t = {t} s: body ω3"), y[3], -MOTOR * t / (i3 - j));
        spin_up.row(
            format!("t = {t} s: wheel Ω"),
            y[Motorised::ROTOR_0],
            MOTOR * t / j + MOTOR * t / (i3 - j),
        );
    }
    spin_up.print("A motor spins the wheel up (J = 0.1, u = 0.05 N m) against the closed form");
    Ok(())
}
