use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
enum Body {
    A,
    B,
}

fn main() {}
