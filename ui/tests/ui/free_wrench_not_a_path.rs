use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[free(gravity = 9.81, wrench = [0.0, 0.0, 1.0])]
struct Ball;

fn main() {}
