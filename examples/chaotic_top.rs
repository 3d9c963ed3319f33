//! An asymmetric heavy top is chaotic: two releases that differ by δ in one component of ω
//! part exponentially, |Δ(t)| ≈ δ e^{λt}, until the difference is as large as the motion.
//! The growth rate λ (the largest Lyapunov exponent) belongs to the motion, not to δ or to
//! the integrator: it is measured here for δ = 1e-6 and δ = 1e-8, and for two different
//! integrators (δ well above the integrators' own errors, which would otherwise seed the
//! separation), while the energy and the vertical angular momentum (the two integrals this
//! top keeps) stay constant in each run.
//!
//! ```sh
//! cargo run --release --example chaotic_top [plot directory]
//! ```

mod common;

use std::error::Error;

use common::{Axes, Series, Table, plot};
use precess::ode::{Adaptive, AdaptiveConfig, Dop853Pair, EmbeddedPair, Vern9Pair};
use precess::prelude::*;

/// Principal moments 1, 1.5, 0.6 about the pivot; the centre of mass off every axis.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.3, 0.2, 1.0], inertia = diag(1.0, 1.5, 0.6), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 1.0)]
struct Asymmetric;

const T_END: f64 = 80.0;
const SAMPLES: usize = 1600;

/// The figure axis (body z) in space, and E and L·γ, at each sample time.
struct Run {
    axis: Vec<Vector3<f64>>,
    energy: Vec<f64>,
    vertical_momentum: Vec<f64>,
}

fn run<P: EmbeddedPair>(delta: f64) -> Result<Run, Box<dyn Error>> {
    let top = Asymmetric;
    let q0 = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), 50f64.to_radians());
    let w0 = Vector3::new(1.0 + delta, 0.5, 2.0);
    let y0 = EulerianTop::<Asymmetric>::state(&q0, &w0);
    let cfg = AdaptiveConfig::with_tol(1e-13, 1e-13);
    let mut ode = Adaptive::<_, P, 7>::new(EulerianTop(&top), 0.0, y0, cfg)?;
    let (inertia, c) = (top.inertia(), top.center_of_mass());
    let mut out = Run {
        axis: vec![],
        energy: vec![],
        vertical_momentum: vec![],
    };
    for k in 0..=SAMPLES {
        ode.advance_to(T_END * k as f64 / SAMPLES as f64)?;
        let y = ode.y();
        let attitude = EulerianTop::<Asymmetric>::attitude(y)?;
        let w = Vector3::new(y[4], y[5], y[6]);
        let gamma = attitude.inverse() * Vector3::z();
        out.axis.push(attitude * Vector3::z());
        out.energy
            .push(0.5 * w.dot(&(inertia * w)) + top.mass() * c.dot(&gamma));
        out.vertical_momentum.push((inertia * w).dot(&gamma));
    }
    Ok(out)
}

/// The angle between the figure axes of two runs at each sample, against time.
fn separation(a: &Run, b: &Run) -> Vec<(f64, f64)> {
    a.axis
        .iter()
        .zip(&b.axis)
        .enumerate()
        .map(|(k, (u, v))| (T_END * k as f64 / SAMPLES as f64, u.angle(v).max(1e-18)))
        .collect()
}

/// λ: the least-squares slope of ln |Δ| over `t_from ≤ t ≤ t_to`, a window where both
/// separations are still small (the linearised flow, in which Δ/δ does not depend on δ).
fn growth_rate(sep: &[(f64, f64)], t_from: f64, t_to: f64) -> f64 {
    let window: Vec<(f64, f64)> = sep
        .iter()
        .filter(|p| p.0 >= t_from && p.0 <= t_to)
        .map(|p| (p.0, p.1.ln()))
        .collect();
    let n = window.len() as f64;
    let (mx, my) = window
        .iter()
        .fold((0.0, 0.0), |s, p| (s.0 + p.0 / n, s.1 + p.1 / n));
    let sxy: f64 = window.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = window.iter().map(|p| (p.0 - mx).powi(2)).sum();
    sxy / sxx
}

fn main() -> Result<(), Box<dyn Error>> {
    let base = run::<Dop853Pair>(0.0)?;
    let base_vern = run::<Vern9Pair>(0.0)?;
    let mut table = Table::default();
    let large = separation(&base, &run::<Dop853Pair>(1e-6)?);
    let small = separation(&base, &run::<Dop853Pair>(1e-8)?);
    let sep_vern = separation(&base_vern, &run::<Vern9Pair>(1e-6)?);
    // The window: from t = 5 s (past the start-up) until the larger separation reaches 1e-3.
    let t_to = large.iter().find(|p| p.1 > 1e-3).map_or(T_END, |p| p.0);
    let rates = [
        growth_rate(&large, 5.0, t_to),
        growth_rate(&small, 5.0, t_to),
    ];
    let rate_vern = growth_rate(&sep_vern, 5.0, t_to);
    let mut curves = vec![
        Series::line("δ = 1e-6, DOP853", large),
        Series::line("δ = 1e-8, DOP853", small),
        Series::line("δ = 1e-6, Vern9", sep_vern),
    ];
    curves.push(Series::line(
        "DOP853 vs Vern9, same release",
        separation(&base, &base_vern),
    ));

    table.row(
        "λ for δ = 1e-6 (theory column: δ = 1e-8)",
        rates[0],
        rates[1],
    );
    table.row(
        "λ with Vern9 (theory column: DOP853), δ = 1e-6",
        rate_vern,
        rates[0],
    );
    let last = base.energy.len() - 1;
    table.row("E(T) (conserved)", base.energy[last], base.energy[0]);
    table.row(
        "L·γ(T) (conserved)",
        base.vertical_momentum[last],
        base.vertical_momentum[0],
    );
    table.print("Asymmetric heavy top: sensitive dependence on the release (rtol 1e-13)");
    println!("  λ fitted over 5 s ≤ t ≤ {t_to:.1} s, where both separations are below 1e-3");
    println!(
        "  λ ≈ {:.3} /s: an error of 1e-13 grows to 1e-2 rad in ~{:.0} s",
        rates[0],
        (1e-2f64 / 1e-13).ln() / rates[0]
    );

    let path = plot(
        "chaotic_top.svg",
        &Axes {
            title: "Asymmetric heavy top: angle between the figure axes of two releases",
            x: "t [s]",
            y: "angle [rad]",
            log_x: false,
            log_y: true,
        },
        &curves,
    )?;
    println!("  figure: {}", path.display());
    Ok(())
}
