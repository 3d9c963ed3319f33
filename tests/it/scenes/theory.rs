//! `TopDynamics::theory()`: the heavy-top closed forms straight from a derived top, with
//! I1, I3 and M g l computed by hand from the parts (parallel-axis sums) and the nutation
//! period checked against an independent DOP853 run of the top's own equations.

use approx::assert_relative_eq;
use precess::ode::{AdaptiveConfig, Dop853};
use precess::prelude::*;
use precess::top::{SleepingTop, TheoryError};

/// A wooden top of stem and disk on a pivot: a cylinder stem of 10 g, radius 3 mm and
/// length 6 cm standing on the pivot, and a disk of 40 g, radius 3 cm and thickness 6 mm
/// centred 4 cm up. Lengths in metres.
#[derive(RigidBody)]
#[rigid(
    cylinder(mass = 0.010, radius = 0.003, length = 0.06, axis = z, at = [0.0, 0.0, 0.03]),
    cylinder(mass = 0.040, radius = 0.03, length = 0.006, axis = z, at = [0.0, 0.0, 0.04]),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81)]
struct WoodenTop;

/// I1, I3 about the pivot and M g l of `WoodenTop`, by hand: a solid cylinder of mass m,
/// radius r, length h has I3 = ½ m r² and I⊥ = m (3 r² + h²)/12 about its centre, plus m d²
/// for its centre at height d.
fn by_hand() -> (f64, f64, f64) {
    let g = 9.81;
    let parts = [(0.010, 0.003, 0.06, 0.03), (0.040, 0.03, 0.006, 0.04)];
    let (mut i1, mut i3, mut mgl) = (0.0, 0.0, 0.0);
    for (m, r, h, d) in parts {
        i1 += m * (3.0 * r * r + h * h) / 12.0 + m * d * d;
        i3 += 0.5 * m * r * r;
        mgl += m * g * d;
    }
    (i1, i3, mgl)
}

#[test]
fn a_derived_top_gives_the_theory_of_its_own_mass_properties() {
    let (i1, i3, mgl) = by_hand();
    let theory = WoodenTop.theory().expect("symmetric, under gravity");
    assert_relative_eq!(theory.i1(), i1, max_relative = 1e-14);
    assert_relative_eq!(theory.i3(), i3, max_relative = 1e-14);
    assert_relative_eq!(theory.mgl(), mgl, max_relative = 1e-14);
    // M g l = 0.5 · 9.81 · 0.002 kg m… summed: 0.01·0.03 + 0.04·0.04 = 1.9e-3 kg m.
    assert_relative_eq!(mgl, 9.81 * 1.9e-3, max_relative = 1e-14);
    // The sleeping threshold ω3² = 4 M g l I1 / I3² and its verdicts either side.
    let threshold = (4.0 * mgl * i1).sqrt() / i3;
    assert_relative_eq!(theory.sleeping_threshold(), threshold, max_relative = 1e-14);
    assert!(matches!(
        theory.sleeping_top(1.01 * threshold),
        Ok(SleepingTop::Stable { .. })
    ));
    assert!(matches!(
        theory.sleeping_top(0.99 * threshold),
        Ok(SleepingTop::Unstable { .. })
    ));
    // The slow steady precession at θ = 30°, spun at 3 × threshold: the smaller root of
    // I1 cos θ Ω² − I3 ω3 Ω + M g l = 0.
    let (theta, w3) = (std::f64::consts::FRAC_PI_6, 3.0 * threshold);
    let (a, b, c) = (i1 * theta.cos(), -i3 * w3, mgl);
    let slow = (-b - (b * b - 4.0 * a * c).sqrt()) / (2.0 * a);
    let steady = theory.steady_precession(theta, w3).expect("fast enough");
    assert_relative_eq!(steady.slow, slow, max_relative = 1e-9);
}

