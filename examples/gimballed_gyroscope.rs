//! A gyroscope in gimbals, derived by `#[derive(Mechanism)]`: with massless gimbals it is
//! the heavy symmetric top, and its precession is measured against the exact top theory; with
//! massive gimbals the precession rate changes, as the formula below says.
//!
//! ```sh
//! cargo run --release --example gimballed_gyroscope [plot directory]
//! ```
//!
//! The outer gimbal turns about the vertical z (angle φ), the inner gimbal about the outer's
//! x (θ), the rotor about the inner's z (ψ): the rotor's attitude is Rz(φ) Rx(θ) Rz(ψ), the
//! ZXZ angles of the top. The rotor (a disk, mass M, radius r) sits l above the gimbals'
//! common centre, so with I1 = M r²/4 + M l² and I3 = M r²/2 about that centre,
//!
//! T = ½ C_o φ̇² + ½ [A_g θ̇² + (B_g sin²θ + C_g cos²θ) φ̇²] + ½ I1 (θ̇² + φ̇² sin²θ)
//!   + ½ I3 (ψ̇ + φ̇ cos θ)²,  V = M g l cos θ,
//!
//! where C_o is the outer gimbal's moment about z and (A_g, B_g, C_g) the inner gimbal's
//! about its x, y, z. At steady precession (θ̇ = 0) the θ equation reads
//!
//! (I1 + B_g − C_g) cos θ Ω² − I3 ω3 Ω + M g l = 0,  ω3 = ψ̇ + φ̇ cos θ,
//!
//! the top's balance with I1 replaced by I1 + B_g − C_g; the outer gimbal does not enter.
//! The slow root is Ω ≈ M g l / (I3 ω3) [1 + (I1 + B_g − C_g) cos θ M g l / (I3 ω3)²]: the
//! inner gimbal's inertia raises the precession rate in second order, by a fraction
//! (B_g − C_g) cos θ M g l / (I3 ω3)². Each gimbal here is a ring (mass m, radius R) whose
//! plane holds the axes it turns about, so B_g − C_g = m R²/2 for the inner one.

mod common;

use std::error::Error;

use common::{Axes, Series, Table, plot};
use precess::ode::{AdaptiveConfig, Dop853};
use precess::top::HeavyTopTheory;

const G: f64 = 9.81;
const M: f64 = 0.4;
const RADIUS: f64 = 0.05;
const L: f64 = 0.04;
const RING: f64 = 0.07;

#[path = "mechanisms/gimballed_gyroscope.rs"]
mod mechanism;
use mechanism::Gyroscope;

/// The top's moments about the gimbal centre and M g l.
fn top_theory() -> Result<HeavyTopTheory, Box<dyn Error>> {
    let i1 = M * RADIUS * RADIUS / 4.0 + M * L * L;
    let i3 = M * RADIUS * RADIUS / 2.0;
    Ok(HeavyTopTheory::new(i1, i3, M * G * L)?)
}

/// The slow steady precession rate with the inner gimbal's B_g − C_g added to I1.
fn gimballed_rate(theory: &HeavyTopTheory, extra: f64, theta: f64, omega3: f64) -> f64 {
    let a = (theory.i1() + extra) * theta.cos();
    let b = theory.i3() * omega3;
    // The small root without cancellation: 2 M g l / (b + √(b² − 4 a M g l)).
    2.0 * theory.mgl() / (b + (b * b - 4.0 * a * theory.mgl()).sqrt())
}

