use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(body(mass = m, at = [0.0, 0.0, 0.1], inertia = diag(0.01, 0.01, 0.02), about = pivot), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81, variational)]
struct Heavy {
    m: f64,
}

fn main() {}
