//! Linearisations of derived tops and of Euler's equations against closed forms: the
//! sleeping-top threshold (ZYX, regular at the vertical), steady precession's small nutation
//! on both branches, the intermediate-axis growth rate, and the 6×6 top Jacobians checked
//! through their characteristic polynomial.

use crate::common;

use approx::assert_relative_eq;
use common::tops::ReferenceTop;
use precess::prelude::*;
use precess_core::body::euler_rhs_diagonal;
use precess_core::linalg::{LinearSystem, Stability, eigenvalues};
use precess_core::nalgebra::{Complex, DMatrix};
use precess_core::ode::{AdaptiveConfig, Dop853, FnSystem};
use precess_core::top::{
    HeavyTopTheory, LinearisationError, SleepingTop, angle_linearisation, reduced_linearisation,
};
use std::f64::consts::FRAC_PI_3;

/// The same top in ZYX, whose chart is regular with the axis vertical.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 1.0, angles = zyx)]
struct UprightTop;

fn reference() -> HeavyTopTheory {
    HeavyTopTheory::new(1.0, 0.5, 1.0).unwrap()
}

/// Sorted |Im λ| of the eigenvalues with |Im λ| above `floor`.
fn frequencies(eig: &[Complex<f64>], floor: f64) -> Vec<f64> {
    let mut f: Vec<f64> = eig
        .iter()
        .map(|e| e.im.abs())
        .filter(|&w| w > floor)
        .collect();
    f.sort_by(f64::total_cmp);
    f
}

/// The sleeping top (ZYX about the vertical, spinning at ω3): linearly stable iff
/// ω3 > √(4 M g l I1)/I3 = 4; below, perturbations grow at √(4 I1 M g l − I3² ω3²)/(2 I1).
/// The tilt in the ZYX chart is seen from a frame turning with the yaw, so the cone rates σ
/// of the theory appear as |σ − ω3|. The full 6×6 and the reduced 4×4 (p_yaw fixed) agree.
#[test]
fn sleeping_top_threshold_in_the_zyx_chart() {
    let theory = reference();
    let q = [0.0, 0.0, 0.0];
    for w3 in [3.0, 3.9, 3.99, 4.01, 4.1, 6.0] {
        let qd = UprightTop
            .rates_from_omega(&q, &Vector3::new(0.0, 0.0, w3))
            .unwrap();
        let full = angle_linearisation(&UprightTop, 0.0, &q, &qd).unwrap();
        let reduced = reduced_linearisation(&UprightTop, 0.0, &q, &qd).unwrap();
        assert_eq!(reduced.kept, vec![1, 2], "yaw is the cyclic coordinate");
        for (name, lin) in [("full", &full), ("reduced", &reduced.system)] {
            let eig = lin.eigenvalues().unwrap();
            let verdict = lin.stability().unwrap();
            match theory.sleeping_top(w3).unwrap() {
                SleepingTop::Stable { slow, fast } => {
                    assert!(
                        matches!(verdict, Stability::LinearlyStable { .. }),
                        "{name}, ω3 = {w3}: {verdict:?} {eig:?}"
                    );
                    let expected = {
                        let mut e = [(slow - w3).abs(), (fast - w3).abs()];
                        e.sort_by(f64::total_cmp);
                        e
                    };
                    let got = frequencies(&eig, 1e-6);
                    assert_eq!(got.len(), 4, "{name}, ω3 = {w3}: {eig:?}");
                    for (g, e) in got.chunks(2).zip(expected) {
                        assert_relative_eq!(g[0], e, max_relative = 1e-9);
                        assert_relative_eq!(g[1], e, max_relative = 1e-9);
                    }
                }
                SleepingTop::Unstable { growth_rate, .. } => match verdict {
                    Stability::Unstable { growth_rate: g } => {
                        eprintln!("{name}, ω3 = {w3}: growth {g} vs {growth_rate}");
                        assert_relative_eq!(g, growth_rate, max_relative = 1e-9)
                    }
                    other => panic!("{name}, ω3 = {w3}: {other:?}"),
                },
                SleepingTop::Threshold { .. } => unreachable!(),
            }
        }
    }
}

