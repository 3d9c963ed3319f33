use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1, at = [0.0, 0.0, 0.1]), pivto = [0.0, 0.0, 0.0])]
struct Ball;

fn main() {}
