//! A satellite with a reaction wheel: a box-shaped bus spun about its intermediate axis, the
//! axis a free body cannot keep (the Dzhanibekov flip), kept by a wheel spinning on it. The
//! derive's `rotor(...)` makes the body a gyrostat, I ω̇ = −ω × (I ω + h); the wheel fast
//! enough (h > (I_z − I_x) n) turns the flip into a wobble of period 2π/√k, too slow and the
//! wobble grows as cosh(√−k t) (theory in `free_bodies/satellite.rs`).
//!
//! ```sh
//! cargo run --release --example gyrostat [plot directory]
//! ```

mod common;
#[path = "free_bodies/satellite.rs"]
mod satellite;

use std::error::Error;

use common::{Axes, Series, Table, plot};
use satellite::{RPM, SPIN, Satellite, run};

fn main() -> Result<(), Box<dyn Error>> {
    let fast = Satellite {
        wheel: 3000.0 * RPM,
    };
    let slow = Satellite {
        wheel: 1000.0 * RPM,
    };
    println!(
        "principal moments {:?} kg m²; spin {SPIN} rad/s about x; the wheel keeps it above {:.1} rpm",
        fast.moments(),
        fast.threshold(SPIN) / RPM
    );
    let a = 1e-4 * SPIN;
    let stable = run(&fast, a, f64::INFINITY, 0.01, 600.0)?;
    let growing = run(&slow, a, 100.0 * a, 0.01, 600.0)?;

    let mut table = Table::default();
    table.row(
        "3000 rpm: wobble period [s]",
        stable.period,
        2.0 * std::f64::consts::PI / fast.k(SPIN).sqrt(),
    );
    // The wobble's other amplitude against the linear theory (ω_y starts at its own peak a).
    table.row(
        "3000 rpm: largest |ω_z| [rad/s]",
        stable.largest_z(),
        fast.z_amplitude(SPIN, a),
    );
    table.row(
        "3000 rpm: |I ω + h| at 600 s [N m s]",
        stable.momentum.1,
        stable.momentum.0,
    );
    table.row(
        "3000 rpm: ½ ωᵀ I ω at 600 s [J]",
        stable.energy.1,
        stable.energy.0,
    );
    // ω_y = a cosh(σ t) reaches 100 a at acosh(100)/σ.
    table.row(
        "1000 rpm: growth rate σ [1/s]",
        100f64.acosh() / growing.grown_at,
        (-slow.k(SPIN)).sqrt(),
    );
    table.row(
        "1000 rpm: |I ω + h| at 600 s [N m s]",
        growing.momentum.1,
        growing.momentum.0,
    );
    table.print("Satellite with a reaction wheel (DOP853, rtol 1e-12)");

    // The runs sample every 0.01 s for the measurements; every 50th sample (0.5 s) draws the
    // dips, which last about a minute, in a figure a fiftieth of the size.
    let series = |r: &satellite::Run, label: &str| {
        Series::line(
            label,
            r.samples
                .iter()
                .step_by(50)
                .map(|(t, w)| (*t, w.x / SPIN))
                .collect(),
        )
    };
    let path = plot(
        "gyrostat.svg",
        &Axes {
            title: "Spin about the intermediate axis: kept by a 3000 rpm wheel, lost at 1000 rpm",
            x: "t [s]",
            y: "ω_x / n",
            log_x: false,
            log_y: false,
        },
        &[
            series(&stable, "wheel 3000 rpm"),
            series(&growing, "wheel 1000 rpm"),
        ],
    )?;
    println!("  figure: {}", path.display());
    Ok(())
}
