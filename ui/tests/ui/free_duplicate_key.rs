use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[free(gravity = 9.81, drag = 0.1, gravity = [0.0, 0.0, -1.62])]
struct Ball;

fn main() {}
