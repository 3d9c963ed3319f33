use precess::prelude::*;

// A point, a thin disk and a tensor have no volume to take a density of.
#[derive(RigidBody)]
#[rigid(
    particle(density = 1000, at = [0, 0, 1]),
    disk(density = 1000, radius = 0.1),
    body(density = 1000, inertia = diag(1, 1, 1)),
)]
struct Body;

fn main() {}
