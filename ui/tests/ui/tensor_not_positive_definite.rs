use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(body(mass = 1.0, inertia = diag(1.0, -1.0, 1.0)))]
struct Body;

fn main() {}
