use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[top(gravity = 9.81)]
struct Spinner;

fn main() {}
