use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1), gravity = 9.81)]
struct Body;

fn main() {}
