use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[free(rotor(axis = [0, 0, 1], inertia = 0.0001, torque = 0.01))]
struct Satellite;

fn main() {}
