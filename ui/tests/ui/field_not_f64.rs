use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = m, radius = r))]
struct Body {
    m: f64,
    r: f32,
}

fn main() {}
