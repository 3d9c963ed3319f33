use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(body(mass = 1.0, at = [0.0, 0.0, 0.1], inertia = diag(0.01, 0.01, 0.02), about = pivot), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81, rotor = 300 rpm)]
struct Gyrotop;

fn main() {}
