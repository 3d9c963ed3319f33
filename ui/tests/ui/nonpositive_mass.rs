use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1), disk(mass = -0.5, radius = 0.2))]
struct Body;

fn main() {}
