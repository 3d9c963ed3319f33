//! The Whipple bicycle, derived nonlinear by the symbolic engine, against the benchmark of
//! Meijaard, Papadopoulos, Ruina & Schwab (Proc. R. Soc. A 463, 2007): the linearised
//! matrices of their eq. 5.3–5.6, the eigenvalues of their Table 2 at 0 … 10 m/s, the weave
//! and capsize speeds, and the nonlinear motion against their linear equations.

use std::sync::OnceLock;

use precess::nalgebra::{Complex, Matrix2, Matrix3, Rotation3, Unit, Vector3};
use precess::ode::{AdaptiveConfig, Dop853, FnSystem};
use precess_testkit::bicycle::{
    CAPSIZE_SPEED, Linear, Parameters, STANDSTILL, STATE, TABLE_2, WEAVE_FREQUENCY, WEAVE_SPEED,
    Whipple,
};
use precess_testkit::rng::Rng;

/// The derived bicycle (its evaluation buffers are per thread, so each test derives its
/// own: about a second).
fn bike() -> Whipple {
    Whipple::new(&Parameters::benchmark()).expect("derives")
}

fn linear() -> &'static Linear {
    static LIN: OnceLock<Linear> = OnceLock::new();
    LIN.get_or_init(|| bike().linearise().expect("linearises"))
}

/// Largest entrywise error, relative to the entry where it is nonzero and absolute where
/// the paper prints 0.
pub(super) fn worst(got: &Matrix2<f64>, want: &Matrix2<f64>) -> f64 {
    got.iter()
        .zip(want.iter())
        .map(|(g, w)| {
            if *w == 0.0 {
                g.abs()
            } else {
                ((g - w) / w).abs()
            }
        })
        .fold(0.0, f64::max)
}

#[test]
fn linearised_matrices_match_the_papers_fifteen_digits() {
    let (lin, paper) = (linear(), Linear::published());
    let errors = [
        ("M", worst(&lin.m, &paper.m)),
        ("C1", worst(&lin.c1, &paper.c1)),
        ("K0", worst(&lin.k0, &paper.k0)),
        ("K2", worst(&lin.k2, &paper.k2)),
    ];
    println!("{errors:?}");
    // Measured: M 1.4e-14, C1 5.5e-15, K0 5.1e-15, K2 2.0e-15 (relative; the printed zeros
    // below 1e-15 absolute). The paper prints 15 significant digits.
    for (name, e) in errors {
        assert!(e < 1e-13, "{name} off the paper by {e:e}");
    }
}

