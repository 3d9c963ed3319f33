//! The benchmark bicycle of Meijaard, Papadopoulos, Ruina & Schwab (Proc. R. Soc. A 463,
//! 2007): the Carvallo–Whipple model derived nonlinear by `#[derive(Mechanism)]` at compile
//! time (the library's ready model `precess::models::Bicycle`: four bodies on three massless
//! carriers, two knife-edge wheels declared `rolls = disk(..)`), linearised about the upright
//! straight run by `Bicycle::canonical`,
//! its eigenvalues against the forward speed, and the weave and capsize speeds that bound its
//! self-stable range.
//!
//! ```sh
//! cargo run --release --example bicycle [plot directory]
//! ```
//!
//! Eight coordinates (rear contact x, y; yaw, roll, pitch; the rear wheel's angle on the
//! frame, steer, the front wheel's angle), two wheels rolling without slip: four rolling rows
//! and the front wheel's contact height, five constraints leaving three free speeds (roll,
//! steer, rear wheel). The linearisation recovers the paper's M, C₁, K₀, K₂ (its eq.
//! 5.3–5.6); the eigenvalues are compared with its Table 2 at 1 … 10 m/s, and a nonlinear run
//! at 5 m/s shows the weave dying out with the energy kept.

mod common;

use std::error::Error;
use std::time::Instant;

use common::{Axes, Series, Table, plot};
use precess::mechanism::rolling::split_rolling;
use precess::models::Bicycle;
use precess::nalgebra::Matrix2;
use precess::ode::{AdaptiveConfig, Dop853};
use precess::prelude::*;
use precess_testkit::bicycle::{CAPSIZE_SPEED, Linear, TABLE_2, WEAVE_SPEED};

fn matrix_rows(table: &mut Table, name: &str, got: &Matrix2<f64>, paper: &Matrix2<f64>) {
    for i in 0..2 {
        for j in 0..2 {
            table.row(format!("{name}[{i}{j}]"), got[(i, j)], paper[(i, j)]);
        }
    }
}

