use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(rod(mass = m, length = l))]
struct Body {
    m: f64,
    l: f64,
}

fn main() {}
