//! The symmetric top's closed forms against derived tops integrated with DOP853, against
//! published values, against an independent quadrature, and in their limits.

use crate::common;

use approx::assert_relative_eq;
use common::tops::ReferenceTop;
use precess::prelude::*;
use precess_core::body::euler_rhs_diagonal;
use precess_core::ode::{AdaptiveConfig, Dop853, FnSystem, solve};
use precess_core::top::{
    HeavyTopMotion, HeavyTopTheory, SleepingTop, TheoryError, TorqueFreeSymmetric,
};
use std::f64::consts::{FRAC_PI_3, PI};

/// I1 = 2, I3 = 0.7, M g l = 1.5 · 9.81 · 0.8.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.5, at = [0.0, 0.0, 0.8], inertia = diag(2.0, 2.0, 0.7), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81)]
struct HeavierTop;

/// The centre of mass below the pivot: M g l = −1.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, -1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 1.0)]
struct HangingTop;

/// The centre of mass at the pivot: a torque-free symmetric body with I3 = 2 I1.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 0.0], inertia = diag(1.0, 1.0, 2.0), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 1.0)]
struct FreeCoin;

fn reference() -> HeavyTopTheory {
    HeavyTopTheory::new(1.0, 0.5, 1.0).unwrap()
}

fn tight() -> AdaptiveConfig {
    AdaptiveConfig::with_tol(1e-13, 1e-13)
}

/// Integrates the derived top from (q, q̇) and holds the closed forms against it: the
/// conserved quantities, θ(t) at many times, θ_max and θ_min at the predicted turning times
/// (θ̇ = 0 there, five periods on), and the mean precession over five periods.
fn check_against_integration<T: TopDynamics>(
    top: &T,
    theory: HeavyTopTheory,
    q: [f64; 3],
    qd: [f64; 3],
) {
    let motion = theory.motion_from_angles(&q, &qd).unwrap();
    assert!(motion.theta_min() > 0.05 && motion.theta_max() < PI - 0.05);
    // Conserved quantities against the generated energy and momenta.
    assert_relative_eq!(motion.energy(), top.energy(&q, &qd), max_relative = 1e-14);
    let p = top.conserved_momenta(&q, &qd);
    assert_relative_eq!(
        motion.p_phi(),
        p[0].unwrap(),
        max_relative = 1e-14,
        epsilon = 1e-14
    );
    assert_relative_eq!(motion.p_psi(), p[2].unwrap(), max_relative = 1e-14);
    // The cubic vanishes at its roots and equals u̇² at the start.
    let [u1, u2, _] = motion.roots();
    let scale = motion
        .cubic_coefficients()
        .iter()
        .map(|c| c.abs())
        .sum::<f64>();
    for r in motion.roots() {
        // Relative to the sizes of the terms summed at r.
        let terms: f64 = motion
            .cubic_coefficients()
            .iter()
            .enumerate()
            .map(|(k, c)| (c * r.powi(k as i32)).abs())
            .sum();
        assert!(
            motion.cubic_at(r).abs() < 1e-14 * terms,
            "f({r}) = {:e}",
            motion.cubic_at(r)
        );
    }
    let u_dot = -q[1].sin() * qd[1];
    assert_relative_eq!(
        motion.cubic_at(q[1].cos()),
        u_dot * u_dot,
        epsilon = 1e-13 * scale
    );
    assert_relative_eq!(motion.theta_max(), u1.acos(), max_relative = 1e-12);
    assert_relative_eq!(motion.theta_min(), u2.acos(), max_relative = 1e-12);

    let chart = TopChart::declared(top);
    let y0 = [q[0], q[1], q[2], qd[0], qd[1], qd[2]];
    let period = motion.nutation_period();
    // θ(t) at 40 times over three periods.
    let mut ode = Dop853::new(&chart, 0.0, y0, tight()).unwrap();
    let mut worst_theta: f64 = 0.0;
    for k in 1..=40 {
        let t = k as f64 * 3.0 * period / 40.0;
        ode.advance_to(t).unwrap();
        let theta = motion.theta_at(t).unwrap();
        worst_theta = worst_theta.max((ode.y()[1] - theta).abs() / theta);
        assert!(
            (ode.y()[1] - theta).abs() < 1e-9 * theta,
            "t = {t}: integrated θ {} vs closed form {theta}",
            ode.y()[1]
        );
    }
    // The turning points: θ̇ = 0 where predicted, θ = θ_max and θ_min there, over five
    // periods; then the mean precession from the first θ_max over five periods.
    let [t_max, t_min] = motion.turning_times().unwrap();
    let amplitude = motion.theta_max() - motion.theta_min();
    let rate_scale = amplitude * 2.0 * PI / period;
    let mut events: Vec<(f64, f64)> = (0..=5)
        .flat_map(|n| {
            let shift = n as f64 * period;
            [
                (t_max + shift, motion.theta_max()),
                (t_min + shift, motion.theta_min()),
            ]
        })
        .collect();
    events.sort_by(|x, y| x.0.total_cmp(&y.0));
    let mut ode = Dop853::new(&chart, 0.0, y0, tight()).unwrap();
    let mut phi_first = None;
    let mut phi_last = 0.0;
    for (t, theta) in events {
        if t > 0.0 {
            ode.advance_to(t).unwrap();
        }
        check_turning(ode.y(), theta, rate_scale, t);
        if t == t_max {
            phi_first = Some(ode.y()[0]);
        }
        if t == t_max + 5.0 * period {
            phi_last = ode.y()[0];
        }
    }
    let mean = (phi_last - phi_first.unwrap()) / (5.0 * period);
    let predicted = motion.mean_precession_rate().unwrap();
    eprintln!(
        "q̇ = {qd:?}: θ(t) worst relative {worst_theta:.1e}, mean precession relative {:.1e}",
        (mean - predicted).abs() / predicted.abs()
    );
    assert!(
        (mean - predicted).abs() < 1e-9 * predicted.abs().max(1e-3),
        "mean precession: integrated {mean}, closed form {predicted}"
    );
}

