use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[free(taylor = 20, taylor = 10)]
struct Ball;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1, at = [0.0, 0.0, 1.0]), pivot = [0.0, 0.0, 0.0])]
#[top(taylor = 20, gravity = 9.81, taylor = 10)]
struct Top;

fn main() {}
