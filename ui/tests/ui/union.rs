use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
union Body {
    a: f64,
    b: u64,
}

fn main() {}