fn check_turning(y: &[f64; 6], theta: f64, rate_scale: f64, t: f64) {
    assert!(
        (y[1] - theta).abs() < 1e-10 * theta,
        "t = {t}: θ = {}, expected turning point {theta}",
        y[1]
    );
    assert!(
        y[4].abs() < 1e-8 * rate_scale,
        "t = {t}: θ̇ = {:e} at a predicted turning point",
        y[4]
    );
}

#[test]
fn reference_top_against_integration() {
    let top = ReferenceTop;
    // A generic state; the published fast top; a slow top with wide nutation; a looping
    // precession (φ̇ changes sign).
    for (q, qd) in [
        ([0.1, 1.0, -0.3], [0.3, 0.5, 8.0]),
        ([0.0, FRAC_PI_3, 0.0], [0.0, 0.0, 20.0]),
        ([0.0, 0.5, 0.0], [0.0, 0.0, 5.0]),
        ([0.0, 1.0, 0.0], [-1.0, 0.2, 10.0]),
    ] {
        check_against_integration(&top, reference(), q, qd);
    }
}

#[test]
fn other_tops_against_integration() {
    let heavier = HeavyTopTheory::new(2.0, 0.7, 1.5 * 9.81 * 0.8).unwrap();
    check_against_integration(&HeavierTop, heavier, [0.2, 0.6, -0.4], [1.5, -0.7, 15.0]);
    // Below the pivot, M g l < 0: the closed forms work in u′ = −u.
    let hanging = HeavyTopTheory::new(1.0, 0.5, -1.0).unwrap();
    check_against_integration(&HangingTop, hanging, [0.0, 2.5, 0.0], [0.4, 0.3, 3.0]);
    check_against_integration(&HangingTop, hanging, [0.3, 2.0, 0.0], [-0.2, -0.6, 1.0]);
}

