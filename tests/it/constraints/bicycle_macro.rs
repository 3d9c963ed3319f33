//! The Whipple bicycle derived by `#[derive(Mechanism)]` (examples/mechanisms/bicycle.rs),
//! linearised, against Meijaard, Papadopoulos, Ruina & Schwab (Proc. R. Soc. A 463, 2007):
//! their eq. 5.3–5.6, Table 2 and the weave and capsize speeds. bicycle_macro_cross.rs
//! checks the same struct against two other formulations.

use super::bicycle::worst;
use std::sync::OnceLock;

use precess::mechanism::rolling::RollingDynamics;
use precess::nalgebra::{Complex, Matrix2, Matrix4};
use precess_testkit::bicycle::{CAPSIZE_SPEED, Linear, TABLE_2, WEAVE_SPEED};

use crate::common::mechanism::examples::bicycle::Bicycle;

const PHI: usize = Bicycle::PHI;
const DELTA: usize = Bicycle::DELTA;

/// [φ̈, δ̈] on the constraint at roll φ, steer δ, their rates, the rear wheel turning at
/// −v / r_R: the pitch put back on the floor first.
fn lateral(bike: &Bicycle, x: [f64; 4], v: f64) -> [f64; 2] {
    let mut q = [0.0; 8];
    q[PHI] = x[0];
    q[DELTA] = x[1];
    bike.close_contacts(&mut q).expect("closes");
    let (_, ud) = bike
        .derivative(0.0, &q, &[x[2], x[3], -v / bike.r_r])
        .expect("derivative");
    [ud[0], ud[1]]
}

/// ∂[φ̈, δ̈]/∂x_j at the upright run: central differences extrapolated twice by Richardson
/// (steps 10⁻², ½·10⁻², ¼·10⁻²) for the angles; for the rates one central difference of
/// step 1, exact since the accelerations are quadratic in the speeds.
fn column(bike: &Bicycle, j: usize, v: f64) -> [f64; 2] {
    let central = |h: f64| {
        let (mut xp, mut xm) = ([0.0; 4], [0.0; 4]);
        xp[j] = h;
        xm[j] = -h;
        let (p, m) = (lateral(bike, xp, v), lateral(bike, xm, v));
        [(p[0] - m[0]) / (2.0 * h), (p[1] - m[1]) / (2.0 * h)]
    };
    if j >= 2 {
        return central(1.0);
    }
    let h = 1e-2;
    let d = [central(h), central(h / 2.0), central(h / 4.0)];
    [0, 1].map(|i| {
        let r1 = (4.0 * d[1][i] - d[0][i]) / 3.0;
        let r2 = (4.0 * d[2][i] - d[1][i]) / 3.0;
        (16.0 * r2 - r1) / 15.0
    })
}

/// The lateral state matrix of (φ, δ, φ̇, δ̇) at speed v, from the derived bicycle alone.
fn state_matrix(bike: &Bicycle, v: f64) -> Matrix4<f64> {
    let mut a = Matrix4::zeros();
    a[(0, 2)] = 1.0;
    a[(1, 3)] = 1.0;
    for j in 0..4 {
        let c = column(bike, j, v);
        a[(2, j)] = c[0];
        a[(3, j)] = c[1];
    }
    a
}

