use precess::prelude::*;

// I₃ about the pivot is 0.02: a wheel of J = 0.03 on the z axis leaves the top a negative
// moment once it turns freely.
#[derive(RigidBody)]
#[rigid(body(mass = 1.0, at = [0.0, 0.0, 0.1], inertia = diag(0.05, 0.05, 0.02), about = pivot), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81, rotor(axis = [0, 0, 1], inertia = 0.03, torque = motor))]
struct Gyrotop;

fn motor(_: &Gyrotop, _t: f64, _y: &[f64]) -> f64 {
    0.01
}

fn main() {}
