use precess::prelude::*;

// A density written as a number must be positive.
#[derive(RigidBody)]
#[rigid(sphere(density = -0.7 g/cm^3, radius = 2 cm), cone(density = 0, radius = 1, height = 1))]
struct Body;

fn main() {}
