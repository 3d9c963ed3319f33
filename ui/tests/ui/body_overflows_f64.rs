use precess::prelude::*;

// 2/5 M R² = 4e309: finite literals whose moment of inertia is past the largest f64.
#[derive(RigidBody)]
#[rigid(sphere(mass = 1e296, radius = 1e7))]
struct Body;

fn main() {}
