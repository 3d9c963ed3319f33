use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(body(mass = 1.0, at = [0.0, 0.0, 0.1], inertia = diag(0.05, 0.05, 0.02), about = pivot), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81, taylor = 20, rotor(axis = [0, 0, 1], inertia = 0.005, torque = motor))]
struct Gyrotop;

fn motor(_: &Gyrotop, _t: f64, _y: &[f64]) -> f64 {
    0.01
}

fn main() {}
