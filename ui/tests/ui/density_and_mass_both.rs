use precess::prelude::*;

// A density stands for the mass: both are two values of one quantity; neither leaves the
// mass unknown.
#[derive(RigidBody)]
#[rigid(
    sphere(mass = 1, density = 700, radius = 0.1),
    cylinder(radius = 0.1, length = 0.2),
)]
struct Body;

fn main() {}