/// REFERENCES: released at rest from 60° with ω3 = 20, nutation 1.7580e-2 rad over
/// 0.634549 s; with ω3 = 50, 2.7779e-3 rad over 0.251729 s (five and six digits).
#[test]
fn published_fast_top_values() {
    for (w3, amplitude, period) in [(20.0, 1.7580e-2, 0.634549), (50.0, 2.7779e-3, 0.251729)] {
        let m = reference()
            .motion_from_angles(&[0.0, FRAC_PI_3, 0.0], &[0.0, 0.0, w3])
            .unwrap();
        assert_eq!(m.theta_min(), FRAC_PI_3);
        assert_relative_eq!(m.theta_max() - FRAC_PI_3, amplitude, max_relative = 3e-5);
        assert_relative_eq!(m.nutation_period(), period, max_relative = 2e-6);
    }
}

/// Goldstein's fast top released at rest: as ω3 → ∞ the nutation frequency tends to
/// I3 ω3 / I1, the mean precession to M g l / (I3 ω3) and the nutation depth to
/// 2 I1 M g l sin θ0 / (I3 ω3)², each with a relative error O(1/ω3²).
#[test]
fn fast_top_limits() {
    let top = HeavyTopTheory::new(1.3, 0.4, 0.9).unwrap();
    let theta0 = 0.7;
    let mut previous = [f64::INFINITY; 3];
    for w3 in [1e2, 1e3, 1e4] {
        let m = top
            .motion_from_angles(&[0.0, theta0, 0.0], &[0.0, 0.0, w3])
            .unwrap();
        let errors = [
            2.0 * PI / m.nutation_period() / (0.4 * w3 / 1.3) - 1.0,
            m.mean_precession_rate().unwrap() / (0.9 / (0.4 * w3)) - 1.0,
            (m.theta_max() - theta0) / (2.0 * 1.3 * 0.9 * theta0.sin() / (0.4 * w3).powi(2)) - 1.0,
        ];
        for (e, p) in errors.iter().zip(previous) {
            assert!(e.abs() < 2e-2, "ω3 = {w3}: {errors:?}");
            // Ten times the spin, a hundred times closer (allowing rounding at the end).
            assert!(
                e.abs() < p.abs() / 50.0 || e.abs() < 1e-10,
                "ω3 = {w3}: {errors:?}"
            );
        }
        previous = errors;
    }
}

/// ⟨φ̇⟩ and T by the closed forms against an independent quadrature: with
/// u = u1 + (u2 − u1) sin²χ, dt = 2 dχ/√(β (u3 − u)) is smooth and π-periodic in χ, so the
/// trapezoidal rule over a period converges geometrically; 4096 points reach rounding.
/// 1 ∓ u are formed as (1 ∓ u1) cos²χ + (1 ∓ u2) sin²χ from the turning angles' half
/// angles, so a turning point near the pole (1 − u2 = 2e-4 in one case) keeps its digits.
#[test]
fn mean_precession_and_period_against_quadrature() {
    let top = HeavyTopTheory::new(1.0, 0.5, 1.0).unwrap();
    let beta = 2.0;
    let mut worst: f64 = 0.0;
    for (q, qd) in [
        ([0.0, 1.0, 0.0], [0.3, 0.5, 8.0]),
        ([0.0, FRAC_PI_3, 0.0], [0.0, 0.0, 20.0]),
        ([0.0, 0.5, 0.0], [0.0, 0.0, 5.0]),
        ([0.0, 1.0, 0.0], [-1.0, 0.2, 10.0]),
        ([0.0, 0.2, 0.0], [0.5, 1.5, 4.5]),
        ([0.0, 2.0, 0.0], [2.0, -1.0, 1.0]),
    ] {
        let m = top.motion_from_angles(&q, &qd).unwrap();
        let [u1, u2, u3] = m.roots();
        let half = |theta: f64| {
            (
                2.0 * (theta / 2.0).sin().powi(2),
                2.0 * (theta / 2.0).cos().powi(2),
            )
        };
        let ((om1, op1), (om2, op2)) = (half(m.theta_max()), half(m.theta_min()));
        let (a, b) = (m.p_psi(), m.p_phi());
        let n = 4096;
        let (mut time, mut angle) = (0.0, 0.0);
        for k in 0..n {
            let (s, c) = (PI * k as f64 / n as f64).sin_cos();
            let (s2, c2) = (s * s, c * c);
            let dt = 2.0 / (beta * ((u3 - u1) - (u2 - u1) * s2)).sqrt();
            let (one_minus, one_plus) = (om1 * c2 + om2 * s2, op1 * c2 + op2 * s2);
            time += dt;
            angle += dt * 0.5 * ((b - a) / one_minus + (b + a) / one_plus);
        }
        let (period, mean) = (time * PI / n as f64, angle / time);
        let e1 = (m.nutation_period() - period).abs() / period;
        let e2 = (m.mean_precession_rate().unwrap() - mean).abs() / mean.abs();
        worst = worst.max(e1).max(e2);
    }
    eprintln!("closed forms vs quadrature: worst relative difference {worst:.1e}");
    assert!(worst < 1e-13, "{worst:e}");
}

