use precess::prelude::*;

// A sphere looks the same at any turn: `rotate` is not one of its keys.
#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1, rotate = x(0.5)))]
struct Body;

fn main() {}