fn nearest(eig: &[Complex<f64>], want: Complex<f64>) -> f64 {
    eig.iter()
        .map(|z| (z - want).norm())
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn eigenvalues_match_table_2_from_standstill_to_ten_metres_a_second() {
    let lin = linear();
    let mut worst_err = 0.0_f64;
    // At rest: ±3.13164324790656 and ±5.53094371765393, the two inverted pendulums.
    let still = lin.eigenvalues(0.0).expect("eigenvalues");
    for want in STANDSTILL {
        worst_err = worst_err.max(nearest(&still, Complex::new(want, 0.0)));
    }
    for (k, &(capsize, re, im, caster)) in TABLE_2.iter().enumerate() {
        let eig = lin.eigenvalues((k + 1) as f64).expect("eigenvalues");
        for want in [
            Complex::new(capsize, 0.0),
            Complex::new(re, im),
            Complex::new(re, -im),
            Complex::new(caster, 0.0),
        ] {
            worst_err = worst_err.max(nearest(&eig, want));
        }
    }
    println!("worst eigenvalue error {worst_err:e}");
    // Measured 7.3e-13 absolute, on eigenvalues up to 24.6 (3e-14 relative); the table
    // prints 14 decimals.
    assert!(
        worst_err < 2e-12,
        "eigenvalues off Table 2 by {worst_err:e}"
    );
}

#[test]
fn weave_and_capsize_speeds_match_the_paper() {
    let lin = linear();
    let weave = lin.weave_speed(4.0, 5.0).expect("weave in [4, 5]");
    let capsize = lin.capsize_speed(5.5, 7.0).expect("capsize in [5.5, 7]");
    let (paper_weave, paper_capsize) = (WEAVE_SPEED, CAPSIZE_SPEED);
    let (ew, ec) = (
        ((weave - paper_weave) / paper_weave).abs(),
        ((capsize - paper_capsize) / paper_capsize).abs(),
    );
    println!("weave {weave:.15} ({ew:e}), capsize {capsize:.15} ({ec:e})");
    assert!(ew < 1e-12 && ec < 1e-12, "weave {ew:e}, capsize {ec:e}");
    // The capsize speed independently: the capsize root crosses zero where
    // det(g K₀ + v² K₂) = 0, a quadratic in s = v²: a s² + b s + c = 0.
    let (k0, k2) = (lin.k0 * lin.g, lin.k2);
    let a = k2[(0, 0)] * k2[(1, 1)] - k2[(0, 1)] * k2[(1, 0)];
    let b = k0[(0, 0)] * k2[(1, 1)] + k2[(0, 0)] * k0[(1, 1)]
        - k0[(0, 1)] * k2[(1, 0)]
        - k2[(0, 1)] * k0[(1, 0)];
    let c = k0[(0, 0)] * k0[(1, 1)] - k0[(0, 1)] * k0[(1, 0)];
    // K₂'s first column is zero, so a = 0 and the root is s = −c / b.
    assert!(a.abs() < 1e-12, "det K2 = {a:e}");
    let closed = (-c / b).sqrt();
    assert!(
        ((closed - capsize) / capsize).abs() < 1e-13,
        "bisection {capsize} vs det root {closed}"
    );
    // At the weave speed the pair is purely imaginary, ±3.43503384866144 i (Table 2).
    let eig = lin.eigenvalues(paper_weave).expect("eigenvalues");
    let pair = nearest(&eig, Complex::new(0.0, WEAVE_FREQUENCY));
    assert!(pair < 1e-12, "weave pair off by {pair:e}");
}

/// A short run at 5 m/s (inside the self-stable range): the nonlinear model keeps its
/// energy, its contacts still and its front wheel on the ground, and the lean decays.
#[test]
fn nonlinear_run_at_five_metres_a_second_keeps_energy_and_contacts() {
    let bike = &bike();
    let y0 = bike.upright(5.0, 0.5).expect("upright");
    let e0 = bike.outputs(&y0).expect("outputs")[0];
    let cfg = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let mut ode = Dop853::new(bike.system(), 0.0, y0, cfg).expect("starts");
    let (mut drift, mut slip, mut height, mut lean) = (0.0_f64, 0.0_f64, 0.0_f64, 0.0_f64);
    for k in 1..=50 {
        ode.advance_to(k as f64 * 0.1).expect("integrates");
        let y: [f64; STATE] = *ode.y();
        let out = bike.outputs(&y).expect("outputs");
        drift = drift.max(((out[0] - e0) / e0).abs());
        slip = out[1..].iter().fold(slip, |s, v| s.max(v.abs()));
        let mut q = [0.0; 8];
        q.copy_from_slice(&y[..8]);
        height = height.max(bike.front_height(&q).abs());
        lean = lean.max(y[3].abs());
    }
    let final_lean = ode.y()[3].abs() + ode.y()[8].abs();
    println!(
        "energy drift {drift:e}, slip {slip:e} m/s, front height {height:e} m, \
         max lean {lean:.4} rad, final |φ| + |φ̇| {final_lean:e}"
    );
    // Measured: energy 6.9e-15, slip 2.8e-15 m/s, height 4.9e-16 m, max lean 0.103 rad,
    // |φ| + |φ̇| 0.016 at 5 s (from 0.5).
    assert!(drift < 1e-12, "energy drifts by {drift:e}");
    assert!(slip < 1e-12, "a contact slips at {slip:e} m/s");
    assert!(
        height < 1e-9,
        "the front wheel leaves the ground by {height:e} m"
    );
    assert!(lean < 0.2, "lean grew to {lean}");
    // The weave decays at Re λ ≈ −0.4 /s at 5 m/s: after 5 s the lean is well down.
    assert!(final_lean < 0.05, "lean did not decay: {final_lean}");
}

/// A small disturbance of the nonlinear model follows the paper's linear equations (its
/// printed matrices, integrated separately) to the order of the disturbance.
#[test]
fn small_disturbance_follows_the_papers_linear_equations() {
    let bike = bike();
    let v = 4.6;
    let eps = 1e-5;
    let y0 = bike.upright(v, eps).expect("upright");
    let cfg = AdaptiveConfig::with_tol(1e-13, 1e-16);
    let mut nonlinear = Dop853::new(bike.system(), 0.0, y0, cfg).expect("starts");
    let paper = Linear::published();
    let a = paper.state_matrix(v).expect("M invertible");
    let lin_sys = FnSystem(move |_t: f64, y: &[f64; 4], d: &mut [f64; 4]| {
        for (i, di) in d.iter_mut().enumerate() {
            *di = (0..4).map(|j| a[(i, j)] * y[j]).sum();
        }
    });
    let mut linear = Dop853::new(lin_sys, 0.0, [0.0, 0.0, eps, 0.0], cfg).expect("starts");
    let mut worst_err = 0.0_f64;
    let mut scale = 0.0_f64;
    for k in 1..=40 {
        let t = k as f64 * 0.1;
        nonlinear.advance_to(t).expect("integrates");
        linear.advance_to(t).expect("integrates");
        let (n, l) = (nonlinear.y(), linear.y());
        for (got, want) in [(n[3], l[0]), (n[5], l[1]), (n[8], l[2]), (n[9], l[3])] {
            worst_err = worst_err.max((got - want).abs());
            scale = scale.max(want.abs());
        }
    }
    let rel = worst_err / scale;
    println!("nonlinear vs the paper's linear equations: {rel:e} of the motion");
    // Mirror symmetry leaves the lateral equations no quadratic terms, so the nonlinear
    // ones are O(ε³) against the O(ε) motion: ε² = 1e-10 relative. Measured 6.0e-11.
    assert!(
        rel < 1e-9,
        "nonlinear model leaves the linear one by {rel:e}"
    );
}

/// The benchmark geometry written out again numerically with nalgebra's rotations, apart
/// from the derivation: the hubs, the front contact, the frames' orientations.
struct Geometry {
    w: f64,
    c: f64,
    lambda: f64,
    r_r: f64,
    r_f: f64,
}

impl Geometry {
    fn rotations(&self, q: &[f64; 8]) -> (Rotation3<f64>, Rotation3<f64>, Rotation3<f64>) {
        let yaw_roll = Rotation3::from_axis_angle(&Vector3::z_axis(), q[2])
            * Rotation3::from_axis_angle(&Vector3::x_axis(), q[3]);
        let rear = yaw_roll * Rotation3::from_axis_angle(&Vector3::y_axis(), q[4]);
        let axis = Unit::new_normalize(Vector3::new(self.lambda.sin(), 0.0, self.lambda.cos()));
        let front = rear * Rotation3::from_axis_angle(&axis, q[5]);
        (yaw_roll, rear, front)
    }

    /// Rear hub, front hub, front contact (z down).
    fn points(&self, q: &[f64; 8]) -> [Vector3<f64>; 3] {
        let (yaw_roll, rear, front) = self.rotations(q);
        let hub_r = Vector3::new(q[0], q[1], 0.0) + yaw_roll * Vector3::new(0.0, 0.0, -self.r_r);
        let foot = Vector3::new(self.w + self.c, 0.0, 0.0);
        let hub_f = hub_r
            + rear * (foot - Vector3::new(0.0, 0.0, -self.r_r))
            + front * (Vector3::new(self.w, 0.0, -self.r_f) - foot);
        let n = front * Vector3::y();
        let d = Vector3::z() - n * n.z;
        [hub_r, hub_f, hub_f + d.normalize() * self.r_f]
    }
}

/// ω from Ṙ Rᵀ, Ṙ by a central difference along the rates.
fn spin(
    r: impl Fn(&[f64; 8]) -> Matrix3<f64>,
    q: &[f64; 8],
    qd: &[f64; 8],
    h: f64,
) -> Vector3<f64> {
    let shifted = |s: f64| {
        let mut p = *q;
        for (pi, vi) in p.iter_mut().zip(qd) {
            *pi += s * vi;
        }
        r(&p)
    };
    let skew = (shifted(h) - shifted(-h)) / (2.0 * h) * r(q).transpose();
    Vector3::new(skew[(2, 1)], skew[(0, 2)], skew[(1, 0)])
}

/// In every rolling state — seeded random leans, steers, yaws and speeds, the pitch put on
/// the constraint — the material points of both wheels at the ground are still, computed
/// from the geometry above (hub velocity plus ω × arm, by central differences), not from
/// the derived constraint rows.
#[test]
fn contact_points_are_still_by_an_independent_geometry() {
    let bike = &bike();
    let p = Parameters::benchmark();
    let geo = Geometry {
        w: p.get("w"),
        c: p.get("c"),
        lambda: p.get("lambda"),
        r_r: p.get("rR"),
        r_f: p.get("rF"),
    };
    let mut rng = Rng::new(24);
    let h = 1e-6;
    let mut worst_slip = 0.0_f64;
    let mut worst_height = 0.0_f64;
    for _ in 0..64 {
        let mut y = [0.0; STATE];
        y[0] = rng.uniform(-5.0, 5.0);
        y[1] = rng.uniform(-5.0, 5.0);
        y[2] = rng.uniform(-3.0, 3.0);
        y[3] = rng.uniform(-0.6, 0.6);
        y[5] = rng.uniform(-0.8, 0.8);
        let mut q = [0.0; 8];
        q.copy_from_slice(&y[..8]);
        bike.close_front_contact(&mut q)
            .expect("the front wheel reaches the ground");
        y[..8].copy_from_slice(&q);
        y[8] = rng.uniform(-2.0, 2.0);
        y[9] = rng.uniform(-3.0, 3.0);
        y[10] = rng.uniform(-30.0, 30.0);
        let qd = bike.rates(&y).expect("regular");
        let along = |k: usize| {
            let at = |s: f64| {
                let mut p = q;
                for (pi, vi) in p.iter_mut().zip(&qd) {
                    *pi += s * vi;
                }
                geo.points(&p)[k]
            };
            (at(h) - at(-h)) / (2.0 * h)
        };
        let [hub_r, hub_f, contact_f] = geo.points(&q);
        let (yaw_roll, _, front) = geo.rotations(&q);
        // The wheels turn with their carriers plus their spin about the axle.
        let omega_r =
            spin(|p| *geo.rotations(p).0.matrix(), &q, &qd, h) + yaw_roll * Vector3::y() * qd[6];
        let omega_f =
            spin(|p| *geo.rotations(p).2.matrix(), &q, &qd, h) + front * Vector3::y() * qd[7];
        let contact_r = Vector3::new(q[0], q[1], 0.0);
        let slip_r = along(0) + omega_r.cross(&(contact_r - hub_r));
        let slip_f = along(1) + omega_f.cross(&(contact_f - hub_f));
        worst_slip = worst_slip.max(slip_r.amax()).max(slip_f.amax());
        worst_height = worst_height.max(contact_f.z.abs());
    }
    println!("independent slip {worst_slip:e} m/s, front contact height {worst_height:e} m");
    // Central differences at h = 1e-6 on speeds up to 10 m/s: about 1e-9 m/s of error
    // (measured 8.9e-10 m/s; the front contact's height 8.3e-16 m).
    assert!(worst_slip < 1e-7, "a contact slips at {worst_slip:e} m/s");
    assert!(
        worst_height < 1e-14,
        "the front contact is off the ground by {worst_height:e} m"
    );
}
