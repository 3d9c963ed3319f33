use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 0.0, radius = 0.1, colour = 3.0), cube(size = 1.0), cone(mass = 1.0, radius = 0.1))]
struct Body;

fn main() {}
