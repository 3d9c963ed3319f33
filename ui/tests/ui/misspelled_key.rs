use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radus = 0.1))]
struct Ball;

fn main() {}