/// Steady precession is the zero-amplitude limit: θ stays at θ0, the period is the small
/// nutation period 2π/ω_n, and the mean precession is Ω; nearby motions approach both.
#[test]
fn steady_precession_is_the_degenerate_limit() {
    let top = reference();
    let theta = FRAC_PI_3;
    let steady = top.steady_precession(theta, 10.0).unwrap();
    for omega_p in [steady.slow, steady.fast.unwrap()] {
        let qd = steady.rates(omega_p);
        let m = top.motion_from_angles(&[0.0, theta, 0.0], &qd).unwrap();
        let w_n = top.small_nutation_frequency(theta, omega_p, 10.0).unwrap();
        assert!(m.theta_max() - m.theta_min() < 1e-12);
        assert_relative_eq!(m.nutation_period(), 2.0 * PI / w_n, max_relative = 1e-9);
        assert_relative_eq!(
            m.mean_precession_rate().unwrap(),
            omega_p,
            max_relative = 1e-12
        );
        assert_relative_eq!(m.theta_at(3.7).unwrap(), theta, max_relative = 1e-12);
        // A small kick: the amplitude scales with it and the period tends to the limit.
        for kick in [1e-3, 1e-5] {
            let kicked = [qd[0], kick, qd[2]];
            let k = top.motion_from_angles(&[0.0, theta, 0.0], &kicked).unwrap();
            assert_relative_eq!(
                k.theta_max() - k.theta_min(),
                2.0 * kick / w_n,
                max_relative = 3e-3 * kick / 1e-3 + 1e-6
            );
            assert_relative_eq!(
                k.nutation_period(),
                2.0 * PI / w_n,
                max_relative = 10.0 * kick * kick + 1e-9
            );
        }
    }
}

