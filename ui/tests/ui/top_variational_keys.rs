use precess::prelude::*;

// Too many tangents, a misspelt key, a list that is not one, and a second group.
#[derive(RigidBody)]
#[rigid(body(mass = m, at = [0.0, 0.0, 0.1], inertia = diag(0.01, 0.01, 0.02), about = pivot), pivot = [0.0, 0.0, 0.0])]
#[top(
    gravity = 9.81,
    variational(tangents = 7, sensitivity = [m], sensitivities = m),
    variational(),
)]
struct Heavy {
    m: f64,
}

fn main() {}
