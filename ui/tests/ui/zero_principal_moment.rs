use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(rod(mass = 1.0, length = 2.0, axis = x), particle(mass = 0.5, at = [3.0, 0.0, 0.0]))]
struct Body;

fn main() {}
