//! Units on a mechanism's values: each load in the dimension its coordinate gives it, a
//! hinge's spring and effort per radian and in torque, a slider's in N/m and in force.

use precess::mechanism::MechanismDynamics;
use precess::prelude::*;

use crate::common::rng::Rng;

/// A hinged arm 10 cm below its pivot carrying a slider: gravity in cm/s², the hinge's spring
/// in N cm per radian resting at 10°, its damper in N m s, the slider's spring in N/cm resting
/// at 5 mm, its damper in N s/m and a push of 30 mN.
#[derive(Clone, Copy, Mechanism)]
#[mechanism(gravity = 981 cm/s^2)]
#[body(arm, joint = revolute(axis = x, at = [0, 0, -10 cm]), q = theta,
       spring(k = 50 N * cm, rest = 10 deg), damper = 0.02 N * m * s,
       parts(particle(mass = 200 g, at = [0, 0, -20 cm])))]
#[body(slider, parent = arm, joint = prismatic(axis = z, at = [0, 0, -20 cm]), q = s,
       spring(k = 2 N/cm, rest = 5 mm), damper = 0.3 N * s/m, effort = 30 N/1000,
       parts(sphere(mass = 50 g, radius = 1 cm)))]
struct Measured;

/// The same mechanism in SI, converted by hand: 50 N cm = 0.5 N m, 10° =
/// 0.17453292519943295 rad, 2 N/cm = 200 N/m.
#[derive(Clone, Copy, Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(arm, joint = revolute(axis = x, at = [0, 0, -0.1]), q = theta,
       spring(k = 0.5, rest = 0.17453292519943295), damper = 0.02,
       parts(particle(mass = 0.2, at = [0, 0, -0.2])))]
#[body(slider, parent = arm, joint = prismatic(axis = z, at = [0, 0, -0.2]), q = s,
       spring(k = 200, rest = 0.005), damper = 0.3, effort = 0.03,
       parts(sphere(mass = 0.05, radius = 0.01)))]
struct Si;

#[test]
fn a_mechanism_in_cm_g_and_deg_is_the_same_mechanism_in_si() {
    let mut rng = Rng::new(27);
    let mut worst: f64 = 0.0;
    for _ in 0..200 {
        let q = [rng.uniform(-3.0, 3.0), rng.uniform(-0.1, 0.1)];
        let qd = [rng.uniform(-5.0, 5.0), rng.uniform(-1.0, 1.0)];
        let a = Measured.accelerations_unchecked(0.0, &q, &qd);
        let b = Si.accelerations_unchecked(0.0, &q, &qd);
        for k in 0..2 {
            worst = worst.max((a[k] - b[k]).abs() / (1.0 + b[k].abs()));
        }
        let (ea, eb) = (Measured.energy(&q, &qd), Si.energy(&q, &qd));
        worst = worst.max((ea - eb).abs() / (1.0 + eb.abs()));
    }
    eprintln!("mechanism units vs SI: worst relative difference {worst:.1e}");
    // Only the 10° rest angle goes through π: one rounding of one product.
    assert!(worst < 1e-13, "{worst:e}");
}
