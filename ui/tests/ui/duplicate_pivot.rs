use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1), pivot = [0.0, 0.0, 0.0], pivot = [0.0, 0.0, 1.0])]
struct Body;

fn main() {}
