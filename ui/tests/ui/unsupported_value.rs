use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = r.ln()))]
struct Body {
    r: f64,
}

fn main() {}
