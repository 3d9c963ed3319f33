use precess::prelude::*;

// A length where a mass belongs, a mass where a length does, a length as an angle, and a
// speed as gravity.
#[derive(RigidBody)]
#[rigid(
    sphere(mass = 2 cm, radius = 3 kg),
    cuboid(mass = 1, size = [1 cm, 2 cm, 3 cm], rotate = y(2 cm)),
    pivot = [0, 0, 0],
)]
#[top(gravity = 9.81 m/s)]
struct Top;

fn main() {}
