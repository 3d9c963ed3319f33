use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1, at = [0.0, 0.0, 0.1]), pivot = [0.0, 0.0, 0.0])]
#[top(torque = drive)]
struct Spinner;

/// Returns the torque's size rather than the torque vector.
fn drive(_: &Spinner, _: f64, _: &Matrix3<f64>, w: &Vector3<f64>) -> f64 {
    -0.1 * w.norm()
}

fn main() {}
