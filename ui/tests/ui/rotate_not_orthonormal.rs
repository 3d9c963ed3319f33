use precess::prelude::*;

// A matrix that stretches is not a rotation, even when the part's size is a field.
#[derive(RigidBody)]
#[rigid(cuboid(mass = 1.0, size = [a, 0.2, 0.3], rotate = matrix([[2.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])))]
struct Stretched {
    a: f64,
}

// Rounded to four digits, a rotation is off by 1e-5: more than 1e-9.
#[derive(RigidBody)]
#[rigid(cuboid(mass = 1.0, size = [0.1, 0.2, 0.3], rotate = matrix([[0.7071, -0.7071, 0.0], [0.7071, 0.7071, 0.0], [0.0, 0.0, 1.0]])))]
struct Rounded;

fn main() {}
