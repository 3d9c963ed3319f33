use precess::prelude::*;

// An unknown field, a field given twice, a field the equations never read, a value that
// is not a field.
#[derive(RigidBody)]
#[rigid(body(mass = m, at = [0.0, 0.0, 0.1], inertia = diag(0.01, 0.01, 0.02), about = pivot), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = g, variational(tangents = 1, sensitivities = [mass, m, g, m, label, 2.0]))]
struct Heavy {
    m: f64,
    g: f64,
    label: f64,
}

fn main() {}
