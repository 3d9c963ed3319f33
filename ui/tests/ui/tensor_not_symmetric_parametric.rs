use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(body(mass = 1.0, inertia = [[a, c, 0.0], [b, a, 0.0], [0.0, 0.0, a]]))]
struct Body {
    a: f64,
    b: f64,
    c: f64,
}

fn main() {}
