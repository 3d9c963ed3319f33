use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(
    rod(mass = 1.0, length = 0.5, rotate = zxz(0.1, 0.2)),
    rod(mass = 1.0, length = 0.5, rotate = x()),
    sphere(mass = 1.0, radius = 0.1),
)]
struct Body;

fn main() {}
