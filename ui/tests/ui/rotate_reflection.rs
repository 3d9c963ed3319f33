use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(cone(mass = 1.0, radius = 0.1, height = 0.3, rotate = matrix([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, -1.0]])))]
struct Mirrored;

fn main() {}
