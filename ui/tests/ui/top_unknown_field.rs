use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = m, radius = 0.1, at = [0.0, 0.0, 0.1]), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = g)]
struct Spinner {
    m: f64,
}

fn main() {}
