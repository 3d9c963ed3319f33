use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(cuboid(mass = 1.0, size = [0.1, 0.2, 0.3]))]
#[free(space_force(at = [0.0, 0.0, 0.1]))]
struct Pushed;

fn main() {}
