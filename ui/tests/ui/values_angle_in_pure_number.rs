use precess::prelude::*;

// An angle unit where a pure number belongs: SI's radian is 1, but `30 deg` is no friction
// coefficient, nor an axis's component, nor a torque.
#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 10 cm))]
#[contact(surface = sphere(radius = 10 cm), law = stick_slip(mu = 30 deg), gravity = 9.81)]
struct Coefficient;

#[derive(RigidBody)]
#[rigid(cylinder(mass = 1.0, radius = 1 cm, length = 1 m, rotate = axis_angle([1 rad, 0, 0], 30 deg)), pivot = [0, 0, 0])]
#[top(gravity = 9.81, body_torque = [0, 0, 1 N m rad])]
struct Tilted;

fn main() {}