/// The sleeping top: stable iff ω3² > 4 M g l I1 / I3² (ω3 > 4 here). Just above, a top
/// tilted by 1e-3 stays within a few 1e-3; just below, the same tilt opens into a wide
/// nutation; upright exactly, θ stays 0 and the period is the limit 2π/√(a² − 2β).
#[test]
fn sleeping_top_threshold_crossing() {
    let top = reference();
    assert_relative_eq!(top.sleeping_threshold(), 4.0);
    match top.sleeping_top(4.4).unwrap() {
        SleepingTop::Stable { slow, fast } => {
            // I1 σ² − I3 ω3 σ + M g l = 0.
            for s in [slow, fast] {
                assert!((s * s - 2.2 * s + 1.0).abs() < 1e-14);
            }
        }
        other => panic!("{other:?}"),
    }
    match top.sleeping_top(3.6).unwrap() {
        SleepingTop::Unstable {
            growth_rate,
            rotation_rate,
        } => {
            assert_relative_eq!(growth_rate, (4.0f64 - 1.8 * 1.8).sqrt() / 2.0);
            assert_relative_eq!(rotation_rate, 0.9);
        }
        other => panic!("{other:?}"),
    }
    assert_eq!(
        top.sleeping_top(4.0).unwrap(),
        SleepingTop::Threshold { rate: 1.0 }
    );
    for (w3, stable) in [(4.04, true), (3.96, false)] {
        let tilted = top
            .motion(1e-3, 0.0, 0.5 * w3 * 1e-3f64.cos(), 0.5 * w3)
            .unwrap();
        assert_eq!(
            tilted.theta_max() < 0.05,
            stable,
            "ω3 = {w3}: θ_max = {}",
            tilted.theta_max()
        );
        let upright = top.motion(0.0, 0.0, 0.5 * w3, 0.5 * w3).unwrap();
        assert_eq!(upright.theta_max(), 0.0);
        assert_eq!(upright.theta_at(10.0).unwrap(), 0.0);
        if stable {
            let (a, beta) = (0.5 * w3, 2.0);
            let limit = 2.0 * PI / (a * a - 2.0 * beta).sqrt();
            assert_relative_eq!(upright.nutation_period(), limit, max_relative = 1e-12);
        } else {
            assert_eq!(upright.nutation_period(), f64::INFINITY);
        }
    }
}

/// Torque-free symmetric body: ω(t) against Euler's equations integrated, and the space-cone
/// rate against a derived top with its centre of mass at the pivot, started with L along z
/// (the rates from ω by the generated kinematics): φ advances at |L|/I1, θ stays put and ψ̇
/// is −Ω_b.
#[test]
fn torque_free_cones() {
    let omega = [0.4, -0.3, 3.0];
    let body = TorqueFreeSymmetric::new(1.0, 2.0, omega).unwrap();
    let moments = Vector3::new(1.0, 1.0, 2.0);
    let euler = FnSystem(move |_t: f64, y: &[f64; 3], d: &mut [f64; 3]| {
        let dw = euler_rhs_diagonal(&moments, &Vector3::from(*y), &Vector3::zeros());
        d.copy_from_slice(dw.as_slice());
    });
    for t in [0.3, 1.0, 7.5] {
        let s = solve::<precess_core::ode::Dop853Pair, _, 3>(&euler, 0.0, omega, t, &[], tight())
            .unwrap();
        let w = body.omega_at(t).unwrap();
        for i in 0..3 {
            assert!((s.y[i] - w[i]).abs() < 1e-11, "t = {t}: {:?} vs {w:?}", s.y);
        }
    }
    // The attitude with L along space z: Rᵀ ẑ = L/|L| in body axes.
    let l = Vector3::new(omega[0], omega[1], 2.0 * omega[2]);
    let (theta, psi) = (body.axis_angle(), l[0].atan2(l[1]));
    assert_relative_eq!(theta, (l[2] / l.norm()).acos(), max_relative = 1e-14);
    let q = [0.0, theta, psi];
    let qd = FreeCoin
        .rates_from_omega(&q, &Vector3::from(omega))
        .unwrap();
    let chart = TopChart::declared(&FreeCoin);
    let y0 = [q[0], q[1], q[2], qd[0], qd[1], qd[2]];
    let t = 4.0;
    let s = solve::<precess_core::ode::Dop853Pair, _, 6>(&chart, 0.0, y0, t, &[], tight()).unwrap();
    assert_relative_eq!(s.y[0] / t, body.space_cone_rate(), max_relative = 1e-11);
    assert_relative_eq!(s.y[1], theta, max_relative = 1e-11);
    assert_relative_eq!(s.y[5], -body.body_cone_rate(), max_relative = 1e-11);
}

