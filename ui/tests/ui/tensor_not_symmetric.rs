use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(body(mass = 1.0, inertia = [[1.0, 0.1, 0.0], [0.2, 1.0, 0.0], [0.0, 0.0, 1.0]]))]
struct Body;

fn main() {}
