use precess::prelude::*;

// A free joint flies the base body: a body hanging from another cannot fly free of it.
#[derive(Mechanism)]
#[body(bus, joint = revolute(axis = x), q = theta, parts(sphere(mass = 1.0, radius = 0.1)))]
#[body(panel, parent = bus, joint = free(sequence = zyx), q = [x, y, z, yaw, pitch, roll],
       parts(sphere(mass = 1.0, radius = 0.1)))]
struct PanelOnAFreeJoint;

fn main() {}