fn main() -> Result<(), Box<dyn Error>> {
    let theory = top_theory()?;
    let mut table = Table::default();

    // Massless gimbals: released with no precession, the rotor nutates and precesses; over a
    // whole number of nutation periods φ advances by the exact mean rate times the time.
    let massless = Gyroscope {
        m_outer: 0.0,
        m_inner: 0.0,
    };
    let (theta0, omega3) = (1.0, 150.0);
    let q0 = [0.0, theta0, 0.0];
    let qd0 = [0.0, 0.0, omega3];
    let motion = theory.motion_from_angles(&q0, &qd0)?;
    let period = motion.nutation_period();
    let y0 = [q0[0], q0[1], q0[2], qd0[0], qd0[1], qd0[2]];
    let mut ode = Dop853::new(&massless, 0.0, y0, AdaptiveConfig::with_tol(1e-12, 1e-14))?;
    let periods = 20.0;
    let mut path = Vec::new();
    for k in 1..=2000 {
        let t = periods * period * k as f64 / 2000.0;
        ode.advance_to(t)?;
        path.push((t, ode.y()[1]));
    }
    let mean = ode.y()[0] / (periods * period);
    table.row(
        "massless gimbals: mean precession ⟨φ̇⟩ [rad/s]",
        mean,
        motion.mean_precession_rate()?,
    );
    table.row(
        "massless gimbals: fast-top M g l/(I3 ω3) [rad/s]",
        mean,
        theory.mgl() / (theory.i3() * omega3),
    );
    let (lo, hi) = path
        .iter()
        .fold((f64::MAX, f64::MIN), |(lo, hi), &(_, th)| {
            (lo.min(th), hi.max(th))
        });
    table.row("massless gimbals: smallest θ [rad]", lo, motion.theta_min());
    table.row("massless gimbals: largest θ [rad]", hi, motion.theta_max());

    // Massive gimbals: steady precession at the gimballed rate stays steady, at a rate
    // above the top's.
    let mut rates = Vec::new();
    let theta = std::f64::consts::FRAC_PI_3;
    let spin = 60.0;
    for m_inner in [0.0, 0.05, 0.1, 0.2, 0.4] {
        let gyro = Gyroscope {
            m_outer: 0.3,
            m_inner,
        };
        let extra = m_inner * RING * RING / 2.0;
        let omega = gimballed_rate(&theory, extra, theta, spin);
        let y0 = [0.0, theta, 0.0, omega, 0.0, spin - omega * theta.cos()];
        let mut ode = Dop853::new(&gyro, 0.0, y0, AdaptiveConfig::with_tol(1e-12, 1e-14))?;
        let t_end = 2.0;
        let mut drift: f64 = 0.0;
        for k in 1..=200 {
            ode.advance_to(t_end * k as f64 / 200.0)?;
            drift = drift.max((ode.y()[1] - theta).abs());
        }
        let measured = ode.y()[0] / t_end;
        let top = theory.steady_precession(theta, spin)?.slow;
        table.row(
            format!("inner gimbal {m_inner} kg: precession Ω [rad/s]"),
            measured,
            omega,
        );
        println!(
            "  inner gimbal {m_inner} kg: Ω = {measured:.9} rad/s, {:+.3e} relative to the top's {top:.9}; θ stays within {drift:.1e} rad",
            (measured - top) / top
        );
        rates.push((m_inner, measured));
    }
    table.print(&format!(
        "Gimballed gyroscope: rotor M = {M} kg, r = {RADIUS} m, l = {L} m, gimbal rings R = 0.08, {RING} m (theory: exact heavy top; the gimballed balance)"
    ));

    let curve: Vec<(f64, f64)> = (0..=40)
        .map(|k| {
            let m = 0.01 * k as f64;
            (
                m,
                gimballed_rate(&theory, m * RING * RING / 2.0, theta, spin),
            )
        })
        .collect();
    let file = plot(
        "gimballed_gyroscope.svg",
        &Axes {
            title: "Gimballed gyroscope: steady precession against the inner gimbal's mass",
            x: "inner gimbal mass [kg]",
            y: "Ω [rad/s]",
            log_x: false,
            log_y: false,
        },
        &[
            Series::markers("simulated", rates),
            Series::line("(I1 + B_g − C_g) cos θ Ω² − I3 ω3 Ω + M g l = 0", curve),
        ],
    )?;
    println!("  wrote {}", file.display());
    let file = plot(
        "gimballed_gyroscope_nutation.svg",
        &Axes {
            title: "Massless gimbals: the rotor's nutation θ(t), released without precession",
            x: "t [s]",
            y: "θ [rad]",
            log_x: false,
            log_y: false,
        },
        &[Series::line("θ", path)],
    )?;
    println!("  wrote {}", file.display());
    Ok(())
}
