use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = m, radius = radius))]
struct Body {
    m: f64,
    r: f64,
}

fn main() {}