fn main() -> Result<(), Box<dyn Error>> {
    // Derived when this example was compiled: M, f, A, Ȧq̇ as straight-line code.
    let bike = Bicycle::benchmark();
    let started = Instant::now();
    let lin = bike.canonical()?;
    println!(
        "derived by #[derive(Mechanism)] at compile time; linearised by Bicycle::canonical in \
         {:.1} ms (exact: the derived derivatives of M, f, A and Ȧq̇ through the \
         projection, the pitch following by the implicit-function theorem)",
        1e3 * started.elapsed().as_secs_f64()
    );
    let paper = Linear::published();

    let mut table = Table::default();
    matrix_rows(&mut table, "M", &lin.m, &paper.m);
    matrix_rows(&mut table, "C1", &lin.c1, &paper.c1);
    matrix_rows(&mut table, "K0", &lin.k0, &paper.k0);
    matrix_rows(&mut table, "K2", &lin.k2, &paper.k2);
    table.print("The linearised matrices against the paper (eq. 5.3–5.6; zeros: absolute error)");

    // Where max Re λ crosses zero: the weave pair in [4, 5] m/s, the capsize mode in
    // [5.5, 7] m/s (Brent's method on the spectral abscissa).
    let weave = lin.stability_crossing(4.0, 5.0)?.parameter;
    let capsize = lin.stability_crossing(5.5, 7.0)?.parameter;
    let mut speeds = Table::default();
    speeds.row("weave speed v_w [m/s]", weave, WEAVE_SPEED);
    speeds.row("capsize speed v_c [m/s]", capsize, CAPSIZE_SPEED);
    speeds.print("The self-stable range v_w < v < v_c against the paper's Table 2");

    println!("\nEigenvalues against Table 2 (derived; the paper's in brackets)");
    println!(
        "  {:>4}  {:>20}  {:>36}  {:>20}",
        "v", "capsize", "weave", "castering"
    );
    let mut worst = 0.0_f64;
    for (k, &(cap, re, im, caster)) in TABLE_2.iter().enumerate() {
        let v = (k + 1) as f64;
        // A fresh Jacobian of the nonlinear model at this speed, not the canonical form.
        let (p, d) = bike.lateral_jacobian(v)?;
        let mut a = precess::nalgebra::Matrix4::zeros();
        a[(0, 2)] = 1.0;
        a[(1, 3)] = 1.0;
        a.fixed_view_mut::<2, 2>(2, 0).copy_from(&p);
        a.fixed_view_mut::<2, 2>(2, 2).copy_from(&d);
        let eig = precess::linalg::eigenvalues(&a)?;
        let real: Vec<f64> = eig.iter().filter(|z| z.im == 0.0).map(|z| z.re).collect();
        let pair = eig.iter().find(|z| z.im > 0.0);
        let (got_cap, got_caster) = match real.as_slice() {
            [a, b] => (a.max(*b), a.min(*b)),
            _ => (f64::NAN, f64::NAN),
        };
        let (got_re, got_im) = pair.map_or((f64::NAN, f64::NAN), |z| (z.re, z.im));
        for (g, w) in [
            (got_cap, cap),
            (got_re, re),
            (got_im, im),
            (got_caster, caster),
        ] {
            worst = worst.max((g - w).abs());
        }
        println!(
            "  {v:>4.1}  {got_cap:>20.14}  {got_re:>17.14} ± {got_im:>15.14}i  {got_caster:>20.14}"
        );
        println!(
            "  {:>4}  [{cap:>18.14}]  [{re:>16.14} ± {im:>14.14}i]  [{caster:>18.14}]",
            ""
        );
    }
    println!("  largest difference from Table 2: {worst:.1e}");

    // Real and imaginary parts against the speed, 0 … 10 m/s.
    let (mut re_points, mut im_points) = (Vec::new(), Vec::new());
    for modes in lin.eigenvalues_against_speed((0..=200).map(|k| k as f64 * 0.05))? {
        for z in modes.eigenvalues {
            re_points.push((modes.speed, z.re));
            if z.im > 0.0 {
                im_points.push((modes.speed, z.im));
            }
        }
    }
    let series = [
        Series::markers("Re λ (all four)", re_points),
        Series::markers("Im λ (weave pair)", im_points),
        Series::line("weave speed v_w", vec![(weave, -10.0), (weave, 10.0)]),
        Series::line("capsize speed v_c", vec![(capsize, -10.0), (capsize, 10.0)]),
    ];
    let path = plot(
        "bicycle_eigenvalues.svg",
        &Axes {
            title: "Benchmark bicycle: eigenvalues against forward speed",
            x: "forward speed v [m/s]",
            y: "eigenvalue [1/s]",
            log_x: false,
            log_y: false,
        },
        &series,
    )?;
    println!("\nwrote {}", path.display());

    // The nonlinear model at 5 m/s, pushed with a roll rate of 0.5 rad/s: the weave decays.
    let y0 = bike.upright(5.0, 0.5)?;
    let energy = |y: &[f64; Bicycle::STATE]| -> Result<f64, MechanismError> {
        let (q, u) = split_rolling::<8, 3, { Bicycle::STATE }>(y);
        Ok(bike.energy(&q, &bike.rates(&q, &u)?))
    };
    let e0 = energy(&y0)?;
    let mut ode = Dop853::new(
        bike.rolling_system::<{ Bicycle::STATE }>(),
        0.0,
        y0,
        AdaptiveConfig::with_tol(1e-12, 1e-12),
    )?;
    let (mut lean, mut steer) = (Vec::new(), Vec::new());
    let mut drift = 0.0_f64;
    let mut slip = 0.0_f64;
    // No projection: the pitch is integrated, and the front contact's height measures how
    // far the holonomic constraint drifts.
    let mut height = 0.0_f64;
    for k in 1..=1000 {
        ode.advance_to(k as f64 * 0.01)?;
        let y = *ode.y();
        drift = drift.max(((energy(&y)? - e0) / e0).abs());
        let (q, u) = split_rolling::<8, 3, { Bicycle::STATE }>(&y);
        slip = slip.max(bike.contact_speed(&q, &bike.rates(&q, &u)?));
        height = bike.heights(&q).iter().fold(height, |m, h| m.max(h.abs()));
        lean.push((ode.t(), y[Bicycle::PHI]));
        steer.push((ode.t(), y[Bicycle::DELTA]));
    }
    println!(
        "\nnonlinear run at 5 m/s for 10 s: energy kept to {drift:.1e} (relative), contact slip \
         ≤ {slip:.1e} m/s, front wheel on the ground to {height:.1e} m, lean {:.2e} rad at \
         the end",
        ode.y()[Bicycle::PHI]
    );
    let path = plot(
        "bicycle_weave.svg",
        &Axes {
            title: "Nonlinear benchmark bicycle at 5 m/s after a roll-rate push of 0.5 rad/s",
            x: "time t [s]",
            y: "angle [rad]",
            log_x: false,
            log_y: false,
        },
        &[Series::line("roll φ", lean), Series::line("steer δ", steer)],
    )?;
    println!("wrote {}", path.display());
    Ok(())
}
