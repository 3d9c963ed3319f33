use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(spehre(mass = 1.0, radius = 0.1))]
struct Ball;

fn main() {}
