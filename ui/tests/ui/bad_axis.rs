use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(disk(mass = 1.0, radius = 0.1, axis = w))]
struct Body;

fn main() {}
