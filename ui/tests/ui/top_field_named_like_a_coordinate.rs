use precess::prelude::*;

// The top's coordinates are φ, θ, ψ: a field `theta` would print as the same θ.
#[derive(RigidBody)]
#[rigid(cone(mass = m, radius = 0.03, height = 0.04, axis = -z, at = [0, 0, theta]),
        pivot = [0, 0, 0])]
#[top(gravity = 9.81)]
struct Top {
    m: f64,
    theta: f64,
}

fn main() {}
