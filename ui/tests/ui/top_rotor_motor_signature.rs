use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(body(mass = 1.0, at = [0.0, 0.0, 0.1], inertia = diag(0.05, 0.05, 0.02), about = pivot), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81, rotor(axis = [0, 0, 1], inertia = 0.005, torque = motor))]
struct Gyrotop;

// The motor takes the whole state as a slice and returns the torque about the wheel's axis.
fn motor(_: &Gyrotop, _t: f64, _omega: &Vector3<f64>) -> Vector3<f64> {
    Vector3::zeros()
}

fn main() {}
