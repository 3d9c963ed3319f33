use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
struct Body<T> {
    m: T,
}

fn main() {}
