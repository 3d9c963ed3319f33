use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 1e400), sphere(mass = f64::INFINITY, radius = 1.0))]
struct Body;

fn main() {}