/// Steady precession on the slow and fast branches, above and below the horizontal: the
/// generated 6×6 Jacobian, the Routh-reduced 2×2 from the derived top, and the analytic
/// reduced system all give ±i ω_n with ω_n = √((a − 2Ω cos θ)² + Ω² sin²θ), and say linearly
/// stable.
#[test]
fn steady_precession_branches_are_linearly_stable() {
    let theory = reference();
    let mut cases = 0;
    for theta in [0.3, FRAC_PI_3, 1.2, 2.0] {
        for w3 in [5.0, 10.0, -7.0] {
            let steady = theory.steady_precession(theta, w3).unwrap();
            for omega_p in [steady.slow, steady.fast.unwrap()] {
                cases += 1;
                let (q, qd) = ([0.3, theta, -0.2], steady.rates(omega_p));
                let w_n = theory.small_nutation_frequency(theta, omega_p, w3).unwrap();
                let full = angle_linearisation(&ReferenceTop, 0.0, &q, &qd).unwrap();
                let reduced = reduced_linearisation(&ReferenceTop, 0.0, &q, &qd).unwrap();
                assert_eq!(reduced.kept, vec![1]);
                let [p_phi, _, p_psi] = reduced.momenta;
                let analytic = theory
                    .reduced_linearisation(theta, p_phi.unwrap(), p_psi.unwrap())
                    .unwrap();
                for (name, lin, tol) in [
                    ("full", &full, 1e-11),
                    ("reduced", &reduced.system, 1e-9),
                    ("analytic", &analytic, 1e-12),
                ] {
                    let eig = lin.eigenvalues().unwrap();
                    let got = frequencies(&eig, 1e-6);
                    assert_eq!(got.len(), 2, "{name}: {eig:?}");
                    for g in got {
                        assert_relative_eq!(g, w_n, max_relative = tol);
                    }
                    assert!(
                        matches!(lin.stability().unwrap(), Stability::LinearlyStable { .. }),
                        "{name}, θ = {theta}, ω3 = {w3}, Ω = {omega_p}: {eig:?}"
                    );
                }
            }
        }
    }
    assert_eq!(cases, 24);
}

