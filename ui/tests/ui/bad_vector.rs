use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1, at = [1.0, 2.0]))]
struct Body;

fn main() {}
