use precess::prelude::*;

// I₃ = 0.02 and a wheel of J = 0.02 (1 − 10⁻¹⁵) on the z axis: the free body keeps a moment
// of 2·10⁻¹⁷ about the axis once the wheel turns freely, a few ulps of its moments and so
// singular to rounding. The message prints that moment, where four decimals showed 0.0000.
#[derive(RigidBody)]
#[rigid(body(mass = 1.0, inertia = diag(0.05, 0.05, 0.02)))]
#[free(rotor(axis = [0, 0, 1], inertia = 0.019999999999999980, torque = motor))]
struct Gyrostat;

fn motor(_: &Gyrostat, _t: f64, _y: &[f64]) -> f64 {
    0.01
}

fn main() {}
