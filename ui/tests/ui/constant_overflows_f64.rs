use precess::prelude::*;

/// Each literal is finite, but the distance from the pivot, 3.4e308 m, is not.
#[derive(RigidBody)]
#[rigid(
    sphere(mass = m, radius = 1.0, at = [1.7e308, 0.0, 0.0]),
    pivot = [-1.7e308, 0.0, 0.0],
)]
struct FarAway {
    m: f64,
}

fn main() {}
