use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(cylinder(mass = 1.0, radius = 0.1, length = 0.5, radius = 0.2))]
struct Body;

fn main() {}