#[test]
fn bad_input_gets_typed_errors() {
    use TheoryError as E;
    assert!(matches!(
        HeavyTopTheory::new(0.0, 1.0, 1.0),
        Err(E::NonPositiveMoment { moment: "I1", .. })
    ));
    assert!(matches!(
        HeavyTopTheory::new(1.0, -1.0, 1.0),
        Err(E::NonPositiveMoment { moment: "I3", .. })
    ));
    assert!(matches!(
        HeavyTopTheory::new(1.0, 1.0, f64::NAN),
        Err(E::NonFinite { .. })
    ));
    assert_eq!(HeavyTopTheory::new(1.0, 1.0, 0.0), Err(E::NoGravity));
    assert!(matches!(
        HeavyTopTheory::from_principal([1.0, 1.1, 0.5], 1.0),
        Err(E::NotSymmetric {
            i1: 1.0,
            i2: 1.1,
            ..
        })
    ));
    assert!(HeavyTopTheory::from_principal([1.0, 1.0, 0.5], 1.0).is_ok());
    let top = reference();
    assert!(matches!(
        top.motion(0.0, 0.0, 1.0, 2.0),
        Err(E::TransverseMomentumAtPole { .. })
    ));
    // sin π rounds to 1.2e-16, not 0: a finite (if huge) energy, not a pole.
    assert!(matches!(
        top.motion(-0.0, 0.0, -1.0, 1.0),
        Err(E::TransverseMomentumAtPole { .. })
    ));
    assert!(top.motion(PI, 0.0, -1.0, 1.0).is_ok());
    assert!(matches!(
        top.motion_from_angles(&[0.0, f64::INFINITY, 0.0], &[0.0; 3]),
        Err(E::NonFinite { .. })
    ));
    let m = top
        .motion_from_angles(&[0.0, 1.0, 0.0], &[0.3, 0.5, 8.0])
        .unwrap();
    assert!(matches!(
        m.precession_rate_at(1.5),
        Err(E::CosineOutOfRange { u: 1.5 })
    ));
    assert!(matches!(
        m.precession_rate_at(0.99),
        Err(E::OutsideNutationBand { .. })
    ));
    assert!(matches!(m.theta_at(f64::NAN), Err(E::NonFinite { .. })));
    assert!(matches!(m.theta_at(1e18), Err(E::Exact(_))));
    assert!(matches!(
        top.steady_precession(0.5, 1.0),
        Err(E::NoSteadyPrecession { .. })
    ));
    assert!(matches!(
        top.small_nutation_frequency(FRAC_PI_3, 0.25, 10.0),
        Err(E::NotSteady { .. })
    ));
    assert!(matches!(
        top.reduced_linearisation(0.0, 1.0, 1.0),
        Err(E::SingularAtPole { .. })
    ));
    assert!(matches!(
        TorqueFreeSymmetric::new(1.0, 0.0, [0.0; 3]),
        Err(E::NonPositiveMoment { .. })
    ));
}

/// The precession rate along the motion, from u, agrees with φ̇ = (p_φ − p_ψ u)/(I1 sin²θ)
/// evaluated from the integrated state (a second formulation).
#[test]
fn precession_rate_along_the_band() {
    let top = reference();
    let (q, qd) = ([0.0, 1.0, 0.0], [0.3, 0.5, 8.0]);
    let m: HeavyTopMotion = top.motion_from_angles(&q, &qd).unwrap();
    let chart = TopChart::declared(&ReferenceTop);
    let mut ode = Dop853::new(
        &chart,
        0.0,
        [q[0], q[1], q[2], qd[0], qd[1], qd[2]],
        tight(),
    )
    .unwrap();
    for k in 1..=10 {
        ode.advance_to(0.1 * k as f64).unwrap();
        let y = ode.y();
        let rate = m.precession_rate_at(y[1].cos()).unwrap();
        assert_relative_eq!(rate, y[3], max_relative = 1e-10);
    }
}
