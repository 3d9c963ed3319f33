use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[free(drag = c)]
struct Ball {
    k: f64,
}

fn main() {}