fn nearest(eig: &[Complex<f64>], want: Complex<f64>) -> f64 {
    eig.iter()
        .map(|z| (z - want).norm())
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn eigenvalues_of_the_derived_bicycle_match_table_2() {
    let bike = Bicycle::benchmark();
    let mut worst = 0.0_f64;
    for (k, &(capsize, re, im, caster)) in TABLE_2.iter().enumerate() {
        let eig = precess::linalg::eigenvalues(&state_matrix(&bike, (k + 1) as f64))
            .expect("eigenvalues");
        for want in [
            Complex::new(capsize, 0.0),
            Complex::new(re, im),
            Complex::new(re, -im),
            Complex::new(caster, 0.0),
        ] {
            worst = worst.max(nearest(&eig, want) / want.norm());
        }
    }
    println!("largest relative eigenvalue error {worst:e}");
    // Measured 2.9e-12 relative (the table prints 14 decimals; its smallest eigenvalue,
    // −0.004 at 6 m/s, carries the Jacobian's absolute error magnified).
    assert!(
        worst < 1e-10,
        "eigenvalues off Table 2 by {worst:e} (relative)"
    );
}

/// The paper's M q̈ + v C₁ q̇ + (g K₀ + v² K₂) q = 0 from the derived bicycle: M is the
/// lateral block of the reduced mass matrix Sᵀ M S at the upright run, and u̇ = M⁻¹ r, so
/// the state matrix's lower half [−M⁻¹ (g K₀ + v² K₂), −v M⁻¹ C₁] is exactly quadratic and
/// linear in v: the speeds 0 and 1 fix K₀, K₂ and C₁.
fn linear() -> &'static Linear {
    static LIN: OnceLock<Linear> = OnceLock::new();
    LIN.get_or_init(|| {
        let bike = Bicycle::benchmark();
        let mut q = [0.0; 8];
        bike.close_contacts(&mut q).expect("closes");
        let (a, _) = bike.constraint_rows(&q, &[0.0; 8]);
        let s = bike
            .partition()
            .rates(&a, &[0.0; 3])
            .expect("projects")
            .projection;
        let (mass, _) = bike.mass_forcing(0.0, &q, &[0.0; 8]);
        let reduced = s.transpose() * mass * s;
        let m = Matrix2::new(
            reduced[(0, 0)],
            reduced[(0, 1)],
            reduced[(1, 0)],
            reduced[(1, 1)],
        );
        let (a0, a1) = (state_matrix(&bike, 0.0), state_matrix(&bike, 1.0));
        let block = |a: &Matrix4<f64>, c: usize| {
            Matrix2::new(a[(2, c)], a[(2, c + 1)], a[(3, c)], a[(3, c + 1)])
        };
        Linear {
            m,
            k0: -(m * block(&a0, 0)) / bike.g,
            k2: -(m * (block(&a1, 0) - block(&a0, 0))),
            c1: -(m * block(&a1, 2)),
            g: bike.g,
        }
    })
}

#[test]
fn linearised_matrices_of_the_derived_bicycle_match_the_paper() {
    let (lin, paper) = (linear(), Linear::published());
    let errors = [
        ("M", worst(&lin.m, &paper.m)),
        ("C1", worst(&lin.c1, &paper.c1)),
        ("K0", worst(&lin.k0, &paper.k0)),
        ("K2", worst(&lin.k2, &paper.k2)),
    ];
    println!("{errors:?}");
    // Measured: M 1.4e-14, C1 5.5e-15, K0 1.3e-14, K2 3.0e-15; the paper prints 15 digits.
    for (name, e) in errors {
        assert!(e < 1e-13, "{name} off the paper by {e:e}");
    }
}

#[test]
fn weave_and_capsize_speeds_of_the_derived_bicycle_match_the_paper() {
    let lin = linear();
    // The structure in v holds: at 7.5 m/s it gives the eigenvalues a fresh Jacobian does.
    let direct = precess::linalg::eigenvalues(&state_matrix(&Bicycle::benchmark(), 7.5))
        .expect("eigenvalues");
    for z in lin.eigenvalues(7.5).expect("eigenvalues") {
        assert!(
            nearest(&direct, z) < 1e-10 * z.norm(),
            "{z} not in {direct:?}"
        );
    }
    let weave = lin.weave_speed(4.0, 5.0).expect("weave in [4, 5]");
    let capsize = lin.capsize_speed(5.5, 7.0).expect("capsize in [5.5, 7]");
    let (ew, ec) = (
        ((weave - WEAVE_SPEED) / WEAVE_SPEED).abs(),
        ((capsize - CAPSIZE_SPEED) / CAPSIZE_SPEED).abs(),
    );
    println!("weave {weave:.15} ({ew:e}), capsize {capsize:.15} ({ec:e})");
    // Measured: weave 1.7e-15, capsize 2.9e-16 relative: the paper's fifteen digits.
    assert!(ew < 1e-12 && ec < 1e-12, "weave {ew:e}, capsize {ec:e}");
}
