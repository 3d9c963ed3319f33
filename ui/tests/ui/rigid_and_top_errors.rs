use precess::prelude::*;

// A bad #[rigid] does not hide a bad #[top]: both are reported in one pass.
#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1, colour = 3.0), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81, friction = 0.1)]
struct Spinner;

fn main() {}
