use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(cuboid(mass = 1.0, size = [0.1, 0.2, 0.3]))]
#[free(body_force(force = [0.0, 0.0, 5.0]))]
struct Thruster;

fn main() {}
