use precess::prelude::*;

// A length plus a mass has no dimension at all.
#[derive(RigidBody)]
#[rigid(sphere(mass = 1, radius = 2 cm + 3 g))]
struct Body;

fn main() {}
