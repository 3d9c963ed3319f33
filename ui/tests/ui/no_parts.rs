use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(pivot = [0.0, 0.0, 0.0])]
struct Body;

fn main() {}
