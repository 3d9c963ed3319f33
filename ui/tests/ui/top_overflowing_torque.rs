use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1, at = [0.0, 0.0, 0.1]), pivot = [0.0, 0.0, 0.0])]
#[top(body_torque = [0.0, 1e200 * 1e200, 0.0])]
struct Spinner;

fn main() {}