#[test]
fn the_theory_nutation_period_is_the_simulated_one() {
    let theory = WoodenTop.theory().expect("symmetric, under gravity");
    // Released at rest in φ and θ at θ0 = 40°, spinning at twice the sleeping threshold:
    // θ0 is a turning point, so θ comes back to θ0 with θ̇ = 0 after one nutation period.
    let theta0 = 40f64.to_radians();
    let w3 = 2.0 * theory.sleeping_threshold();
    let q = [0.0, theta0, 0.0];
    let q_dot = [0.0, 0.0, w3];
    let motion = theory
        .motion_from_angles(&q, &q_dot)
        .expect("a bounded nutation");
    let period = motion.nutation_period();
    let lowest = motion.theta_max();
    assert!(period.is_finite() && period > 0.0);
    assert_relative_eq!(motion.theta_min(), theta0, max_relative = 1e-12);

    let chart = TopChart::declared(&WoodenTop);
    let tight = AdaptiveConfig::with_tol(1e-13, 1e-13);
    let y0 = [q[0], q[1], q[2], q_dot[0], q_dot[1], q_dot[2]];
    let mut ode = Dop853::new(&chart, 0.0, y0, tight).expect("valid top");
    ode.advance_to(0.5 * period).expect("half a period");
    let (theta_half, theta_dot_half) = (ode.y()[1], ode.y()[4]);
    ode.advance_to(period).expect("a period");
    let (theta_full, theta_dot_full) = (ode.y()[1], ode.y()[4]);
    // Half way the top is at its lowest, at the theory's θ_max, and turning.
    assert_relative_eq!(theta_half, lowest, max_relative = 1e-8);
    let swing = lowest - theta0;
    let rate_scale = swing * std::f64::consts::TAU / period;
    assert!(
        theta_dot_half.abs() < 1e-6 * rate_scale,
        "{theta_dot_half:e}"
    );
    // A period on, it is back at θ0, turning again.
    assert_relative_eq!(theta_full, theta0, max_relative = 1e-9);
    assert!(
        theta_dot_full.abs() < 1e-6 * rate_scale,
        "{theta_dot_full:e}"
    );
}

/// A field gravity: the theory reads its value.
#[derive(RigidBody)]
#[rigid(
    body(mass = 2.0, at = [0.0, 0.0, 0.25], inertia = diag(0.3, 0.3, 0.1), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = g)]
struct OnAnotherPlanet {
    g: f64,
}

#[test]
fn the_theory_reads_field_gravity_and_refuses_none() {
    let mars = OnAnotherPlanet { g: 3.721 };
    assert_relative_eq!(
        mars.theory().expect("under gravity").mgl(),
        2.0 * 3.721 * 0.25,
        max_relative = 1e-15
    );
    let nowhere = OnAnotherPlanet { g: 0.0 };
    assert_eq!(
        nowhere.theory(),
        Err(TopError::Theory(TheoryError::NoGravity))
    );
    let signed = OnAnotherPlanet { g: -9.81 };
    assert_eq!(
        signed.theory(),
        Err(TopError::NegativeGravity { value: -9.81 })
    );
}

#[derive(RigidBody)]
#[rigid(
    cuboid(mass = 1.0, size = [0.1, 0.2, 0.3], at = [0.0, 0.0, 0.15]),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81)]
struct Brick;

#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.01, 0.0, 0.2], inertia = diag(0.3, 0.3, 0.1), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81)]
struct Lopsided;

#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 0.2], inertia = diag(0.3, 0.3, 0.1), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81, damping = 0.01)]
struct Damped;

#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 0.2], inertia = [[0.3, 0.01, 0.0], [0.01, 0.3, 0.0], [0.0, 0.0, 0.1]], about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81)]
struct Skewed;

#[test]
fn the_theory_refuses_a_top_it_does_not_describe() {
    // Ixx = (0.2² + 0.3²)/12 + 0.15², Iyy = (0.1² + 0.3²)/12 + 0.15².
    let Err(TopError::Theory(TheoryError::NotSymmetric { i1, i2, .. })) = Brick.theory() else {
        panic!("{:?}", Brick.theory());
    };
    assert_relative_eq!(i1, 0.13 / 12.0 + 0.0225, max_relative = 1e-14);
    assert_relative_eq!(i2, 0.10 / 12.0 + 0.0225, max_relative = 1e-14);
    assert!(matches!(
        Lopsided.theory(),
        Err(TopError::Theory(TheoryError::CentreOffAxis {
            x: 0.01,
            y: 0.0,
            ..
        }))
    ));
    assert_eq!(
        Damped.theory(),
        Err(TopError::Theory(TheoryError::OtherTorque {
            declared: "damping"
        }))
    );
    assert!(matches!(
        Skewed.theory(),
        Err(TopError::Theory(TheoryError::ProductsOfInertia {
            ixy: 0.01,
            ..
        }))
    ));
}
