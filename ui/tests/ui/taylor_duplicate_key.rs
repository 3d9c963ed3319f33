use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[free(taylor = 20, taylor = 10)]
struct Ball;

fn main() {}
