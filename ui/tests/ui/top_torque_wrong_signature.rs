use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1, at = [0.0, 0.0, 0.1]), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81, torque = drive)]
struct Spinner;

/// The torque as a function of time alone: not the signature `#[top(torque = ..)]` calls.
fn drive(_: &Spinner, t: f64) -> Vector3<f64> {
    Vector3::new(0.0, 0.0, t)
}

fn main() {}
