use precess::prelude::*;

#[derive(RigidBody)]
struct Body {
    m: f64,
}

fn main() {}
