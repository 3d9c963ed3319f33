use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[free(gravty = 9.81, body_force(force = [0.0, 0.0, 1.0], att = [0.0, 0.0, 0.1]))]
struct Ball;

fn main() {}
