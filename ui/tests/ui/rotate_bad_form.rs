use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(
    disk(mass = 1.0, radius = 0.1, rotate = quaternion(1.0, 0.0, 0.0, 0.0)),
    disk(mass = 1.0, radius = 0.1, rotate = 0.5),
    disk(mass = 1.0, radius = 0.1, rotate = axis_angle([1.0, 0.0, 0.0])),
    disk(mass = 1.0, radius = 0.1, rotate = matrix([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])),
    disk(mass = 1.0, radius = 0.1, rotate = matrix(1.0)),
    disk(mass = 1.0, radius = 0.1, rotate = matrix([1.0], [2.0])),
    disk(mass = 1.0, radius = 0.1, rotate = xyzx(0.1, 0.2, 0.3, 0.4)),
)]
struct Body;

fn main() {}
