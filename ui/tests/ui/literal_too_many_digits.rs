use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.2345678901234567890123456789012345678901, radius = 1.0))]
struct Body;

fn main() {}
