use precess::prelude::*;

// The square root of a negative constant, a power that is not a written whole number,
// `^` (Rust's exclusive or), a division by zero, and the square root of a length's power.
#[derive(RigidBody)]
#[rigid(
    rod(mass = 1, length = sqrt(-1)),
    rod(mass = 1, length = 0.1.powi(1.5)),
    rod(mass = 2 ^ 3, length = 1),
    rod(mass = PI / (1 - 1), length = 1),
    rod(mass = 1, length = sqrt(2 m)),
)]
struct Body;

fn main() {}
