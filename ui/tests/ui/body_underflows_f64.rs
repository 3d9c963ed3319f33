use precess::prelude::*;

// 2/5 M R² = 4e-321: below the smallest normal f64, where digits are lost.
#[derive(RigidBody)]
#[rigid(sphere(mass = 1e-300, radius = 1e-10))]
struct Body;

fn main() {}
