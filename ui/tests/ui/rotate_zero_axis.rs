use precess::prelude::*;

// A zero axis has no direction: refused when its values are literals, whatever the angle.
#[derive(RigidBody)]
#[rigid(cylinder(mass = 1.0, radius = 0.1, length = 0.5, rotate = axis_angle([0.0, 0.0, 0.0], 0.5)))]
struct Literal;

#[derive(RigidBody)]
#[rigid(cylinder(mass = 1.0, radius = 0.1, length = 0.5, rotate = axis_angle([0.0, 0.0, 0.0], a)))]
struct FieldAngle {
    a: f64,
}

fn main() {}
