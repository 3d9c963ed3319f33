use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(tube(mass = 1.0, inner = 0.3, outer = 0.2, length = 1.0))]
struct Body;

fn main() {}
