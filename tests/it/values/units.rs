//! Units on values: a wooden top declared in cm, g, deg, rpm and g/cm³ is the same top as
//! declared in SI, and its sleeping threshold is the hand computation's.

use approx::assert_relative_eq;
use precess::prelude::*;
use precess::top::HeavyTopTheory;

use crate::common::rng::Rng;

/// A cone of wood (ρ = 0.7 g/cm³) on its apex with a brass stem, tilted 20°, under gravity
/// in cm/s² and a damping of 10⁻⁵ N m per rpm.
#[derive(RigidBody)]
#[rigid(
    cone(density = 0.7 g/cm^3, radius = 3 cm, height = 4 cm, axis = -z, at = [0, 0, 4 cm]),
    cylinder(mass = 12 g, radius = 5 mm, length = 3 cm, at = [0, 0, 5.5 cm], rotate = y(20 deg)),
    pivot = [0, 0, 0],
)]
#[top(gravity = 981 cm/s^2, damping = 1e-5 N m / rpm, body_torque = [0, 0, 2 N * mm])]
struct Measured;

/// The same top in SI, every conversion done by hand: 0.7 g/cm³ = 700 kg/m³,
/// 20° = 0.3490658503988659 rad, 10⁻⁵ N m/rpm = 10⁻⁵ · 30/π N m s.
#[derive(RigidBody)]
#[rigid(
    cone(density = 700, radius = 0.03, height = 0.04, axis = -z, at = [0, 0, 0.04]),
    cylinder(mass = 0.012, radius = 0.005, length = 0.03, at = [0, 0, 0.055],
             rotate = y(0.3490658503988659)),
    pivot = [0, 0, 0],
)]
#[top(gravity = 9.81, damping = 9.549296585513721e-5, body_torque = [0, 0, 0.002])]
struct Si;

#[test]
fn a_top_in_cm_g_deg_and_rpm_is_the_same_top_in_si() {
    assert_eq!(Measured.mass(), Si.mass());
    assert_relative_eq!(Measured.inertia(), Si.inertia(), max_relative = 1e-15);
    let mut rng = Rng::new(26);
    let mut worst: f64 = 0.0;
    for _ in 0..200 {
        let q = [
            rng.uniform(-3.0, 3.0),
            rng.uniform(0.2, 2.9),
            rng.uniform(-3.0, 3.0),
        ];
        let qd = [
            rng.uniform(-5.0, 5.0),
            rng.uniform(-5.0, 5.0),
            rng.uniform(-100.0, 100.0),
        ];
        let a = Measured.accelerations_unchecked(0.0, &q, &qd);
        let b = Si.accelerations_unchecked(0.0, &q, &qd);
        for k in 0..3 {
            worst = worst.max((a[k] - b[k]).abs() / (1.0 + b[k].abs()));
        }
    }
    eprintln!("units vs SI: worst relative difference of q̈ {worst:.1e}");
    // The two differ only where π enters (deg, rpm): by the rounding of one product.
    assert!(worst < 1e-13, "{worst:e}");
}

/// A wooden top: a cone (radius 3 cm, height 4 cm) on its apex with a stem (radius 5 mm,
/// length 3 cm) on its base, all of wood at 0.7 g/cm³.
#[derive(RigidBody)]
#[rigid(
    cone(density = 0.7 g/cm^3, radius = 3 cm, height = 4 cm, axis = -z, at = [0, 0, 4 cm]),
    cylinder(density = 0.7 g/cm^3, radius = 5 mm, length = 3 cm, at = [0, 0, 5.5 cm]),
    pivot = [0, 0, 0],
)]
#[top(gravity = 981 cm/s^2)]
struct WoodenTop;

/// The wooden top's M, l, I₁ (about the pivot, transverse) and I₃ by the textbook formulas.
fn by_hand() -> (f64, f64, f64, f64) {
    let pi = std::f64::consts::PI;
    let rho = 700.0;
    // Cone about its apex: m = ρ π R² H/3, G at 3H/4, I₃ = 3/10 m R²,
    // I₁ = 3/5 m H² + 3/20 m R².
    let (r, h) = (0.03, 0.04);
    let mc = rho * pi * r * r * h / 3.0;
    let (zc, i3c, i1c) = (
        0.75 * h,
        0.3 * mc * r * r,
        0.6 * mc * h * h + 0.15 * mc * r * r,
    );
    // Stem: a cylinder of radius a, length L centred at z = H + L/2: I₃ = ½ m a²,
    // I₁ = m (3a² + L²)/12 + m z².
    let (a, len) = (0.005, 0.03);
    let ms = rho * pi * a * a * len;
    let zs = h + len / 2.0;
    let (i3s, i1s) = (
        0.5 * ms * a * a,
        ms * (3.0 * a * a + len * len) / 12.0 + ms * zs * zs,
    );
    let m = mc + ms;
    let l = (mc * zc + ms * zs) / m;
    (m, l, i1c + i1s, i3c + i3s)
}

#[test]
fn the_wooden_tops_sleeping_threshold_is_the_hand_computation() {
    let (m, l, i1, i3) = by_hand();
    let top = WoodenTop;
    assert_relative_eq!(top.mass(), m, max_relative = 1e-14);
    assert_relative_eq!(top.center_of_mass().z, l, max_relative = 1e-14);
    let inertia = top.inertia();
    assert_relative_eq!(inertia[(0, 0)], i1, max_relative = 1e-14);
    assert_relative_eq!(inertia[(2, 2)], i3, max_relative = 1e-14);
    // Gravity in cm/s² is 9.81 m/s²: released at rest at tilt θ, θ̈ = M g l sin θ / I₁.
    let theta = 0.3;
    let qdd = top.accelerations_unchecked(0.0, &[0.0, theta, 0.0], &[0.0; 3]);
    assert_relative_eq!(
        qdd[1],
        m * 9.81 * l * theta.sin() / i1,
        max_relative = 1e-13
    );
    // Sleeping above ω₃ = 2 √(I₁ M g l) / I₃ (Goldstein §5.7).
    let hand = 2.0 * (i1 * m * 9.81 * l).sqrt() / i3;
    let theory = HeavyTopTheory::new(
        inertia[(0, 0)],
        inertia[(2, 2)],
        top.mass() * 9.81 * top.center_of_mass().z,
    )
    .expect("a symmetric top");
    let threshold = theory.sleeping_threshold();
    eprintln!(
        "wooden top: M = {m:.5} kg, l = {l:.5} m, threshold {threshold:.3} rad/s = {:.0} rpm",
        threshold * 30.0 / std::f64::consts::PI
    );
    assert_relative_eq!(threshold, hand, max_relative = 1e-13);
}