/// The small nutation about steady precession, measured: a kick of 1e-6 in θ̇, integrated
/// with DOP853, crosses θ̇ = 0 rising every 2π/ω_n (amplitude effects O(1e-12)).
#[test]
fn integrated_small_nutation_matches_the_linear_frequency() {
    let theory = reference();
    let theta = FRAC_PI_3;
    let steady = theory.steady_precession(theta, 10.0).unwrap();
    for omega_p in [steady.slow, steady.fast.unwrap()] {
        let w_n = theory
            .small_nutation_frequency(theta, omega_p, 10.0)
            .unwrap();
        let period = 2.0 * std::f64::consts::PI / w_n;
        let r = steady.rates(omega_p);
        let chart = TopChart::declared(&ReferenceTop);
        let y0 = [0.0, theta, 0.0, r[0], 1e-6, r[2]];
        let cfg = AdaptiveConfig::with_tol(1e-13, 1e-15);
        let mut ode = Dop853::new(&chart, 0.0, y0, cfg).unwrap();
        // θ̇ = 1e-6 cos(ω_n t): rising zero crossings every period, the first at 3/4.
        let mut rising = Vec::new();
        while rising.len() < 4 {
            let (t_before, before) = (ode.t(), ode.y()[4]);
            ode.step(10.0 * period).unwrap();
            if before < 0.0 && ode.y()[4] >= 0.0 {
                // The crossing lies in the step just taken: bisection on its dense output.
                let (mut lo, mut hi) = (t_before, ode.t());
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    if ode.dense_at(mid).unwrap()[4] < 0.0 {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                rising.push(0.5 * (lo + hi));
            }
        }
        let measured = (rising[3] - rising[0]) / 3.0;
        eprintln!("Ω = {omega_p}: integrated nutation period {measured}, linear {period}");
        assert_relative_eq!(measured, period, max_relative = 1e-9);
    }
}

/// Euler's equations about each principal axis: the intermediate one grows at
/// ω √((I2 − I1)(I3 − I2)/(I1 I3)); the others oscillate at ω √((I_j − I_i)(I_k − I_i)/(I_j I_k)).
#[test]
fn free_body_axes() {
    let i = [1.0, 2.0, 3.5];
    let moments = Vector3::from(i);
    let euler = FnSystem(move |_t: f64, y: &[f64; 3], d: &mut [f64; 3]| {
        let dw = euler_rhs_diagonal(&moments, &Vector3::from(*y), &Vector3::zeros());
        d.copy_from_slice(dw.as_slice());
    });
    let w = 2.5;
    let lin = LinearSystem::from_system(&euler, 0.0, &[0.0, w, 0.0]).unwrap();
    let growth = w * ((i[1] - i[0]) * (i[2] - i[1]) / (i[0] * i[2])).sqrt();
    match lin.stability().unwrap() {
        Stability::Unstable { growth_rate } => {
            assert_relative_eq!(growth_rate, growth, max_relative = 1e-11)
        }
        other => panic!("{other:?}"),
    }
    for (axis, (j, k)) in [(0, (1, 2)), (2, (0, 1))] {
        let mut y = [0.0; 3];
        y[axis] = w;
        let lin = LinearSystem::from_system(&euler, 0.0, &y).unwrap();
        let freq = w * ((i[j] - i[axis]) * (i[k] - i[axis]) / (i[j] * i[k])).sqrt();
        assert!(matches!(
            lin.stability().unwrap(),
            Stability::LinearlyStable { .. }
        ));
        for f in frequencies(&lin.eigenvalues().unwrap(), 1e-6) {
            assert_relative_eq!(f, freq, max_relative = 1e-11);
        }
    }
}

/// The characteristic polynomial by Faddeev–LeVerrier (traces of matrix powers, no
/// eigenvalues), against the one expanded from the computed eigenvalues.
fn check_by_characteristic_polynomial(a: &DMatrix<f64>) {
    let n = a.nrows();
    let mut coef = vec![0.0; n + 1];
    coef[n] = 1.0;
    let mut m = DMatrix::<f64>::zeros(n, n);
    for k in 1..=n {
        m = a * &m + DMatrix::identity(n, n) * coef[n - k + 1];
        coef[n - k] = -(a * &m).trace() / k as f64;
    }
    let eig = eigenvalues(a).unwrap();
    let mut from_eig = vec![Complex::new(0.0, 0.0); n + 1];
    from_eig[0] = Complex::new(1.0, 0.0);
    for (len, e) in eig.iter().enumerate() {
        for j in (1..=len + 1).rev() {
            let prev = from_eig[j - 1];
            from_eig[j] -= prev * e;
        }
    }
    // from_eig[j] is the coefficient of λ^{n−j}.
    let scale = a.norm().max(1.0);
    for j in 0..=n {
        let got = from_eig[j];
        let want = coef[n - j];
        let tol = 1e-12 * scale.powi(j as i32);
        assert!(
            (got.re - want).abs() < tol && got.im.abs() < tol,
            "λ^{}: {got} vs {want}",
            n - j
        );
    }
}

/// The generated 6×6 Jacobians of tops, at generic states and at steady and sleeping
/// motions (defective zero eigenvalues from the cyclic coordinates): the routine returns,
/// and its eigenvalues rebuild the characteristic polynomial. The upright ZYX top at
/// ω3 = 3 is a matrix on which nalgebra 0.34's `complex_eigenvalues` did not return within
/// a minute.
#[test]
fn six_by_six_top_jacobians() {
    let theory = reference();
    let steady = theory.steady_precession(FRAC_PI_3, 10.0).unwrap();
    let states = [
        ([0.1, 1.0, -0.3], [0.3, 0.5, 8.0]),
        ([2.0, 0.4, 1.0], [-1.5, 2.0, -3.0]),
        ([0.0, FRAC_PI_3, 0.0], steady.rates(steady.slow)),
        ([0.0, FRAC_PI_3, 0.0], steady.rates(steady.fast.unwrap())),
        ([0.0, 2.9, 0.0], [0.0, 0.0, 0.0]),
    ];
    for (q, qd) in states {
        let lin = angle_linearisation(&ReferenceTop, 0.0, &q, &qd).unwrap();
        check_by_characteristic_polynomial(lin.matrix());
    }
    for w3 in [0.0, 3.0, 10.0] {
        let q = [0.0, 0.0, 0.0];
        let qd = UprightTop
            .rates_from_omega(&q, &Vector3::new(0.0, 0.0, w3))
            .unwrap();
        let lin = angle_linearisation(&UprightTop, 0.0, &q, &qd).unwrap();
        check_by_characteristic_polynomial(lin.matrix());
    }
}

/// The angle form refuses its gimbal lock and non-finite states with the top's typed errors.
#[test]
fn singular_and_bad_states_are_refused() {
    let at_lock = angle_linearisation(&ReferenceTop, 0.0, &[0.0, 0.0, 0.0], &[0.0, 0.0, 5.0]);
    assert!(matches!(
        at_lock,
        Err(LinearisationError::Top(TopError::Chart(
            ChartError::SingularChart { .. }
        )))
    ));
    // Regular chart (|det B| = sin θ = 1e-7) but p_φ, p_ψ no longer determine φ̇, ψ̇:
    // det M_cc relative to its diagonal is (I1/I3) sin²θ = 2e-14.
    let near_lock = reduced_linearisation(&ReferenceTop, 0.0, &[0.0, 1e-7, 0.0], &[0.0, 0.0, 5.0]);
    assert!(
        matches!(near_lock, Err(LinearisationError::SingularMomentumMap { det, .. }) if det < 1e-13),
        "{near_lock:?}"
    );
    let nan = reduced_linearisation(&ReferenceTop, 0.0, &[0.0, f64::NAN, 0.0], &[0.0; 3]);
    assert!(matches!(
        nan,
        Err(LinearisationError::Top(TopError::NonFinite { .. }))
    ));
}
