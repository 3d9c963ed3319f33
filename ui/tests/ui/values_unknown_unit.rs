use precess::prelude::*;

// An unknown unit, a unit written as a suffix, and a power that is not a whole number.
#[derive(RigidBody)]
#[rigid(
    sphere(mass = 2 kgs, radius = 3cm),
    rod(mass = 1 kg, length = 1 m^x),
)]
struct Body;

fn main() {}
